#pragma once

// Parts of `trueturn simulate`'s output that are not the statistics: the verdicts of every machined part
// with the warm-up's share apart, the corrections and their limits (an absent limit written as null), and
// the merged set-up (`--dump-preset`).
#include <QJsonObject>
#include <QString>

#include "config/loop_scenario.h"
#include "core/control/correction_limits.h"
#include "core/run/shaft_study.h"

namespace tt::cli {

/// "verdicts": {"good", "rework", "scrap"} of every machined part (warm-up included: they are machined,
/// measured and stored), "machined_parts" (their sum) and "warmup": the warm-up's share, {good, rework, scrap}.
QJsonObject verdictsJson(const core::LatheStudyResult& r);

/// The verdict line of the text output, naming the warm-up's share.
QString verdictsText(const core::LatheStudyResult& r);

/// "corrections": the largest |correction| sent and its largest change (radial mm), and the limits
/// `limit_abs_mm`, `limit_step_mm`: null when the set-up has none (unlimited).
QJsonObject correctionsJson(const core::LatheStudyResult& r, const core::CorrectionLimits& limits);

/// The set-up that runs: the preset merged over its based_on chain (config::mergePreset), without
/// "based_on" (the dump is complete: loaded again it runs the same).
QJsonObject presetDump(const config::LoopScenario& scenario);

}  // namespace tt::cli
