#include "config/robust_config.h"

#include <stdexcept>
#include <string>

#include "config/json_section.h"

namespace tt::config {

core::PlantMismatch plantMismatchFromPreset(const QJsonObject& preset) {
    core::PlantMismatch m;
    if (!preset.contains(QStringLiteral("plant_mismatch"))) return m;
    const JsonSection s(preset, QStringLiteral("plant_mismatch"));
    m.gainFactor = s.number(QStringLiteral("gain_factor"), 1.0, core::kMinPlantGainFactor, core::kMaxPlantGainFactor);
    if (s.has(QStringLiteral("delay"))) m.delayParts = s.integer(QStringLiteral("delay"), 1, 1, core::kMaxDelay);
    if (s.has(QStringLiteral("step"))) {
        const JsonSection st = JsonSection::of(s.value(QStringLiteral("step")).toObject(), s.name() + ".step");
        if (!s.value(QStringLiteral("step")).isObject()) s.fail(QStringLiteral("step"), "must be an object");
        core::PlantStep p;
        p.atPart = st.integer(QStringLiteral("at_part"), 1, 1, 100000000);
        p.sizeMm = st.required(QStringLiteral("size_mm"), -core::kMaxPlantStepMm, core::kMaxPlantStepMm);
        if (st.has(QStringLiteral("point"))) p.point = st.integer(QStringLiteral("point"), 1, 1, 16) - 1;
        m.step = p;
    }
    return m;
}

core::IntegralAction integralActionFromPreset(const QJsonObject& preset) {
    core::IntegralAction a;
    const QJsonObject controller = preset.value(QStringLiteral("controller")).toObject();
    if (!controller.contains(QStringLiteral("integral"))) return a;
    const JsonSection s(controller, QStringLiteral("integral"), QStringLiteral("controller"));
    a.enabled = s.flag(QStringLiteral("enabled"), false);
    a.weight = s.number(QStringLiteral("weight"), a.weight, core::kMinIntegralWeight, core::kMaxIntegralWeight);
    return a;
}

core::MismatchMonitorConfig mismatchMonitorFromPreset(const QJsonObject& preset) {
    core::MismatchMonitorConfig c;
    const QJsonObject loop = preset.value(QStringLiteral("loop")).toObject();
    if (!loop.contains(QStringLiteral("mismatch_monitor"))) return c;
    const JsonSection s(loop, QStringLiteral("mismatch_monitor"), QStringLiteral("loop"));
    c.enabled = s.flag(QStringLiteral("enabled"), c.enabled);
    c.windowParts = s.integer(QStringLiteral("window_parts"), c.windowParts, 10, 1000);
    c.minParts = s.integer(QStringLiteral("min_parts"), c.minParts, 5, 1000);
    c.falseAlarmProbability = s.number(QStringLiteral("false_alarm_probability"), c.falseAlarmProbability, 1e-12, 1e-2);
    c.pointCorrelation =
        s.number(QStringLiteral("point_correlation"), c.pointCorrelation, 0.0, core::kMaxPointCorrelation);
    try {
        c.action = core::mismatchActionFromName(s.text(QStringLiteral("action"), "adapt"));
        c.validate();
    } catch (const std::invalid_argument& e) {
        s.fail(QString(), e.what());
    }
    return c;
}

core::AdaptationConfig adaptationFromPreset(const QJsonObject& preset) {
    core::AdaptationConfig c;
    const QJsonObject loop = preset.value(QStringLiteral("loop")).toObject();
    if (!loop.contains(QStringLiteral("adaptation"))) return c;
    const JsonSection s(loop, QStringLiteral("adaptation"), QStringLiteral("loop"));
    c.windowParts = s.integer(QStringLiteral("window_parts"), c.windowParts, 200, 100000);
    c.retryParts = s.integer(QStringLiteral("retry_parts"), c.retryParts, 1, 10000);
    c.transferParts = s.integer(QStringLiteral("transfer_parts"), c.transferParts, 1, 1000);
    c.ditherShare = s.number(QStringLiteral("dither_share"), c.ditherShare, 0.0, core::kMaxDitherShare);
    c.maxExtraLag = s.integer(QStringLiteral("max_extra_lag"), c.maxExtraLag, 0, 4);
    c.maxArmaOrder = s.integer(QStringLiteral("max_arma_order"), c.maxArmaOrder, 0, core::kMaxArmaOrder);
    c.maxGainRelativeStdErr = s.number(QStringLiteral("max_gain_std_error"), c.maxGainRelativeStdErr, 1e-4, 1.0);
    c.minDelayEvidence = s.number(QStringLiteral("min_delay_evidence"), c.minDelayEvidence, 0.0, 1e6);
    c.minParts = s.integer(QStringLiteral("min_parts"), c.minParts, 70, 100000);
    c.refineBelow = s.number(QStringLiteral("refine_below"), c.refineBelow, 0.0, 1.0);
    c.minGainMargin = s.number(QStringLiteral("min_gain_margin"), c.minGainMargin, 1.05, core::kMaxMinGainMargin);
    c.refineParts = s.integer(QStringLiteral("refine_parts"), c.refineParts, 10, 100000);
    try {
        c.criterion = core::informationCriterionFromName(s.text(QStringLiteral("criterion"), "bic"));
        c.validate();
    } catch (const std::invalid_argument& e) {
        s.fail(QString(), e.what());
    }
    return c;
}

}  // namespace tt::config
