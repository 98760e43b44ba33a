#include "ui/controller/history_identification.h"

#include <exception>

#include "core/storage/history_store.h"

namespace tt::ui {

HistoryIdentification identifyFromHistory(const storage::DatabaseConfig& config, std::optional<std::int64_t> runId,
                                          const core::RunToRunSetup& setup) {
    HistoryIdentification out;
    try {
        storage::Database database(config);
        storage::SqlHistoryStore history(database);
        const std::vector<core::RunSummary> runs = history.runs();
        if (runs.empty()) throw std::invalid_argument("the history holds no run");
        const core::RunSummary* run = &runs.front();
        for (const core::RunSummary& r : runs)
            if (runId ? r.runId == *runId : r.runId > run->runId) run = &r;
        if (runId && run->runId != *runId)
            throw std::invalid_argument("the history has no run " + std::to_string(*runId));
        // The run's own delay z: the identified plant delay is z + its lag.
        core::RunToRunSetup forRun = setup;
        forRun.plant.delay = run->description.delayParts;
        if (forRun.model && forRun.plant.delay + forRun.model->lagParts > core::kMaxDelay) forRun.model.reset();
        out.tuning = core::tuneFromStoredRun(history, run->runId, forRun, core::AdaptationConfig{});
    } catch (const std::exception& e) {
        out.problem = QString::fromStdString(e.what());
    }
    return out;
}

}  // namespace tt::ui
