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
    try {
        c.action = core::mismatchActionFromName(s.text(QStringLiteral("action"), "hold"));
        c.validate();
    } catch (const std::invalid_argument& e) {
        s.fail(QString(), e.what());
    }
    return c;
}

}  // namespace tt::config
