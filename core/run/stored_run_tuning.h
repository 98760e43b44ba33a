#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/control/adaptive_design.h"
#include "core/control/plant_identification.h"
#include "core/loop/adaptation_config.h"
#include "core/ports/history_store.h"
#include "core/sim/statistics/run_to_run_analysis.h"

namespace tt::core {

/// The closed-loop record of stored run `runId` for the identification: its parts in order from the first stored
/// one (the last `lastParts` of them when given), the corrections applied and the deviations the controller used.
/// Throws IdentificationRefused when the run has no stored part, std::invalid_argument for an unknown run.
LoopHistory storedLoopHistory(HistoryStore& history, std::int64_t runId, std::optional<std::int64_t> lastParts);

/// The commissioning step (`trueturn tune`, the Controller page's "Identify from history"): the plant identified
/// from a stored run, an LQG designed for it with its margins checked, and what it would give on the identified
/// plant (analytic steady state) beside the run's own controller and the best EWMA.
struct StoredRunTuning {
    std::int64_t runId = 0;
    std::int64_t firstPart = 0, lastPart = 0;  ///< the parts read
    PlantIdentification identification;
    PlantModelRecord model;  ///< the identified model as recorded (with its standard errors)
    AdaptedDesign design;    ///< the new design (design.passes: its margins hold)
    /// On the identified plant: the run's own LQG (designed on its model), the new design and the best EWMA.
    SteadyStateVariances current, adapted, ewma;
    double ewmaWeight = 0.0;
};

/// Identifies run `runId` of `history` with the options of `config` (the loop's adaptation settings) for a loop of
/// `setup`'s delay (its model's gains as the prior), designs for it and analyses the three controllers. Throws
/// IdentificationRefused (the data cannot tell yet, with the parts needed) or std::invalid_argument.
StoredRunTuning tuneFromStoredRun(HistoryStore& history, std::int64_t runId, const RunToRunSetup& setup,
                                  const AdaptationConfig& config, std::optional<std::int64_t> lastParts = std::nullopt);

}  // namespace tt::core
