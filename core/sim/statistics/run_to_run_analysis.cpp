#include "core/sim/statistics/run_to_run_analysis.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/control/margins.h"
#include "core/linalg/stein.h"

namespace tt::core {

namespace {

using Eigen::Index;
using Eigen::MatrixXd;

void requireNoFeedthrough(const RunToRunPlant& plant) {
    if (!plant.D.isZero(0.0))
        throw std::invalid_argument("analysis: plants with feed-through (D != 0) are not supported");
}

}  // namespace

LinearControllerModel lqgControllerModel(const RunToRunPlant& plant, const LqgDesign& design) {
    requireNoFeedthrough(plant);
    const Index n = plant.stateCount();
    const MatrixXd I = MatrixXd::Identity(n, n);
    const MatrixXd AminusBK = plant.A - plant.B * design.K;
    const MatrixXd IminusLC = I - design.L * plant.C;
    return {AminusBK * IminusLC, AminusBK * design.L, -design.K * IminusLC, -design.K * design.L};
}

LinearControllerModel ewmaControllerModel(const RunToRunPlant& plant, double weight) {
    if (!(weight > 0.0 && weight <= 1.0)) throw std::invalid_argument("analysis: the EWMA weight must be in (0, 1]");
    const LoopController c = ewmaLoopController(plant.gain, plant.delay, weight);
    return {c.Ac, c.Bc, c.Cc, c.Dc};
}

LinearControllerModel openLoopControllerModel(const RunToRunPlant& plant) {
    const Index m = plant.pointCount();
    return {MatrixXd::Zero(0, 0), MatrixXd::Zero(0, m), MatrixXd::Zero(m, 0), MatrixXd::Zero(m, m)};
}

SteadyStateVariances analyseSteadyState(const RunToRunPlant& plant, const LinearControllerModel& controller) {
    requireNoFeedthrough(plant);
    const Index m = plant.pointCount();
    const Index n = plant.stateCount();
    const Index nc = controller.Ac.rows();
    SteadyStateVariances out;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.openMm2 = Eigen::VectorXd::Constant(m, nan);
    out.closedMm2 = Eigen::VectorXd::Constant(m, nan);
    out.kEff = Eigen::VectorXd::Constant(m, nan);
    out.kEffOverall = nan;
    for (const DisturbanceModel& d : plant.disturbances)
        if (!d.isStationary()) return out;

    const MatrixXd GWG = plant.G * plant.W * plant.G.transpose();
    const MatrixXd openSigma = solveDiscreteLyapunov(plant.A, GWG);
    out.openMm2 = (plant.C * openSigma * plant.C.transpose()).diagonal();
    out.available = true;

    // Closed loop of plant state x and controller state xi, driven by w and v.
    MatrixXd Phi(n + nc, n + nc);
    Phi.topLeftCorner(n, n) = plant.A + plant.B * controller.Dc * plant.C;
    if (nc > 0) {
        Phi.topRightCorner(n, nc) = plant.B * controller.Cc;
        Phi.bottomLeftCorner(nc, n) = controller.Bc * plant.C;
        Phi.bottomRightCorner(nc, nc) = controller.Ac;
    }
    MatrixXd Gamma = MatrixXd::Zero(n + nc, plant.G.cols() + m);
    Gamma.block(0, 0, n, plant.G.cols()) = plant.G;
    Gamma.block(0, plant.G.cols(), n, m) = plant.B * controller.Dc;
    if (nc > 0) Gamma.block(n, plant.G.cols(), nc, m) = controller.Bc;
    MatrixXd Xi = MatrixXd::Zero(plant.G.cols() + m, plant.G.cols() + m);
    Xi.topLeftCorner(plant.W.rows(), plant.W.cols()) = plant.W;
    Xi.bottomRightCorner(m, m) = plant.V;
    if (spectralRadius(Phi) >= 1.0) {
        out.closedMm2.setConstant(std::numeric_limits<double>::infinity());
        out.kEff.setZero();
        out.kEffOverall = 0.0;
        return out;
    }
    const MatrixXd sigma = solveDiscreteLyapunov(Phi, Gamma * Xi * Gamma.transpose());
    const MatrixXd Cx = plant.C;  // true deviation: C x (D = 0), no gauge noise
    out.closedMm2 = (Cx * sigma.topLeftCorner(n, n) * Cx.transpose()).diagonal();
    out.kEff = out.openMm2.cwiseQuotient(out.closedMm2);
    out.kEffOverall = out.openMm2.sum() / out.closedMm2.sum();
    return out;
}

std::vector<double> defaultEwmaWeightGrid() {
    std::vector<double> grid;
    for (int i = 1; i <= 20; ++i)
        grid.push_back(0.05 * i);
    return grid;
}

EwmaWeightChoice bestEwmaWeight(const RunToRunPlant& plant, const std::vector<double>& grid) {
    if (grid.empty()) throw std::invalid_argument("EWMA weight search: empty grid");
    EwmaWeightChoice best{grid.front(), std::numeric_limits<double>::infinity()};
    for (double weight : grid) {
        const SteadyStateVariances v = analyseSteadyState(plant, ewmaControllerModel(plant, weight));
        if (!v.available)
            throw std::invalid_argument(
                "the EWMA weight cannot be chosen automatically for a disturbance that is not stationary "
                "(random walk); give --ewma-weight");
        const double sum = v.closedMm2.sum();
        if (sum < best.closedVarianceSumMm2) best = {weight, sum};
    }
    return best;
}

double chooseEwmaWeight(const RunToRunSetup& setup, const RunToRunPlant& plant, std::optional<double> given) {
    if (given) return *given;
    return setup.ewmaWeightAuto ? bestEwmaWeight(plant, defaultEwmaWeightGrid()).weight : setup.ewma.weight;
}

LinearControllerModel controllerModel(const RunToRunSetup& setup, const RunToRunPlant& plant, ControllerKind kind,
                                      double ewmaWeight) {
    switch (kind) {
        case ControllerKind::Lqg:
            return lqgControllerModel(plant, designLqg(plant, setup.weights));
        case ControllerKind::Ewma:
            return ewmaControllerModel(plant, ewmaWeight);
        case ControllerKind::Open:
            break;
        case ControllerKind::Dewma:
            throw std::invalid_argument("analysis: the double EWMA has no linear model here");
    }
    return openLoopControllerModel(plant);
}

}  // namespace tt::core
