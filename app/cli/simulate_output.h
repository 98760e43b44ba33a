#pragma once

// What `trueturn simulate` prints: the study's result as JSON or text (k_eff per control point, verdicts, the
// profile, the step residual, the model alarms and the corrections).
#include <QJsonObject>
#include <QString>
#include <cstdint>
#include <optional>

#include "config/loop_scenario.h"
#include "core/run/shaft_study.h"

namespace tt::cli {

/// The study as `simulate --json` prints it (with the profile when asked, the history and run when stored),
/// including the plant, integral action, step residual, model alarms and corrections of the scenario run.
QJsonObject simulateJson(const core::LatheStudyResult& result, const config::LoopScenario& scenario, bool profile,
                         const std::optional<QString>& database);

/// The study as `simulate` prints it without --json.
void printSimulateText(const QString& preset, const core::LatheStudyResult& result, std::uint64_t seed, bool profile);

}  // namespace tt::cli
