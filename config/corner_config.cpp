#include "config/corner_config.h"

#include <QJsonArray>
#include <stdexcept>

#include "config/json_section.h"
#include "config/preset_library.h"

namespace tt::config {

namespace {

JsonSection subSection(const JsonSection& parent, const QString& key) {
    const QJsonValue v = parent.value(key);
    if (!v.isUndefined() && !v.isObject()) parent.fail(key, "must be an object");
    return JsonSection::of(v.toObject(), parent.name() + QLatin1Char('.') + key);
}

core::FeedDriveAxisConfig readAxis(const JsonSection& s, core::FeedDriveAxisConfig a) {
    a.inertiaKgM2 = s.number(QStringLiteral("inertia_kg_m2"), a.inertiaKgM2, 1e-6, 10.0);
    a.torqueConstantNmPerA = s.number(QStringLiteral("torque_constant_nm_per_a"), a.torqueConstantNmPerA, 1e-3, 100.0);
    a.currentLimitA = s.number(QStringLiteral("current_limit_a"), a.currentLimitA, 0.1, 1000.0);
    a.viscousFrictionNmSPerRad =
        s.number(QStringLiteral("viscous_friction_nm_s_per_rad"), a.viscousFrictionNmSPerRad, 0.0, 100.0);
    a.coulombFrictionNm = s.number(QStringLiteral("coulomb_friction_nm"), a.coulombFrictionNm, 0.0, 1000.0);
    a.staticFrictionNm = s.number(QStringLiteral("static_friction_nm"), a.staticFrictionNm, 0.0, 1000.0);
    a.stribeckSpeedRadPerS = s.number(QStringLiteral("stribeck_speed_rad_per_s"), a.stribeckSpeedRadPerS, 1e-3, 100.0);
    a.screwLeadMm = s.number(QStringLiteral("screw_lead_mm"), a.screwLeadMm, 0.1, 100.0);
    a.encoderStepMm = s.number(QStringLiteral("encoder_step_mm"), a.encoderStepMm, 1e-6, 0.1);
    a.positionGainPerS = s.number(QStringLiteral("position_gain_per_s"), a.positionGainPerS, 0.1, 1000.0);
    a.speedPerVoltRadPerSPerV =
        s.number(QStringLiteral("speed_per_volt_rad_per_s_per_v"), a.speedPerVoltRadPerSPerV, 0.01, 1000.0);
    a.commandLimitV = s.number(QStringLiteral("command_limit_v"), a.commandLimitV, 0.1, 100.0);
    a.velocityGainAPerRadPerS =
        s.number(QStringLiteral("velocity_gain_a_per_rad_per_s"), a.velocityGainAPerRadPerS, 1e-4, 1000.0);
    a.velocityIntegralTimeS = s.number(QStringLiteral("velocity_integral_time_s"), a.velocityIntegralTimeS, 0.0, 10.0);
    if (a.staticFrictionNm < a.coulombFrictionNm)
        s.fail(QStringLiteral("static_friction_nm"), "must be at least coulomb_friction_nm");
    return a;
}

core::SpeedRange readRange(const JsonSection& s, const QString& key, core::SpeedRange fallback) {
    const QJsonValue v = s.value(key);
    if (v.isUndefined()) return fallback;
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.size() != 2 || !a.at(0).isDouble() || !a.at(1).isDouble())
        s.fail(key, "must be [min, max] in rad/s");
    const core::SpeedRange r{a.at(0).toDouble(), a.at(1).toDouble()};
    if (!(r.minRadPerS >= core::kMinCornerSpeedRadPerS && r.maxRadPerS <= core::kMaxCornerSpeedRadPerS &&
          r.minRadPerS <= r.maxRadPerS))
        s.fail(key, "must lie within 0.5 .. 9 rad/s with min <= max (the speeds the paper's network covers)");
    return r;
}

void readDrives(const QJsonObject& preset, core::CornerScenario& sc) {
    const JsonSection drives(preset, QStringLiteral("drives"));
    sc.drives.stepS = drives.number(QStringLiteral("step_ms"), sc.drives.stepS * 1e3, 0.001, 0.1) * 1e-3;
    sc.drives.x = readAxis(subSection(drives, QStringLiteral("x")), sc.drives.x);
    sc.drives.z = readAxis(subSection(drives, QStringLiteral("z")), sc.drives.z);
}

void readCostAndPulse(const QJsonObject& preset, core::CornerScenario& sc) {
    const JsonSection cost(preset, QStringLiteral("cost"));
    sc.cost.beforeS = cost.number(QStringLiteral("t1_s"), sc.cost.beforeS, 0.001, 1.0);
    sc.cost.afterS = cost.number(QStringLiteral("t2_s"), sc.cost.afterS, 0.001, 1.0);
    sc.cost.maxWeight = cost.number(QStringLiteral("k1"), sc.cost.maxWeight, 0.0, 100.0);
    sc.cost.meanWeight = cost.number(QStringLiteral("k2"), sc.cost.meanWeight, 0.0, 100.0);
    const JsonSection pulse(preset, QStringLiteral("pulse"));
    const std::string axis = pulse.text(QStringLiteral("axis"), core::toString(sc.pulse.axis));
    if (axis != "x" && axis != "z") pulse.fail(QStringLiteral("axis"), "must be \"x\" or \"z\"");
    sc.pulse.axis = core::feedAxisFromString(axis.c_str());
    sc.pulse.leadS = pulse.number(QStringLiteral("lead_s"), sc.pulse.leadS, 0.0, 0.2);
    sc.pulse.durationS = pulse.number(QStringLiteral("duration_s"), sc.pulse.durationS, 0.001, 0.2);
    sc.pulse.limitV = pulse.number(QStringLiteral("limit_v"), sc.pulse.limitV, 0.01, core::kMaxPulseAmplitudeV);
    const JsonSection speeds(preset, QStringLiteral("speeds"));
    sc.xSpeeds = readRange(speeds, QStringLiteral("x_rad_per_s"), sc.xSpeeds);
    sc.zSpeeds = readRange(speeds, QStringLiteral("z_rad_per_s"), sc.zSpeeds);
}

void readTraining(const QJsonObject& preset, core::CornerScenario& sc) {
    const JsonSection t(preset, QStringLiteral("training"));
    core::CornerTrainingSettings& tr = sc.training;
    tr.moves = t.integer(QStringLiteral("moves"), tr.moves, 10, 100000);
    tr.seed =
        static_cast<unsigned long long>(t.integer(QStringLiteral("seed"), static_cast<int>(tr.seed), 0, 2147483647));
    tr.search.gridPoints = t.integer(QStringLiteral("grid_points"), tr.search.gridPoints, 3, 201);
    tr.search.toleranceV = t.number(QStringLiteral("tolerance_v"), tr.search.toleranceV, 1e-6, 0.05);
    tr.search.maxSimulations = t.integer(QStringLiteral("max_simulations"), tr.search.maxSimulations, 6, 1000);
    tr.network.hiddenCount = t.integer(QStringLiteral("hidden"), tr.network.hiddenCount, 1, 100);
    tr.network.maxEpochs = t.integer(QStringLiteral("max_epochs"), tr.network.maxEpochs, 1, 100000);
    tr.network.patience = t.integer(QStringLiteral("patience"), tr.network.patience, 1, 100000);
    tr.network.validationFraction =
        t.number(QStringLiteral("validation_fraction"), tr.network.validationFraction, 0.05, 0.5);
    tr.network.learningRate = t.number(QStringLiteral("learning_rate"), tr.network.learningRate, 1e-5, 1.0);
    tr.network.seed = static_cast<unsigned long long>(
        t.integer(QStringLiteral("network_seed"), static_cast<int>(tr.network.seed), 0, 2147483647));
}

void readRetrainingAndMachine(const QJsonObject& preset, core::CornerScenario& sc) {
    const JsonSection r(preset, QStringLiteral("retraining"));
    core::CornerRetrainSettings& rt = sc.retraining;
    rt.monitor.windowCorners = r.integer(QStringLiteral("window_corners"), rt.monitor.windowCorners, 3, 1000);
    rt.monitor.thresholdFraction =
        r.number(QStringLiteral("threshold_pct"), rt.monitor.thresholdFraction * 100.0, 0.1, 1000.0) / 100.0;
    rt.monitor.outlierMads = r.number(QStringLiteral("outlier_mads"), rt.monitor.outlierMads, 1.0, 20.0);
    rt.oldSetWeight = r.number(QStringLiteral("old_set_weight"), rt.oldSetWeight, 0.0, 1.0);
    core::DriveIdentificationSettings& id = rt.identification;
    id.frictionMin = r.number(QStringLiteral("friction_factor_min"), id.frictionMin, 0.05, 1.0);
    id.frictionMax = r.number(QStringLiteral("friction_factor_max"), id.frictionMax, 1.0, 20.0);
    id.inertiaMin = r.number(QStringLiteral("inertia_factor_min"), id.inertiaMin, 0.05, 1.0);
    id.inertiaMax = r.number(QStringLiteral("inertia_factor_max"), id.inertiaMax, 1.0, 20.0);
    id.gainMin = r.number(QStringLiteral("gain_factor_min"), id.gainMin, 0.05, 1.0);
    id.gainMax = r.number(QStringLiteral("gain_factor_max"), id.gainMax, 1.0, 20.0);
    id.sweeps = r.integer(QStringLiteral("identification_sweeps"), id.sweeps, 1, 5);
    rt.validationMoves = r.integer(QStringLiteral("validation_moves"), rt.validationMoves, 5, 1000);
    const JsonSection m(preset, QStringLiteral("machine"));
    core::MachineVariation& mv = sc.machine;
    mv.frictionScatter = m.number(QStringLiteral("friction_scatter"), mv.frictionScatter, 0.0, 0.3);
    mv.outlierProbability = m.number(QStringLiteral("outlier_probability"), mv.outlierProbability, 0.0, 0.5);
    mv.outlierTorqueNm = m.number(QStringLiteral("outlier_torque_nm"), mv.outlierTorqueNm, 0.0, 100.0);
    mv.outlierDurationS = m.number(QStringLiteral("outlier_duration_s"), mv.outlierDurationS, 0.0, 0.5);
    mv.seed =
        static_cast<unsigned long long>(m.integer(QStringLiteral("seed"), static_cast<int>(mv.seed), 0, 2147483647));
    const JsonSection w(preset, QStringLiteral("work"));
    sc.evaluationMoves = w.integer(QStringLiteral("moves"), sc.evaluationMoves, 1, 100000);
}

}  // namespace

core::CornerScenario cornerScenarioFromPreset(const QJsonObject& preset) {
    core::CornerScenario sc;
    sc.name = preset.value(QStringLiteral("name")).toString().toStdString();
    sc.description = preset.value(QStringLiteral("description")).toString().toStdString();
    readDrives(preset, sc);
    readCostAndPulse(preset, sc);
    readTraining(preset, sc);
    readRetrainingAndMachine(preset, sc);
    core::validateCornerScenario(sc);
    return sc;
}

core::CornerScenario loadCornerScenario(const QString& nameOrPath) {
    const QJsonObject preset = PresetLibrary::load(nameOrPath);
    try {
        return cornerScenarioFromPreset(preset);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("preset '" + nameOrPath.toStdString() + "': " + e.what());
    }
}

}  // namespace tt::config
