#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/control/arma_identification.h"
#include "core/ports/history_store.h"

namespace tt::core {

/// The part-to-part disturbance of one control point of a stored run: d(k) = measured deviation - k_i x
/// the radial correction part k received (what the part would have been without correction), over the
/// longest stretch of consecutive parts whose reading at the point the controller used.
struct DisturbanceSeries {
    std::int64_t runId = 0;
    int point = 0;                 ///< 0-based
    std::int64_t firstPart = 0;    ///< the stretch's first part
    std::int64_t lastPart = 0;     ///< and its last
    std::vector<double> valuesMm;  ///< d(k), mm of diameter
    std::size_t partsInRun = 0;    ///< parts stored for the run
};

/// Reads the series from the history: run `runId` (none: the newest run), point `point` (0-based), gain
/// k_i (diameter per radial move, 2 on a lathe). Throws std::invalid_argument naming the run or the point
/// when the history has no such run, the point does not exist or fewer than kMinArmaValues consecutive
/// parts were measured there.
DisturbanceSeries storedDisturbance(HistoryStore& history, std::optional<std::int64_t> runId, int point, double gain);

/// What the Controller page and `trueturn identify` show: the series and its ARMA fit (fitArma), whose
/// disturbanceModel() is the shaping filter to use.
struct DisturbanceIdentification {
    DisturbanceSeries series;
    ArmaFit fit;
};

/// storedDisturbance then fitArma with `orders`; throws as they do.
DisturbanceIdentification identifyStoredDisturbance(HistoryStore& history, std::optional<std::int64_t> runId, int point,
                                                    ArmaOrders orders, double gain = 2.0);

}  // namespace tt::core
