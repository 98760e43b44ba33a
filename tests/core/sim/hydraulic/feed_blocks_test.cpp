// The blocks of the feed stabiliser's chain (paper 003, shared/seeds/003_*.txt), each integrated with
// the project's Dormand-Prince integrator and compared with its analytic step response: the
// electromagnet (eq. 2), the spool for xi > 1 (eq. 11), xi = 1 and xi < 1 (eq. 12), the cylinder
// (eq. 22); and the derived coefficients against the numbers the paper prints.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/sim/hydraulic/hydraulic_feed_blocks.h"
#include "core/sim/hydraulic/hydraulic_feed_params.h"
#include "core/sim/hydraulic/ode_integrator.h"

namespace tt::core {
namespace {

std::vector<double> timeGrid(double endS, int steps) {
    std::vector<double> t;
    for (int k = 0; k <= steps; ++k)
        t.push_back(endS * k / steps);
    return t;
}

/// Integrates dx/dt = f(x) from x0 and returns the first component at each time of `times`.
std::vector<double> solve(const OdeRightHandSide& f, std::vector<double> x0, const std::vector<double>& times,
                          std::vector<double> scale) {
    std::vector<double> out;
    integrateDormandPrince(
        f, std::move(x0), times, [&](double, const std::vector<double>& x) { out.push_back(x[0]); }, scale);
    return out;
}

// Eq. 2: i(t) = k_k U (1 - e^{-t/T_k}), k_k = 1/r, T_k = L/r. The paper's coil: L = 115^2 x 1.79e-5 H.
TEST(FeedBlocks, ElectromagnetFollowsTheFirstOrderStepResponse) {
    const double inductance = 115.0 * 115.0 * 1.79e-5;  // 0.2367 H
    const double r = 240.0;
    const double u = 4.0;
    const double tk = inductance / r;
    const std::vector<double> t = timeGrid(8.0 * tk, 200);
    const std::vector<double> i =
        solve([&](double, const std::vector<double>& x,
                  std::vector<double>& d) { d = {magnetCurrentRate(x[0], u, inductance, r)}; },
              {0.0}, t, {u / r});
    for (std::size_t k = 0; k < t.size(); ++k)
        EXPECT_NEAR(i[k], u / r * (1.0 - std::exp(-t[k] / tk)), 1e-7 * u / r) << t[k];
    // The paper's settling rule t_c = 3T: 95 % of the final value.
    EXPECT_NEAR(u / r * (1.0 - std::exp(-3.0)), 0.950213 * u / r, 1e-6 * u / r);
}

/// The spool's response to a force step F: h(t) for T_z = 3 ms, K_z = 7.6e-5 m/N.
std::vector<double> spoolStep(double xi, const std::vector<double>& t, double forceN) {
    constexpr double tz = 0.003;
    constexpr double kz = 7.6e-5;
    return solve(
        [&](double, const std::vector<double>& x, std::vector<double>& d) {
            d = {x[1], spoolAcceleration(x[0], x[1], forceN, tz, xi, kz)};
        },
        {0.0, 0.0}, t, {kz * forceN, kz * forceN / tz});
}

// Eq. 11 (xi >= 1, aperiodic of the second order): h = h_y (1 - T3/(T3-T4) e^{-t/T3} + T4/(T3-T4) e^{-t/T4})
// with T3 T4 = T_z^2 and T3 + T4 = 2 xi T_z.
TEST(FeedBlocks, SpoolAboveCriticalDampingIsTwoFirstOrderLags) {
    const double tz = 0.003, xi = 1.5, force = 2.0, hy = 7.6e-5 * force;
    const double root = std::sqrt(xi * xi - 1.0);
    const double t3 = tz * (xi + root), t4 = tz * (xi - root);
    ASSERT_NEAR(t3 * t4, tz * tz, 1e-15);
    const std::vector<double> t = timeGrid(0.06, 300);
    const std::vector<double> h = spoolStep(xi, t, force);
    double highest = 0.0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        const double exact = hy * (1.0 - t3 / (t3 - t4) * std::exp(-t[k] / t3) + t4 / (t3 - t4) * std::exp(-t[k] / t4));
        EXPECT_NEAR(h[k], exact, 1e-6 * hy) << t[k];
        highest = std::max(highest, h[k]);
    }
    EXPECT_LE(highest, hy * (1.0 + 1e-6));  // no overshoot
}

// xi = 1 (the repeated root of eq. 10): h = h_y (1 - (1 + t/T_z) e^{-t/T_z}).
TEST(FeedBlocks, SpoolAtCriticalDampingHasTheRepeatedRootResponse) {
    const double tz = 0.003, force = 2.0, hy = 7.6e-5 * force;
    const std::vector<double> t = timeGrid(0.05, 250);
    const std::vector<double> h = spoolStep(1.0, t, force);
    for (std::size_t k = 0; k < t.size(); ++k)
        EXPECT_NEAR(h[k], hy * (1.0 - (1.0 + t[k] / tz) * std::exp(-t[k] / tz)), 1e-6 * hy) << t[k];
}

// Eq. 12 (xi < 1, oscillatory): h = h_y (1 - e^{-t/T} (cos wt + sin(wt) / (wT))), T = T_z / xi,
// w = sqrt(1 - xi^2) / T_z; the first peak overshoots by exp(-pi xi / sqrt(1 - xi^2)).
TEST(FeedBlocks, SpoolBelowCriticalDampingOscillates) {
    const double tz = 0.003, xi = 0.3, force = 2.0, hy = 7.6e-5 * force;
    const double tDecay = tz / xi;
    const double w = std::sqrt(1.0 - xi * xi) / tz;
    const std::vector<double> t = timeGrid(0.1, 1000);
    const std::vector<double> h = spoolStep(xi, t, force);
    double highest = 0.0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        const double exact =
            hy * (1.0 - std::exp(-t[k] / tDecay) * (std::cos(w * t[k]) + std::sin(w * t[k]) / (w * tDecay)));
        EXPECT_NEAR(h[k], exact, 1e-6 * hy) << t[k];
        highest = std::max(highest, h[k]);
    }
    // 37.2 % for xi = 0.3 (the sampled peak is within 0.1 % of the continuous one at this grid).
    EXPECT_NEAR(highest / hy - 1.0, std::exp(-std::numbers::pi * xi / std::sqrt(1.0 - xi * xi)), 2e-3);
}

// Eq. 22: from rest, V = k_0 (Q - alpha_0)(1 - e^{-t/T_c}); with the paper's numbers (k_0 = 56.588 m^-2,
// T_c = 0.018 s, Q = 3.036e-5 m^3/s, alpha_0 = 1.268e-5 m^3/s) it ends at 1e-3 m/s.
TEST(FeedBlocks, CylinderFollowsEquationTwentyTwo) {
    const double k0 = 56.588, tc = 0.018, q = 3.036e-5, alpha = 1.268e-5;
    const std::vector<double> t = timeGrid(0.2, 200);
    const std::vector<double> v =
        solve([&](double, const std::vector<double>& x,
                  std::vector<double>& d) { d = {cylinderAcceleration(x[0], q, alpha, tc, k0)}; },
              {0.0}, t, {1e-3});
    for (std::size_t k = 0; k < t.size(); ++k)
        EXPECT_NEAR(v[k], k0 * (q - alpha) * (1.0 - std::exp(-t[k] / tc)), 1e-9) << t[k];
    EXPECT_NEAR(v.back(), 1.0e-3, 0.001e-3);  // 56.588 x 1.768e-5 = 1.0005e-3
}

TEST(FeedBlocks, StaticBlocks) {
    // Eq. 6 with eq. 5's gain for the paper's coil (115 turns, Lambda = 1.79e-5, S = 4.11e-4 m^2 at a 1 mm gap,
    // mu = 1.25e-6): K_e = (115 x 1.79e-5)^2 / (2 x 1.25e-6 x 4.11e-4) = 4124.0 N/A^2.
    EXPECT_NEAR(armatureForce(0.02, 4124.0), 4124.0 * 4e-4, 1e-12);
    EXPECT_DOUBLE_EQ(slotFlow(1e-4, 0.118), 0.118e-4);  // eq. 15
    EXPECT_DOUBLE_EQ(slotOpening(0.5e-3, 0.2e-3, 1e-3), 0.3e-3);
    EXPECT_DOUBLE_EQ(slotOpening(0.1e-3, 0.2e-3, 1e-3), 0.0);   // inside the lap: shut
    EXPECT_DOUBLE_EQ(slotOpening(2.0e-3, 0.2e-3, 1e-3), 1e-3);  // on the stop
    EXPECT_DOUBLE_EQ(leakageFlow(3.23, 6.94e-8 / 0.0176715), 6.94e-8 * 3.23 / 0.0176715);
    EXPECT_DOUBLE_EQ(sensedForce(10.0, 0.5e-3, 1e-3, 0.0), 10.0);  // the paper: force independent of the feed
    EXPECT_NEAR(sensedForce(10.0, 0.5e-3, 1e-3, 0.6), 10.0 * std::pow(0.5, 0.6), 1e-12);
    EXPECT_DOUBLE_EQ(sensedForce(10.0, -1e-4, 1e-3, 0.6), 0.0);  // the tool leaves the cut
}

// The paper's printed coefficients follow from the kept data (the preset's notes): k_0 = 1/F = 56.588 m^-2
// with F = pi 0.15^2 / 4; T_c = M k_y / F^2 = 0.018 s; alpha_0 = k_y R / F = 1.268e-5 m^3/s for R = 3.23;
// the control flow Q_y + alpha_0 = 3.036e-5 m^3/s; L = 0.2367 H, K_e = 4124 N/A^2.
TEST(FeedBlocks, DerivedCoefficientsReproduceThePaperPrintedValues) {
    const HydraulicFeedParams p;
    const HydraulicFeedDerived d = deriveFeedQuantities(p);
    EXPECT_NEAR(d.cylinderGainPerM2, 56.588, 0.001);
    EXPECT_NEAR(d.cylinderTimeConstantS, 0.018, 0.00005);
    EXPECT_NEAR(d.leakagePerNewtonM3PerS * 3.23, 1.268e-5, 0.001e-5);
    EXPECT_NEAR(d.pumpFlowM3PerS + d.leakagePerNewtonM3PerS * 3.23, 3.036e-5, 0.001e-5);
    EXPECT_NEAR(d.coilInductanceH, 0.2367, 0.0001);
    EXPECT_NEAR(d.armatureGainNPerA2, 4124.0, 0.1);
    // k_s = 0.63 pi 0.004 sqrt(2 x 1e5 / 900) = 0.11802 m^2/s.
    EXPECT_NEAR(d.slotGainM2PerS, 0.11802, 0.00001);
}

TEST(FeedParams, ValidationNamesTheValueAndItsLimits) {
    HydraulicFeedParams p;
    p.spoolDampingRatio = 0.01;
    try {
        validate(p);
        FAIL() << "xi = 0.01 accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "spool damping ratio xi = 0.01 is outside 0.05 .. 10");
    }
    p = HydraulicFeedParams{};
    p.pistonDiameterM = std::nan("");
    EXPECT_THROW(validate(p), std::invalid_argument);
    p = HydraulicFeedParams{};
    p.coilResistanceOhm = 2000.0;
    try {
        validate(p);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "coil resistance r = 2000 ohm is outside 0.1 .. 1000 ohm");
    }
    EXPECT_NO_THROW(validate(HydraulicFeedParams{}));
    EXPECT_EQ(feedParameters().size(), 21u);
    EXPECT_THROW(feedParameter("spool.mass"), std::invalid_argument);
}

// The design rule (the slot opens exactly as much as the leakage needs): with the lap and bias at 0,
// the gain gives K_z K_e (K_a k_d R / r)^2 = alpha_0 / k_s.
TEST(FeedParams, DesignGainOpensTheSlotForExactlyTheLeakage) {
    const HydraulicFeedParams p;
    const HydraulicFeedDerived d = deriveFeedQuantities(p);
    const double gain = designAmplifierGain(p, 3.23);
    const double current = gain * p.sensorGainVPerN * 3.23 / p.coilResistanceOhm;
    const double opening = p.spoolGainMPerN * d.armatureGainNPerA2 * current * current;
    EXPECT_NEAR(d.slotGainM2PerS * opening, d.leakagePerNewtonM3PerS * 3.23, 1e-12 * 1e-5);
    EXPECT_NEAR(gain, p.amplifierGain, 0.01);  // the preset's 137.6 is this gain rounded
    EXPECT_THROW(designAmplifierGain(p, 0.0), std::invalid_argument);
    EXPECT_THROW(designAmplifierGain(p, 500.0), std::invalid_argument);  // more leakage than the full slot passes
    EXPECT_DOUBLE_EQ(matchedSpoolLap(p), 0.0);
}

TEST(OdeIntegrator, RefusesBadInput) {
    const OdeRightHandSide f = [](double, const std::vector<double>& x, std::vector<double>& d) { d = {-x[0]}; };
    const OdeObserver none = [](double, const std::vector<double>&) {};
    EXPECT_THROW(integrateDormandPrince(f, {1.0}, {0.0, 1.0}, none, {1.0, 1.0}), std::invalid_argument);
    EXPECT_THROW(integrateDormandPrince(f, {1.0}, {1.0, 0.0}, none, {1.0}), std::invalid_argument);
    EXPECT_THROW(integrateDormandPrince(f, {1.0}, {0.0, 1.0}, none, {0.0}), std::invalid_argument);
    const OdeRightHandSide blowUp = [](double, const std::vector<double>& x, std::vector<double>& d) {
        d = {x[0] * x[0]};  // x = 1 / (1 - t): infinite at t = 1
    };
    EXPECT_THROW(integrateDormandPrince(blowUp, {1.0}, {0.0, 2.0}, none, {1.0}), std::runtime_error);
    EXPECT_NEAR(integrateDormandPrince(f, {1.0}, {0.0, 1.0}, none, {1.0})[0], std::exp(-1.0), 1e-8);
}

}  // namespace
}  // namespace tt::core
