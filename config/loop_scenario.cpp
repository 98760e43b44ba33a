#include "config/loop_scenario.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QStringList>
#include <stdexcept>

#include "config/json_section.h"
#include "config/lathe_config.h"
#include "config/plant_config.h"
#include "config/preset_library.h"
#include "config/preset_merge.h"
#include "config/profile_model_config.h"
#include "config/robust_config.h"
#include "core/quality/iso286.h"

namespace tt::config {

namespace {

/// What identifies a preset in a based_on chain: a file by its canonical path, a built-in one by name.
QString presetIdentity(const QString& nameOrPath) {
    if (!nameOrPath.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) return nameOrPath;
    const QString canonical = QFileInfo(nameOrPath).canonicalFilePath();
    return canonical.isEmpty() ? nameOrPath : canonical;
}

std::string chainText(const QStringList& chain) {
    return chain.join(QStringLiteral(" -> ")).toStdString();
}

/// `preset` (loaded as chain.back()) merged over its based_on chain (mergePreset: objects key by key, arrays
/// and values replace, null removes); refuses a
/// cycle and a chain of more than kMaxBasedOnDepth links, naming the chain.
QJsonObject withBase(const QJsonObject& preset, QStringList& chain, QStringList& identities) {
    const QJsonValue base = preset.value(QStringLiteral("based_on"));
    if (base.isUndefined()) return preset;
    if (!base.isString()) throw std::invalid_argument("based_on: must be the name of a preset");
    const QString baseName = base.toString();
    chain << baseName;
    if (identities.contains(presetIdentity(baseName)))
        throw std::invalid_argument("based_on: cycle " + chainText(chain));
    if (chain.size() - 1 > kMaxBasedOnDepth)
        throw std::invalid_argument("based_on: the chain " + chainText(chain) + " is deeper than " +
                                    std::to_string(kMaxBasedOnDepth) + " levels");
    identities << presetIdentity(baseName);
    const QJsonObject parent = withBase(PresetLibrary::load(baseName), chain, identities);
    return mergePreset(parent, preset);
}

/// One tolerance entry: {"fit": "h9"} (ISO 286 shaft class) or {"upper_mm": 0.0, "lower_mm": -0.052}
/// (deviations from the nominal), with an optional "nominal_mm" (default: the loop's nominal diameter).
core::ToleranceZone toleranceFrom(const JsonSection& entry, double loopNominalMm) {
    const double nominal = entry.number(QStringLiteral("nominal_mm"), loopNominalMm, 0.1, 1e4);
    core::ToleranceZone zone{nominal, 0.0, 0.0};
    try {
        if (entry.has(QStringLiteral("fit"))) {
            if (entry.has(QStringLiteral("upper_mm")) || entry.has(QStringLiteral("lower_mm")))
                entry.fail(QStringLiteral("fit"), "give either an ISO 286 class or upper_mm and lower_mm, not both");
            zone = core::iso286ShaftZone(nominal, entry.text(QStringLiteral("fit"), {}));
        } else {
            zone.upperDeviationMm = entry.required(QStringLiteral("upper_mm"), -100.0, 100.0);
            zone.lowerDeviationMm = entry.required(QStringLiteral("lower_mm"), -100.0, 100.0);
        }
        core::checkToleranceZone(zone);
    } catch (const std::invalid_argument& e) {
        if (std::string(e.what()).rfind(entry.name().toStdString(), 0) == 0) throw;
        entry.fail(QString(), e.what());
    }
    return zone;
}

/// "loop.tolerance": one entry for every control point, or an array with one entry per point.
std::vector<core::ToleranceZone> tolerancesFrom(const JsonSection& loop, double nominalMm, std::size_t points) {
    const QJsonValue value = loop.value(QStringLiteral("tolerance"));
    if (value.isUndefined()) return {};
    if (value.isObject())
        return std::vector<core::ToleranceZone>(
            points,
            toleranceFrom(JsonSection::of(value.toObject(), loop.name() + QStringLiteral(".tolerance")), nominalMm));
    if (!value.isArray() || static_cast<std::size_t>(value.toArray().size()) != points)
        loop.fail(QStringLiteral("tolerance"), "must be one object for every control point or an array of " +
                                                   std::to_string(points) + " objects, one per point");
    std::vector<core::ToleranceZone> zones;
    for (qsizetype i = 0; i < value.toArray().size(); ++i) {
        const QJsonValue entry = value.toArray().at(i);
        const QString name = loop.name() + QStringLiteral(".tolerance[%1]").arg(i);
        if (!entry.isObject()) throw std::invalid_argument(name.toStdString() + ": must be an object");
        zones.push_back(toleranceFrom(JsonSection::of(entry.toObject(), name), nominalMm));
    }
    return zones;
}

LoopScenario read(const QString& name, const QJsonObject& preset, std::optional<int> delay) {
    LoopScenario s;
    s.preset = name;
    QStringList chain{name};
    QStringList identities{presetIdentity(name)};
    s.json = withBase(preset, chain, identities);
    s.control = runToRunSetupFromPreset(s.json, delay);
    const QJsonValue lathe = s.json.value(QStringLiteral("lathe"));
    if (!lathe.isUndefined()) {
        if (!lathe.isObject()) throw std::invalid_argument("lathe: must be an object");
        s.lathe = latheSetupFromJson(lathe.toObject());
        s.timing = stationTimingFromJson(lathe.toObject());
    }
    if (s.json.contains(QStringLiteral("systematic_model")))
        s.systematicModel = systematicModelFromPreset(s.json).diameterError();

    const JsonSection loop(s.json, QStringLiteral("loop"));
    const QJsonObject plant = s.json.value(QStringLiteral("plant")).toObject();
    double length = s.lathe ? s.lathe->workpiece.lengthMm
                            : plant.value(QStringLiteral("part_length_mm")).toDouble(s.control.plant.points.back().xMm);
    s.partLengthMm = loop.number(QStringLiteral("part_length_mm"), length, 1.0, 1e5);
    if (!(s.partLengthMm >= 1.0 && s.partLengthMm <= 1e5))  // the plant's length, when the loop names none
        throw std::invalid_argument("plant.part_length_mm: " + QString::number(s.partLengthMm).toStdString() +
                                    " mm is outside 1 .. 100000 mm");
    s.nominalDiameterMm = loop.number(QStringLiteral("nominal_diameter_mm"),
                                      s.lathe ? s.lathe->workpiece.finishDiameterMm : 27.0, 0.1, 1e4);
    if (s.lathe &&
        (s.partLengthMm != s.lathe->workpiece.lengthMm || s.nominalDiameterMm != s.lathe->workpiece.finishDiameterMm))
        throw std::invalid_argument("loop: the part length and nominal diameter must be the lathe's workpiece's");
    s.plausibleRangeMm = loop.number(QStringLiteral("plausible_range_mm"), s.plausibleRangeMm, 1e-3, 100.0);
    s.pathStepMm = loop.number(QStringLiteral("path_step_mm"), s.pathStepMm, 0.01, 100.0);
    s.gaugeTimeoutS = loop.number(QStringLiteral("gauge_timeout_s"), s.gaugeTimeoutS, 1.0, 1e7);
    s.toleranceMm = loop.number(QStringLiteral("tolerance_mm"), s.toleranceMm, 1e-4, 100.0);
    s.tolerances = tolerancesFrom(loop, s.nominalDiameterMm, s.control.plant.points.size());
    s.pauseOnScrap = loop.flag(QStringLiteral("pause_on_scrap"), false);
    if (loop.has(QStringLiteral("interpolation"))) {
        const QJsonValue method = loop.value(QStringLiteral("interpolation"));
        if (!method.isString()) throw std::invalid_argument("loop.interpolation: must be \"pchip\" or \"spline\"");
        try {
            s.interpolation = core::interpolationMethodFromName(method.toString().toStdString());
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(std::string("loop.interpolation: ") + e.what());
        }
    }
    s.control.integral = integralActionFromPreset(s.json);
    s.plantMismatch = plantMismatchFromPreset(s.json);
    s.mismatchMonitor = mismatchMonitorFromPreset(s.json);
    s.adaptation = adaptationFromPreset(s.json);
    for (const core::ControlPointSpec& p : s.control.plant.points)
        if (p.xMm < 0.0 || p.xMm > s.partLengthMm)
            throw std::invalid_argument("plant: control point x = " + std::to_string(p.xMm) +
                                        " mm lies outside the part (0 .. " + std::to_string(s.partLengthMm) + " mm)");
    return s;
}

}  // namespace

LoopScenario loadLoopScenario(const QString& nameOrPath, std::optional<int> delay) {
    const QJsonObject preset = PresetLibrary::load(nameOrPath);
    try {
        return read(nameOrPath, preset, delay);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("preset '" + nameOrPath.toStdString() + "': " + e.what());
    }
}

}  // namespace tt::config
