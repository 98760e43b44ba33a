#include "core/sim/hydraulic/feed_linearisation.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

#include "core/sim/hydraulic/hydraulic_feed_params.h"

namespace tt::core {

namespace {

/// d(amplifier voltage)/d(feed) and d(amplifier voltage)/d(load) at the steady state.
std::pair<double, double> amplifierSlopes(const HydraulicFeedModel& model, double loadN, double feedMPerS) {
    const HydraulicFeedParams& p = model.params();
    if (!model.regulatorOn()) return {0.0, 0.0};
    const double gain = p.amplifierGain * p.sensorGainVPerN;
    if (p.feedExponent == 0.0) return {0.0, gain};
    if (feedMPerS <= 0.0) return {0.0, 0.0};
    const double ratio = feedMPerS / p.setFeedMPerS;
    return {gain * loadN * p.feedExponent * std::pow(ratio, p.feedExponent - 1.0) / p.setFeedMPerS,
            gain * std::pow(ratio, p.feedExponent)};
}

/// dm/dh: 1 while the slot is partly open (a steady state on the lap counts as opening: a load
/// pushes the spool that way), 0 when shut further in or on the stop.
double openingSlope(const HydraulicFeedModel& model, double spoolM) {
    const double beyondLap = spoolM - model.params().spoolLapM;
    const double tolerance = 1e-12 * std::max(1e-6, model.params().spoolLapM);
    return beyondLap >= -tolerance && beyondLap < model.params().maxOpeningM * (1.0 - 1e-9) ? 1.0 : 0.0;
}

}  // namespace

bool FeedLinearisation::stable() const {
    for (Eigen::Index k = 0; k < eigenvalues.size(); ++k)
        if (eigenvalues(k).real() >= 0.0) return false;
    return eigenvalues.size() > 0;
}

FeedLinearisation linearise(const HydraulicFeedModel& model, double loadN) {
    const HydraulicFeedParams& p = model.params();
    const HydraulicFeedDerived& d = model.derived();
    FeedLinearisation lin;
    lin.loadN = loadN;
    lin.equilibrium = model.equilibrium(loadN);
    const FeedState& x = lin.equilibrium.state;
    const auto [voltagePerFeed, voltagePerLoad] = amplifierSlopes(model, loadN, x.feedMPerS);
    const double slope = openingSlope(model, x.spoolM);
    const double tz2 = p.spoolTimeConstantS * p.spoolTimeConstantS;
    const double tc = d.cylinderTimeConstantS;

    lin.A = Eigen::MatrixXd::Zero(4, 4);
    lin.A(0, 0) = -p.coilResistanceOhm / d.coilInductanceH;
    lin.A(0, 3) = voltagePerFeed / d.coilInductanceH;
    lin.A(1, 2) = 1.0;
    lin.A(2, 0) = 2.0 * p.spoolGainMPerN * d.armatureGainNPerA2 * x.currentA / tz2;
    lin.A(2, 1) = -1.0 / tz2;
    lin.A(2, 2) = -2.0 * p.spoolDampingRatio / p.spoolTimeConstantS;
    lin.A(3, 1) = d.cylinderGainPerM2 * d.slotGainM2PerS * slope / tc;
    lin.A(3, 3) = -1.0 / tc;
    lin.B = Eigen::VectorXd::Zero(4);
    lin.B(0) = voltagePerLoad / d.coilInductanceH;
    lin.B(3) = -d.cylinderGainPerM2 * d.leakagePerNewtonM3PerS / tc;
    lin.eigenvalues = Eigen::EigenSolver<Eigen::MatrixXd>(lin.A, false).eigenvalues();
    lin.loopGain = d.cylinderGainPerM2 * d.slotGainM2PerS * slope * p.spoolGainMPerN * 2.0 * d.armatureGainNPerA2 *
                   x.currentA * voltagePerFeed / p.coilResistanceOhm;
    return lin;
}

std::vector<FeedState> linearStepResponse(const FeedLinearisation& lin, double deltaLoadN,
                                          const std::vector<double>& timesS) {
    // In scaled states (each divided by its steady-state size) the modal basis is well conditioned
    // unless two poles coincide.
    Eigen::VectorXd scale(4);
    const FeedState& x = lin.equilibrium.state;
    scale << std::max(std::abs(x.currentA), 1e-6), std::max(std::abs(x.spoolM), 1e-9),
        std::max(std::abs(x.spoolM), 1e-9) * std::abs(lin.A(2, 2)), std::max(std::abs(x.feedMPerS), 1e-9);
    const Eigen::MatrixXd scaled = scale.cwiseInverse().asDiagonal() * lin.A * scale.asDiagonal();
    Eigen::EigenSolver<Eigen::MatrixXd> eig(scaled, true);
    const Eigen::VectorXcd lambda = eig.eigenvalues();
    for (Eigen::Index i = 0; i < lambda.size(); ++i)
        for (Eigen::Index j = i + 1; j < lambda.size(); ++j)
            if (std::abs(lambda(i) - lambda(j)) < 1e-6 * std::max(std::abs(lambda(i)), std::abs(lambda(j))))
                throw std::runtime_error(
                    "the linearised chain has repeated poles (the spool at xi = 1?): its modal solution does not "
                    "exist");
    const Eigen::MatrixXcd V = scale.cast<std::complex<double>>().asDiagonal() * eig.eigenvectors();
    const Eigen::VectorXcd modal = V.partialPivLu().solve((lin.B * deltaLoadN).cast<std::complex<double>>());
    std::vector<FeedState> out;
    out.reserve(timesS.size());
    for (double t : timesS) {
        Eigen::VectorXcd weights(lambda.size());
        for (Eigen::Index k = 0; k < lambda.size(); ++k)
            weights(k) =
                std::abs(lambda(k)) < 1e-12 ? std::complex<double>(t) : (std::exp(lambda(k) * t) - 1.0) / lambda(k);
        const Eigen::VectorXd dx = (V * weights.cwiseProduct(modal)).real();
        out.push_back({dx(0), dx(1), dx(2), dx(3)});
    }
    return out;
}

FeedStability analyseStability(const HydraulicFeedParams& params, double loadN) {
    FeedStability s;
    s.designGain = designAmplifierGain(params, loadN);
    s.atGain = linearise(HydraulicFeedModel(params, true), loadN);
    auto linearisedAt = [&](double gain) {
        HydraulicFeedParams p = params;
        p.amplifierGain = gain;
        return linearise(HydraulicFeedModel(p, true), loadN);
    };
    auto regulating = [](const FeedLinearisation& lin) { return !lin.equilibrium.slotFullyOpen && lin.stable(); };
    const double maxGain = feedParameter("amplifier.gain").maxValue;
    double lo = 0.0;
    double hi = std::max({1.0, params.amplifierGain, s.designGain});
    while (regulating(linearisedAt(hi))) {
        lo = hi;
        if (hi >= maxGain) return s;
        hi = std::min(maxGain, 2.0 * hi);
    }
    for (int it = 0; it < 80 && hi - lo > 1e-9 * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        (regulating(linearisedAt(mid)) ? lo : hi) = mid;
    }
    // Losing stability, an eigenvalue comes to the imaginary axis (at a fold of the steady state it
    // goes to 0 as the square root of the distance to the limit); reaching the stop, the eigenvalues
    // stay where the chain's time constants put them.
    const FeedLinearisation last = linearisedAt(lo);
    double slowest = -std::numeric_limits<double>::infinity();
    for (Eigen::Index k = 0; k < last.eigenvalues.size(); ++k)
        slowest = std::max(slowest, last.eigenvalues(k).real());
    const double cylinderRate = -last.A(3, 3);  // 1 / T_c
    if (slowest > -0.01 * cylinderRate)
        s.gainLimit = lo;
    else
        s.fullOpeningGain = lo;
    return s;
}

}  // namespace tt::core
