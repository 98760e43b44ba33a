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
        if (!runId) {
            const std::vector<core::RunSummary> runs = history.runs();
            if (runs.empty()) throw std::invalid_argument("the history holds no run");
            runId = runs.front().runId;
            for (const core::RunSummary& r : runs)
                runId = std::max(*runId, r.runId);
        }
        out.tuning = core::tuneFromStoredRun(history, *runId, setup, core::AdaptationConfig{});
    } catch (const std::exception& e) {
        out.problem = QString::fromStdString(e.what());
    }
    return out;
}

}  // namespace tt::ui
