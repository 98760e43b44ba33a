#include "config/hydraulic_feed_config.h"

#include <QJsonArray>
#include <stdexcept>

#include "config/json_section.h"
#include "config/preset_library.h"

namespace tt::config {

namespace {

/// "spool.damping_ratio" -> ("spool", "damping_ratio").
std::pair<QString, QString> splitKey(const char* key) {
    const QString k = QString::fromLatin1(key);
    const qsizetype dot = k.indexOf(QLatin1Char('.'));
    return {k.left(dot), k.mid(dot + 1)};
}

core::FeedLoadProfile readLoad(const QJsonObject& preset) {
    core::FeedLoadProfile load;
    const QJsonValue v = preset.value(QStringLiteral("load"));
    if (v.isUndefined()) return load;
    if (!v.isArray()) throw std::invalid_argument("load: must be an array of {time_s, force_n[, duration_s]}");
    const QJsonArray events = v.toArray();
    for (qsizetype i = 0; i < events.size(); ++i) {
        const QString name = QStringLiteral("load[%1]").arg(i);
        if (!events[i].isObject()) throw std::invalid_argument(name.toStdString() + ": must be an object");
        const JsonSection e = JsonSection::of(events[i].toObject(), name);
        const double time = e.required(QStringLiteral("time_s"), 0.0, core::FeedLoadProfile::kMaxTimeS);
        const double force = e.required(QStringLiteral("force_n"), 0.0, core::FeedLoadProfile::kMaxForceN);
        const double duration = e.number(QStringLiteral("duration_s"), 0.0, 0.0, core::FeedLoadProfile::kMaxTimeS);
        try {
            if (duration > 0.0)
                load.addRamp(time, duration, force);
            else
                load.addStep(time, force);
        } catch (const std::invalid_argument& err) {
            throw std::invalid_argument(name.toStdString() + ": " + err.what());
        }
    }
    return load;
}

}  // namespace

core::FeedScenario hydraulicFeedScenarioFromPreset(const QJsonObject& preset) {
    core::FeedScenario s;
    for (const core::FeedParameterInfo& info : core::feedParameters()) {
        const auto [section, field] = splitKey(info.key);
        const JsonSection js(preset, section);
        s.params.*(info.member) = js.number(field, s.params.*(info.member), info.minValue, info.maxValue);
    }
    try {
        core::validate(s.params);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("hydraulic feed: ") + e.what());
    }
    s.load = readLoad(preset);
    const JsonSection sim(preset, QStringLiteral("simulation"));
    s.run.durationS = sim.number(QStringLiteral("duration_s"), s.run.durationS, 1e-3, core::FeedLoadProfile::kMaxTimeS);
    s.run.sampleS = sim.number(QStringLiteral("sample_s"), s.run.sampleS, 1e-6, s.run.durationS);
    if (s.run.durationS / s.run.sampleS > core::FeedRunOptions::kMaxSamples)
        sim.fail(QStringLiteral("sample_s"), "gives more than 200000 samples over duration_s");
    const std::string start = sim.text(QStringLiteral("start"), "running");
    if (start != "running" && start != "rest") sim.fail(QStringLiteral("start"), "must be \"running\" or \"rest\"");
    s.run.fromRest = start == "rest";
    return s;
}

core::FeedScenario loadHydraulicFeedScenario(const QString& nameOrPath) {
    const QJsonObject preset = PresetLibrary::load(nameOrPath);
    try {
        return hydraulicFeedScenarioFromPreset(preset);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(nameOrPath.toStdString() + ": " + e.what());
    }
}

QJsonObject hydraulicFeedParamsToJson(const core::HydraulicFeedParams& params) {
    QJsonObject out;
    for (const core::FeedParameterInfo& info : core::feedParameters()) {
        const auto [section, field] = splitKey(info.key);
        QJsonObject s = out.value(section).toObject();
        s.insert(field, params.*(info.member));
        out.insert(section, s);
    }
    return out;
}

}  // namespace tt::config
