#pragma once

#include <QJsonObject>

#include "app/cli/command_parser.h"
#include "config/loop_scenario.h"
#include "core/run/shaft_study.h"

namespace tt::cli {

/// mismatch_action, adaptations:[{part, kind, reason, fallback, fallback_weight, model_before{delay, lag, gain, ar, ma,
/// noise_variance, ...}, model_after{...} | null, margins{gain, gain_lower, phase_deg, delay_parts, extra_parts},
/// applied, message}], adaptation_notices:[{part, kind, message}] and, under corrections, max_switch_step_mm and
/// switches.
void addAdaptationJson(QJsonObject& out, const core::LatheStudyResult& result, const config::LoopScenario& scenario);
/// The same in lines of text.
void printAdaptationText(const core::LatheStudyResult& result);

}  // namespace tt::cli
