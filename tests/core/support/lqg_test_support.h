#pragma once

#include <vector>

#include "core/control/run_to_run_plant.h"
#include "core/control/run_to_run_setup.h"

namespace tt::core::test {

/// Table 2 of paper 000 (seed 000_38bcd8d82e5e464d.txt): k_eff for z = 1..4.
inline constexpr double kTable2KEff[4] = {10.02, 4.23, 2.84, 2.25};

/// The calibrated disturbance of resources/presets/paper-2012.json (reasoning in docs/DECISIONS.md,
/// "paper-2012 calibration"): W(z) = (z + 0.246)/(z - 0.9215), 0.0013 mm^2 per point.
inline DisturbanceModel paper2012Disturbance() {
    return DisturbanceModel({DisturbanceComponent::shapingFilterWithVariance(
        ShapingFilter::fromRoots({1.0, 0.246}, {{0.9215, 0.0}}), 0.0013)});
}

/// The paper-2012 scenario as in the preset: 5 points on 325 mm, k_i = 2, gauge 2.5e-7 mm^2, R1 = 1,
/// R2 = 0.01, limits 0.3 mm / 0.1 mm per part, gate 5 sigma.
inline RunToRunSetup paper2012Setup(int delay) {
    RunToRunSetup s;
    s.plant.delay = delay;
    for (double x : paperControlPointsMm(325.0))
        s.plant.points.push_back(ControlPointSpec{x, 2.0, paper2012Disturbance(), 2.5e-7});
    s.weights = {Eigen::MatrixXd::Identity(5, 5), 0.01 * Eigen::MatrixXd::Identity(5, 5)};
    s.limits = {0.3, 0.1};
    return s;
}

/// A one-point plant with an AR(1) disturbance (pole, variance) and gauge noise.
inline RunToRunPlant ar1Plant(int delay, double pole, double varianceMm2, double gaugeMm2, int points = 1) {
    RunToRunPlantSpec spec;
    spec.delay = delay;
    for (int i = 0; i < points; ++i)
        spec.points.push_back(ControlPointSpec{
            10.0 * i, 2.0, DisturbanceModel({DisturbanceComponent::ar1(pole, varianceMm2)}), gaugeMm2});
    return buildRunToRunPlant(spec);
}

}  // namespace tt::core::test
