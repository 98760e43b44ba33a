#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "core/control/plant_identification.h"
#include "core/control/run_to_run_setup.h"
#include "tests/core/support/lqg_test_support.h"

namespace tt::core::test {

/// The ARMA(1, 1) of paper-2012 (a = 0.9215, b = 0.246, stationary variance 0.0013 mm^2): its innovation variance
/// 0.0013 (1 - a^2) / (1 + 2ab + b^2).
inline constexpr double kPaperPole = 0.9215;
inline constexpr double kPaperZero = 0.246;
inline double paperInnovationVariance() {
    return 0.0013 * (1.0 - kPaperPole * kPaperPole) / (1.0 + 2.0 * kPaperPole * kPaperZero + kPaperZero * kPaperZero);
}

/// A closed loop of the paper-2012 plant (5 points, gauge noise 2.5e-7 mm^2) run part by part with `controller`
/// (designed by the caller) whose true gain is `gainFactor` x 2 and whose corrections act `lag` parts late:
/// before part p the measurement of part p - z is offered, then the correction of part p is asked for (the loop
/// engine's order). Returns the record the identification reads. std::mt19937_64 with `seed`.
inline LoopHistory runClosedLoop(RunToRunController& controller, int delay, double gainFactor, int lag,
                                 std::size_t parts, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n01(0.0, 1.0);
    const int m = controller.pointCount();
    const double sigmaE = std::sqrt(paperInnovationVariance());
    const double sigmaGauge = std::sqrt(2.5e-7);
    std::vector<double> d(static_cast<std::size_t>(m), 0.0), e(static_cast<std::size_t>(m), 0.0);
    // Burn-in of the disturbance to its stationary state.
    for (int k = 0; k < 500; ++k)
        for (std::size_t i = 0; i < d.size(); ++i) {
            const double en = sigmaE * n01(rng);
            d[i] = kPaperPole * d[i] + en + kPaperZero * e[i];
            e[i] = en;
        }
    LoopHistory h;
    h.firstPart = 1;
    std::vector<Eigen::VectorXd> measured;
    for (std::size_t p = 1; p <= parts; ++p) {
        const auto part = static_cast<std::int64_t>(p);
        if (part - delay >= 1)
            controller.addMeasurement({part - delay, measured[p - 1 - static_cast<std::size_t>(delay)]});
        const Eigen::VectorXd u = controller.nextCorrection(part);
        h.appliedMm.push_back(u);
        Eigen::VectorXd y(m);
        for (int i = 0; i < m; ++i) {
            const auto ii = static_cast<std::size_t>(i);
            const double en = sigmaE * n01(rng);
            d[ii] = kPaperPole * d[ii] + en + kPaperZero * e[ii];
            e[ii] = en;
            const double acting =
                p > static_cast<std::size_t>(lag) ? h.appliedMm[p - 1 - static_cast<std::size_t>(lag)](i) : 0.0;
            y(i) = 2.0 * gainFactor * acting + d[ii] + sigmaGauge * n01(rng);
        }
        measured.push_back(y);
        h.deviationMm.push_back(y);
    }
    // The newest z parts are not measured yet when the last part starts: the record ends with them unmeasured.
    for (std::size_t p = parts - static_cast<std::size_t>(delay); p < parts; ++p)
        h.deviationMm[p].setConstant(std::numeric_limits<double>::quiet_NaN());
    return h;
}

/// The identification options for a loop of delay z starting from paper-2012's model (gain 2, ARMA(1, 1) 0.9215 /
/// 0.246 at every point).
inline PlantIdentificationOptions paperIdentification(int delay) {
    PlantIdentificationOptions o;
    o.loopDelay = delay;
    o.priorGain.assign(5, 2.0);
    o.priorAr.assign(5, {kPaperPole});
    o.priorMa.assign(5, {kPaperZero});
    return o;
}

/// The paper-2012 LQG for delay z (designed on the model: gain 2, no lag).
inline std::unique_ptr<RunToRunController> paperLqg(int delay) {
    const RunToRunSetup s = paper2012Setup(delay);
    return makeRunToRunController(s, buildRunToRunPlant(s.plant), ControllerKind::Lqg, 1.0);
}

}  // namespace tt::core::test
