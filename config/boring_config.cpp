#include "config/boring_config.h"

#include <cmath>

#include <QJsonArray>
#include <stdexcept>

#include "config/json_section.h"
#include "config/preset_library.h"
#include "core/sim/boring/boring_machine.h"

namespace tt::config {

namespace {

core::ToolRecord readTool(const QJsonObject& preset) {
    if (!preset.value(QStringLiteral("tool")).isObject())
        throw std::invalid_argument("tool: missing (the boring bar: section, overhang, material, k_p)");
    const JsonSection s(preset, QStringLiteral("tool"));
    core::ToolRecord t;
    t.id = s.text(QStringLiteral("id"), "T1");
    t.name = s.text(QStringLiteral("name"), "");
    try {
        const core::SectionShape shape = core::sectionShapeFromString(s.text(QStringLiteral("section"), "round"));
        t.section = shape == core::SectionShape::Round
                        ? core::HolderSection::round(s.required(QStringLiteral("diameter_mm"), 5.0, 500.0))
                        : core::HolderSection::rectangular(s.required(QStringLiteral("width_mm"), 5.0, 500.0),
                                                           s.required(QStringLiteral("height_mm"), 5.0, 500.0));
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        throw std::invalid_argument(what.rfind("tool.", 0) == 0 ? what : "tool.section: " + what);
    }
    t.overhangMm = s.required(QStringLiteral("overhang_mm"), 10.0, 5000.0);
    t.material = s.text(QStringLiteral("material"), "Steel");
    t.youngsModulusMpa =
        s.required(QStringLiteral("youngs_modulus_mpa"), core::kMinYoungsModulusMpa, core::kMaxYoungsModulusMpa);
    t.currentToForceGainNPerA = s.required(QStringLiteral("current_to_force_n_per_a"), 1e-3, 1e6);
    if (s.has(QStringLiteral("measured_stiffness_n_per_mm")))
        t.measured = core::MeasuredStiffness{s.required(QStringLiteral("measured_stiffness_n_per_mm"), 1e-3, 1e8),
                                             s.text(QStringLiteral("measured_on"), ""),
                                             s.text(QStringLiteral("measured_by"), "")};
    const std::vector<std::string> problems = core::validateTool(t);
    if (!problems.empty()) throw std::invalid_argument("tool: " + problems.front());
    return t;
}

/// The largest |c_i| of a bridge characteristic r(u) = Σ c_i u^i (a bridge ratio is about ±1 at full scale).
constexpr double kMaxBridgeCoefficient = 10.0;

std::vector<double> coefficients(const JsonSection& s, const QString& key, const std::vector<double>& fallback) {
    const QJsonValue v = s.value(key);
    if (v.isUndefined()) return fallback;
    if (!v.isArray()) s.fail(key, "must be an array of numbers c0, c1, ...");
    std::vector<double> out;
    for (const QJsonValue& item : v.toArray()) {
        if (!item.isDouble()) s.fail(key, "must contain numbers only");
        if (std::abs(item.toDouble()) > kMaxBridgeCoefficient)
            s.fail(key,
                   QString::number(item.toDouble()).toStdString() + " is outside -10 .. 10 (a bridge ratio of u = ±1)");
        out.push_back(item.toDouble());
    }
    if (out.size() < 3 || out.size() > 5) s.fail(key, "must have 3 to 5 coefficients (degree 2 .. 4)");
    return out;
}

int calibrationDegree(const JsonSection& s) {
    const QJsonValue v = s.value(QStringLiteral("degree"));
    if (v.isUndefined() || (v.isString() && v.toString() == QStringLiteral("auto"))) return core::kAutoDegree;
    if (v.isDouble() && (v.toDouble() == 2.0 || v.toDouble() == 3.0 || v.toDouble() == 4.0))
        return static_cast<int>(v.toDouble());
    s.fail(QStringLiteral("degree"), "must be 2, 3, 4 or \"auto\"");
}

}  // namespace

core::BoringScenario boringScenarioFromPreset(const QJsonObject& preset) {
    core::BoringScenario sc;
    sc.name = preset.value(QStringLiteral("name")).toString().toStdString();
    sc.description = preset.value(QStringLiteral("description")).toString().toStdString();
    sc.tool = readTool(preset);

    const JsonSection bar(preset, QStringLiteral("bar"));
    sc.trueStiffnessFactor = bar.number(QStringLiteral("true_stiffness_factor"), 1.0, 0.5, 1.5);

    const JsonSection cut(preset, QStringLiteral("cut"));
    core::BoringCutConfig& c = sc.cut;
    c.boreLengthMm = cut.number(QStringLiteral("bore_length_mm"), c.boreLengthMm, 10.0, 5000.0);
    c.feedMmPerRev = cut.number(QStringLiteral("feed_mm_per_rev"), c.feedMmPerRev, 0.01, 2.0);
    c.spindleRpm = cut.number(QStringLiteral("spindle_rpm"), c.spindleRpm, 1.0, 5000.0);
    c.radialSpecificForceNPerMm2 =
        cut.number(QStringLiteral("radial_specific_force_n_per_mm2"), c.radialSpecificForceNPerMm2, 10.0, 10000.0);
    c.tangentialToRadialRatio =
        cut.number(QStringLiteral("tangential_to_radial_ratio"), c.tangentialToRadialRatio, 0.0, 10.0);
    c.depthStartMm = cut.number(QStringLiteral("depth_start_mm"), c.depthStartMm, 0.01, 20.0);
    c.depthEndMm = cut.number(QStringLiteral("depth_end_mm"), c.depthEndMm, 0.01, 20.0);
    c.hardnessVariation = cut.number(QStringLiteral("hardness_variation"), c.hardnessVariation, 0.0, 0.5);
    c.hardnessWavelengthMm = cut.number(QStringLiteral("hardness_wavelength_mm"), c.hardnessWavelengthMm, 1.0, 1e5);
    c.wearForceIncrease = cut.number(QStringLiteral("wear_force_increase"), c.wearForceIncrease, 0.0, 2.0);
    c.approachMm = cut.number(QStringLiteral("approach_mm"), c.approachMm, 0.0, 100.0);
    c.entryRampMm = cut.number(QStringLiteral("entry_ramp_mm"), c.entryRampMm, 0.0, 50.0);
    c.gaugeMarginMm = cut.number(QStringLiteral("gauge_margin_mm"), c.gaugeMarginMm, 0.0, c.boreLengthMm / 2.0 - 1.0);
    c.boreToleranceMm = cut.number(QStringLiteral("bore_tolerance_mm"), c.boreToleranceMm, 0.0, 1.0);

    const JsonSection drive(preset, QStringLiteral("drive"));
    core::CrossFeedDriveConfig& d = sc.drive;
    d.slideMassKg = drive.number(QStringLiteral("slide_mass_kg"), d.slideMassKg, 1.0, 1e5);
    d.motorInertiaKg = drive.number(QStringLiteral("motor_inertia_kg"), d.motorInertiaKg, 0.0, 1e5);
    d.coulombFrictionN = drive.number(QStringLiteral("coulomb_friction_n"), d.coulombFrictionN, 0.0, 1e6);
    d.staticFrictionN = drive.number(QStringLiteral("static_friction_n"), d.staticFrictionN, 0.0, 1e6);
    d.viscousFrictionNsPerMm =
        drive.number(QStringLiteral("viscous_friction_n_s_per_mm"), d.viscousFrictionNsPerMm, 0.0, 1e6);
    d.transmissionStiffnessNPerMm =
        drive.number(QStringLiteral("transmission_stiffness_n_per_mm"), d.transmissionStiffnessNPerMm, 1e3, 1e8);
    d.transmissionDampingNsPerMm =
        drive.number(QStringLiteral("transmission_damping_n_s_per_mm"), d.transmissionDampingNsPerMm, 0.0, 1e6);
    d.currentToForceNPerA = drive.number(QStringLiteral("current_to_force_n_per_a"), d.currentToForceNPerA, 1e-3, 1e6);
    d.currentNoiseA = drive.number(QStringLiteral("current_noise_a"), d.currentNoiseA, 0.0, 100.0);
    d.velocityNoiseMmPerS = drive.number(QStringLiteral("velocity_noise_mm_per_s"), d.velocityNoiseMmPerS, 0.0, 10.0);
    d.positionNoiseMm = drive.number(QStringLiteral("position_noise_mm"), d.positionNoiseMm, 0.0, 1.0);
    if (d.staticFrictionN < d.coulombFrictionN)
        drive.fail(QStringLiteral("static_friction_n"), "must be at least coulomb_friction_n");

    const JsonSection dither(preset, QStringLiteral("dither"));
    sc.dither.amplitudeMm = dither.number(QStringLiteral("amplitude_mm"), sc.dither.amplitudeMm, 0.005, 0.05);
    sc.dither.periodS = dither.number(QStringLiteral("period_s"), sc.dither.periodS, 0.2, 2.0);
    sc.dither.constantVelocityFraction =
        dither.number(QStringLiteral("constant_velocity_fraction"), sc.dither.constantVelocityFraction, 0.2, 0.9);

    const JsonSection est(preset, QStringLiteral("estimator"));
    core::DitherEstimatorConfig& e = sc.estimator;
    e.movingVelocityMmPerS = est.number(QStringLiteral("moving_velocity_mm_per_s"), e.movingVelocityMmPerS, 1e-6, 10.0);
    e.plateauTolerance = est.number(QStringLiteral("plateau_tolerance"), e.plateauTolerance, 0.01, 0.5);
    e.minPlateauSamples = est.integer(QStringLiteral("min_plateau_samples"), e.minPlateauSamples, 1, 1000);
    e.minStrokeMm = est.number(QStringLiteral("min_stroke_mm"), e.minStrokeMm, 1e-6, 1.0);
    e.maxSpeedAsymmetry = est.number(QStringLiteral("max_speed_asymmetry"), e.maxSpeedAsymmetry, 0.01, 1.0);
    e.maxStrokeS = est.number(QStringLiteral("max_stroke_s"), e.maxStrokeS, 0.1, 100.0);
    e.maxQuietS = est.number(QStringLiteral("max_quiet_s"), e.maxQuietS, 0.1, 100.0);
    e.maxPairAgeS = est.number(QStringLiteral("max_pair_age_s"), e.maxPairAgeS, 0.1, 100.0);
    e.strokesAveraged = est.integer(QStringLiteral("strokes_averaged"), e.strokesAveraged, 1, 64);

    const JsonSection probe(preset, QStringLiteral("probe"));
    core::InductiveProbeConfig& p = sc.probe;
    p.adcBits = probe.integer(QStringLiteral("adc_bits"), p.adcBits, core::kMinAdcBits, core::kMaxAdcBits);
    p.fullScaleGapMm = probe.number(QStringLiteral("full_scale_gap_mm"), p.fullScaleGapMm, 1e-3, 10.0);
    p.bridgeCoefficients = coefficients(probe, QStringLiteral("bridge_coefficients"), p.bridgeCoefficients);
    p.noiseRms = probe.number(QStringLiteral("noise_rms"), p.noiseRms, 0.0, 0.1);
    p.supplyVariation = probe.number(QStringLiteral("supply_variation"), p.supplyVariation, 0.0, 0.4);
    p.supplyVariationPeriodS =
        probe.number(QStringLiteral("supply_variation_period_s"), p.supplyVariationPeriodS, 0.01, 1e4);
    p.filterTimeConstantS = probe.number(QStringLiteral("filter_time_constant_s"), p.filterTimeConstantS, 1e-5, 1.0);
    p.crossTalk = probe.number(QStringLiteral("cross_talk"), p.crossTalk, 0.0, 0.5);
    p.sensorPositionFraction =
        probe.number(QStringLiteral("sensor_position_fraction"), p.sensorPositionFraction, 0.05, 1.0);
    p.sampleRateHz = probe.number(QStringLiteral("sample_rate_hz"), p.sampleRateHz, 1.0, 10000.0);

    const JsonSection cal(preset, QStringLiteral("calibration"));
    core::ProbeCalibrationConfig& k = sc.calibration;
    k.points = cal.integer(QStringLiteral("points"), k.points, 5, 1000);
    k.readingsPerPoint = cal.integer(QStringLiteral("readings_per_point"), k.readingsPerPoint, 1, 1000);
    k.spanFraction = cal.number(QStringLiteral("span_fraction"), k.spanFraction, 0.1, 1.0);
    k.referenceResolutionUm =
        cal.number(QStringLiteral("reference_resolution_um"), k.referenceResolutionUm, 0.0, 100.0);
    k.referenceNoiseUm = cal.number(QStringLiteral("reference_noise_um"), k.referenceNoiseUm, 0.0, 100.0);
    k.degree = calibrationDegree(cal);

    const JsonSection comp(preset, QStringLiteral("compensation"));
    sc.limits.maxOffsetMm = comp.number(QStringLiteral("max_offset_mm"), sc.limits.maxOffsetMm, 1e-3, 10.0);
    sc.limits.maxRateMmPerS = comp.number(QStringLiteral("max_rate_mm_per_s"), sc.limits.maxRateMmPerS, 1e-4, 100.0);
    sc.plcCycleS = comp.number(QStringLiteral("plc_cycle_ms"), sc.plcCycleS * 1000.0, 10.0, 100.0) / 1000.0;

    const JsonSection sim(preset, QStringLiteral("simulation"));
    sc.simStepS = sim.number(QStringLiteral("step_ms"), sc.simStepS * 1000.0, 0.01, 1.0) / 1000.0;
    sc.seed = static_cast<unsigned long long>(sim.number(QStringLiteral("seed"), 1.0, 0.0, 9007199254740991.0));
    core::validateScenario(sc);
    return sc;
}

core::BoringScenario loadBoringScenario(const QString& nameOrPath) {
    const QJsonObject preset = PresetLibrary::load(nameOrPath);
    try {
        return boringScenarioFromPreset(preset);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("preset '" + nameOrPath.toStdString() + "': " + e.what());
    }
}

}  // namespace tt::config
