#include "ui/controller/history_identification.h"

#include <exception>

#include "core/storage/history_store.h"

namespace tt::ui {

HistoryIdentification identifyFromHistory(const storage::DatabaseConfig& config, std::optional<std::int64_t> runId,
                                          const std::vector<double>& gainPerPoint) {
    HistoryIdentification out;
    try {
        storage::Database database(config);
        storage::SqlHistoryStore history(database);
        for (std::size_t i = 0; i < gainPerPoint.size(); ++i) {
            try {
                // ARMA(1, 1): the order of the typed shaping filter (z + b)/(z - a) (paper 000).
                out.points.push_back(core::identifyStoredDisturbance(history, runId, static_cast<int>(i),
                                                                     core::ArmaOrders{1, 1}, gainPerPoint[i]));
            } catch (const std::invalid_argument& e) {
                if (i == 0) {
                    out.problem = QString::fromStdString(e.what());
                    return out;
                }
            }
        }
    } catch (const std::exception& e) {
        out.problem = QString::fromStdString(e.what());
    }
    return out;
}

}  // namespace tt::ui
