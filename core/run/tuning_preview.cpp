#include "core/run/tuning_preview.h"

#include <cmath>
#include <deque>
#include <numbers>
#include <stdexcept>

#include "core/control/lqg_design.h"
#include "core/sim/statistics/run_to_run_analysis.h"

namespace tt::core {

std::vector<double> stepResponse(const RunToRunPlant& plant, const Eigen::MatrixXd& Ac, const Eigen::MatrixXd& Bc,
                                 const Eigen::MatrixXd& Cc, const Eigen::MatrixXd& Dc, int point, int steps) {
    const Eigen::Index m = plant.pointCount();
    if (point < 0 || point >= m)
        throw std::invalid_argument("step response: no control point " + std::to_string(point + 1));
    Eigen::VectorXd xi = Eigen::VectorXd::Zero(Ac.rows());
    std::deque<Eigen::VectorXd> pending(static_cast<std::size_t>(plant.delay), Eigen::VectorXd::Zero(m));
    std::vector<double> out;
    out.reserve(static_cast<std::size_t>(steps));
    for (int k = 0; k < steps; ++k) {
        // y(k) = d(k) + k_i u(k - z): the correction decided z parts ago acts now.
        Eigen::VectorXd y = plant.gain.cwiseProduct(pending.front());
        pending.pop_front();
        y(point) += 1.0;
        out.push_back(y(point));
        const Eigen::VectorXd u = Cc * xi + Dc * y;
        xi = Ac * xi + Bc * y;
        pending.push_back(u);
    }
    return out;
}

namespace {

/// The loop of one point alone (the EWMA controls every point independently): its gain and the delay.
RunToRunPlant pointLoop(const RunToRunPlant& plant, int point) {
    RunToRunPlant one;
    one.delay = plant.delay;
    one.xMm = {plant.xMm[static_cast<std::size_t>(point)]};
    one.gain = Eigen::VectorXd::Constant(1, plant.gain(point));
    return one;
}

/// The best EWMA's figures on the plant (they do not depend on the LQG weights).
void computeEwmaPart(const RunToRunPlant& plant, const RunToRunSetup& setup, bool varianceAvailable, TuningPreview& p) {
    p.ewmaWeight = varianceAvailable ? bestEwmaWeight(plant, defaultEwmaWeightGrid()).weight : setup.ewma.weight;
    const LinearControllerModel ewma = ewmaControllerModel(plant, p.ewmaWeight);
    p.ewmaKEff = analyseSteadyState(plant, ewma).kEff;
    p.stepEwma = stepResponse(plant, ewma.Ac, ewma.Bc, ewma.Cc, ewma.Dc, 0, kPreviewSteps);
    // The EWMA's points do not interact: each point's margins from its own loop (5 small loops instead of
    // one 5-channel loop broken at each point).
    p.ewmaMargins = LoopMargins{};
    p.ewmaMargins.closedLoopStable = true;
    for (int i = 0; i < plant.pointCount(); ++i) {
        const RunToRunPlant one = pointLoop(plant, i);
        const LinearControllerModel c = ewmaControllerModel(one, p.ewmaWeight);
        const LoopMargins m = computeLoopMargins(one.gain, one.delay, {c.Ac, c.Bc, c.Cc, c.Dc});
        p.ewmaMargins.channels.push_back(m.channels.front());
        p.ewmaMargins.closedLoopStable = p.ewmaMargins.closedLoopStable && m.closedLoopStable;
        p.ewmaMargins.delayMarginBelowOnePart = p.ewmaMargins.delayMarginBelowOnePart || m.delayMarginBelowOnePart;
        if (i == 0)
            p.sensitivityEwma =
                sensitivityMagnitude(one.gain, one.delay, {c.Ac, c.Bc, c.Cc, c.Dc}, 0, p.frequencyRadPerPart);
    }
}

}  // namespace

bool samePlantSpec(const RunToRunPlantSpec& a, const RunToRunPlantSpec& b) {
    if (a.delay != b.delay || a.points.size() != b.points.size()) return false;
    for (std::size_t i = 0; i < a.points.size(); ++i) {
        const ControlPointSpec& p = a.points[i];
        const ControlPointSpec& q = b.points[i];
        if (p.xMm != q.xMm || p.gain != q.gain || p.measurementNoiseVarianceMm2 != q.measurementNoiseVarianceMm2 ||
            p.disturbance.describe() != q.disturbance.describe() ||
            p.disturbance.stationaryVarianceMm2() != q.disturbance.stationaryVarianceMm2())
            return false;
    }
    return true;
}

TuningPreview computeTuningPreview(const RunToRunSetup& setup, const TuningPreview* samePlant) {
    // With an identified model (setup.model) its gains, disturbances and delay z + lag are the plant analysed.
    const RunToRunPlantSpec spec = designPlantSpec(setup);
    const RunToRunPlant plant = buildRunToRunPlant(spec);
    validateWeights(plant, setup.weights);
    // Integral action lives in the LQG's design model only: the design is made on the plant with the
    // integrating state and its loop analysed on the true plant (as planShaftRun runs it).
    const RunToRunPlant designPlant =
        setup.integral.enabled ? buildRunToRunPlant(withIntegralAction(spec, setup.integral)) : plant;
    const LqgDesign design = designLqg(designPlant, setup.weights);
    TuningPreview p;
    const LinearControllerModel lqg = lqgControllerModel(designPlant, design);
    const SteadyStateVariances lqgVar = analyseSteadyState(plant, lqg);
    p.varianceAvailable = lqgVar.available;
    p.openMm2 = lqgVar.openMm2;
    p.lqgMm2 = lqgVar.closedMm2;
    p.lqgKEff = lqgVar.kEff;
    p.lqgMargins = lqgMargins(designPlant, design);
    p.stepLqg = stepResponse(plant, lqg.Ac, lqg.Bc, lqg.Cc, lqg.Dc, 0, kPreviewSteps);
    p.stepOpen.assign(static_cast<std::size_t>(kPreviewSteps), 1.0);
    for (int k = 1; k <= kPreviewFrequencies; ++k)
        p.frequencyRadPerPart.push_back(std::numbers::pi * k / kPreviewFrequencies);
    p.sensitivityLqg = lqgSensitivityMagnitude(designPlant, design, 0, p.frequencyRadPerPart);
    if (samePlant && samePlant->sensitivityEwma.size() == p.frequencyRadPerPart.size()) {
        p.ewmaWeight = samePlant->ewmaWeight;
        p.ewmaKEff = samePlant->ewmaKEff;
        p.ewmaMargins = samePlant->ewmaMargins;
        p.stepEwma = samePlant->stepEwma;
        p.sensitivityEwma = samePlant->sensitivityEwma;
    } else {
        computeEwmaPart(plant, setup, lqgVar.available, p);
    }
    return p;
}

}  // namespace tt::core
