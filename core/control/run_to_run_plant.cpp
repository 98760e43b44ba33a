#include "core/control/run_to_run_plant.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {

std::invalid_argument pointError(std::size_t index, const std::string& why) {
    return std::invalid_argument("control point " + std::to_string(index + 1) + ": " + why);
}

void validate(const RunToRunPlantSpec& spec) {
    const std::size_t n = spec.points.size();
    if (n < 1 || n > static_cast<std::size_t>(kMaxControlPoints))
        throw std::invalid_argument("the number of control points must be 1 .. " + std::to_string(kMaxControlPoints) +
                                    ", got " + std::to_string(n));
    if (spec.delay < 1 || spec.delay > kMaxDelay)
        throw std::invalid_argument("the delay must be 1 .. " + std::to_string(kMaxDelay) + " parts, got " +
                                    std::to_string(spec.delay));
    for (std::size_t i = 0; i < n; ++i) {
        const ControlPointSpec& p = spec.points[i];
        if (!std::isfinite(p.xMm) || p.xMm < 0.0) throw pointError(i, "the position must be a number >= 0 mm");
        if (!std::isfinite(p.gain) || p.gain <= 0.0 || p.gain > 100.0)
            throw pointError(i, "the gain k_i must be in (0, 100] (2 = radial move to diameter)");
        if (!std::isfinite(p.measurementNoiseVarianceMm2) || p.measurementNoiseVarianceMm2 <= 0.0)
            throw pointError(i, "the gauge noise variance must be > 0 mm^2 (the paper's micrometer: 2.5e-7 mm^2)");
    }
}

}  // namespace

RunToRunPlant buildRunToRunPlant(const RunToRunPlantSpec& spec) {
    validate(spec);
    const Eigen::Index m = static_cast<Eigen::Index>(spec.points.size());
    const Eigen::Index z = spec.delay;
    std::vector<DisturbanceRealisation> dist;
    for (const ControlPointSpec& p : spec.points)
        dist.push_back(p.disturbance.realise());
    const DisturbanceRealisation stacked = stackRealisations(dist);
    const Eigen::Index disturbanceStates = stacked.A.rows();
    const Eigen::Index noiseInputs = stacked.G.cols();
    const Eigen::Index n = m * z + disturbanceStates;

    RunToRunPlant plant;
    plant.delay = spec.delay;
    plant.A = Eigen::MatrixXd::Zero(n, n);
    plant.B = Eigen::MatrixXd::Zero(n, m);
    plant.C = Eigen::MatrixXd::Zero(m, n);
    plant.D = Eigen::MatrixXd::Zero(m, m);
    plant.G = Eigen::MatrixXd::Zero(n, noiseInputs);
    // Disturbance: s(k+1) = A_d s + G_d w, added to the output; the points' models stacked after the
    // delay chains.
    plant.A.bottomRightCorner(disturbanceStates, disturbanceStates) = stacked.A;
    plant.G.bottomRows(disturbanceStates) = stacked.G;
    plant.C.rightCols(disturbanceStates) = stacked.C;
    plant.W = stacked.W;
    plant.V = Eigen::MatrixXd::Zero(m, m);
    plant.gain = Eigen::VectorXd(m);
    plant.layout.resize(static_cast<std::size_t>(m));

    Eigen::Index s = m * z;
    Eigen::Index w = 0;
    for (Eigen::Index i = 0; i < m; ++i) {
        const ControlPointSpec& p = spec.points[static_cast<std::size_t>(i)];
        const DisturbanceRealisation& d = dist[static_cast<std::size_t>(i)];
        RunToRunPlant::PointLayout& L = plant.layout[static_cast<std::size_t>(i)];
        // Delay chain: x1(k+1) = u(k), x_j(k+1) = x_{j-1}(k); y = k_i x_z.
        L.delayStart = i * z;
        L.delayCount = z;
        plant.B(L.delayStart, i) = 1.0;
        for (Eigen::Index j = 1; j < z; ++j)
            plant.A(L.delayStart + j, L.delayStart + j - 1) = 1.0;
        plant.C(i, L.delayStart + z - 1) = p.gain;
        L.disturbanceStart = s;
        L.disturbanceCount = d.A.rows();
        L.noiseStart = w;
        L.noiseCount = d.G.cols();
        plant.V(i, i) = p.measurementNoiseVarianceMm2;
        plant.gain(i) = p.gain;
        plant.xMm.push_back(p.xMm);
        plant.disturbances.push_back(p.disturbance);
        s += d.A.rows();
        w += d.G.cols();
    }
    return plant;
}

std::vector<double> paperControlPointsMm(double lengthMm) {
    if (!std::isfinite(lengthMm) || lengthMm <= 100.0)
        throw std::invalid_argument("the paper's control points need a part longer than 100 mm");
    return {0.0, 27.5, lengthMm / 2.0, lengthMm - 62.5, lengthMm};
}

}  // namespace tt::core
