#include "core/control/lqg_design.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/control/kalman_filter.h"
#include "core/control/lq_regulator.h"
#include "core/linalg/stein.h"

namespace tt::core {

namespace {

using Index = Eigen::Index;

Eigen::MatrixXd select(const Eigen::MatrixXd& m, const std::vector<Index>& rows, const std::vector<Index>& cols) {
    Eigen::MatrixXd out(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t c = 0; c < cols.size(); ++c)
            out(static_cast<Index>(r), static_cast<Index>(c)) = m(rows[r], cols[c]);
    return out;
}

std::vector<Index> toIndex(const std::vector<int>& v) {
    return {v.begin(), v.end()};
}

/// Groups of points coupled by off-diagonal entries of R1, R2 or V (union-find).
std::vector<std::vector<int>> coupledGroups(const RunToRunPlant& plant, const LqgWeights& w) {
    const int m = plant.pointCount();
    std::vector<int> parent(static_cast<std::size_t>(m));
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int i) {
        while (parent[static_cast<std::size_t>(i)] != i)
            i = parent[static_cast<std::size_t>(i)] =
                parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
        return i;
    };
    for (int i = 0; i < m; ++i)
        for (int j = i + 1; j < m; ++j)
            if (w.R1(i, j) != 0.0 || w.R2(i, j) != 0.0 || plant.V(i, j) != 0.0 || plant.D(i, j) != 0.0 ||
                plant.D(j, i) != 0.0)
                parent[static_cast<std::size_t>(find(j))] = find(i);
    std::vector<std::vector<int>> groups;
    std::vector<int> groupOf(static_cast<std::size_t>(m), -1);
    for (int i = 0; i < m; ++i) {
        const int root = find(i);
        if (groupOf[static_cast<std::size_t>(root)] < 0) {
            groupOf[static_cast<std::size_t>(root)] = static_cast<int>(groups.size());
            groups.emplace_back();
        }
        groups[static_cast<std::size_t>(groupOf[static_cast<std::size_t>(root)])].push_back(i);
    }
    return groups;
}

struct BlockResult {
    LqgBlock block;
    Eigen::MatrixXd P;  // block order
    int iterations = 0;
    double residual = 0.0;
};

BlockResult designBlock(const RunToRunPlant& plant, const LqgWeights& w, const std::vector<int>& points) {
    std::vector<Index> delayStates, distStates, noise;
    for (int i : points) {
        const auto& L = plant.layout[static_cast<std::size_t>(i)];
        for (Index j = 0; j < L.delayCount; ++j)
            delayStates.push_back(L.delayStart + j);
        for (Index j = 0; j < L.disturbanceCount; ++j)
            distStates.push_back(L.disturbanceStart + j);
        for (Index j = 0; j < L.noiseCount; ++j)
            noise.push_back(L.noiseStart + j);
    }
    const std::vector<Index> pts = toIndex(points);
    const Eigen::MatrixXd Ap = select(plant.A, delayStates, delayStates);
    const Eigen::MatrixXd Bp = select(plant.B, delayStates, pts);
    const Eigen::MatrixXd Cp = select(plant.C, pts, delayStates);
    const Eigen::MatrixXd Ad = select(plant.A, distStates, distStates);
    const Eigen::MatrixXd Gd = select(plant.G, distStates, noise);
    const Eigen::MatrixXd Cd = select(plant.C, pts, distStates);
    const Eigen::MatrixXd Wd = select(plant.W, noise, noise);
    const Eigen::MatrixXd D = select(plant.D, pts, pts);
    const Eigen::MatrixXd V = select(plant.V, pts, pts);
    const Eigen::MatrixXd R1 = select(w.R1, pts, pts);
    const Eigen::MatrixXd R2 = select(w.R2, pts, pts);

    // LQ on the delay chains (lqry), then the disturbance feed-forward from the Stein equation
    // P_pd = (A_p - B_p K_p)' P_pd A_d + (C_p - D K_p)' R1 C_d.
    const LqRegulator lq = lqry(Ap, Bp, Cp, D, R1, R2);
    const Eigen::MatrixXd Acl = Ap - Bp * lq.K;
    const Eigen::MatrixXd Ppd = solveStein(Acl.transpose(), Ad, (Cp - D * lq.K).transpose() * R1 * Cd);
    const Eigen::MatrixXd S = R2 + D.transpose() * R1 * D + Bp.transpose() * lq.S * Bp;
    const Eigen::MatrixXd Kd =
        Eigen::LDLT<Eigen::MatrixXd>(S).solve(Bp.transpose() * Ppd * Ad + D.transpose() * R1 * Cd);

    // Kalman filter on the disturbance only: the delay chains hold known past inputs (no noise).
    const KalmanDesign kf = designKalman(Ad, Cd, Gd, Wd, V);

    const Index np = Ap.rows();
    const Index nd = Ad.rows();
    const Index nb = np + nd;
    BlockResult r;
    LqgBlock& b = r.block;
    b.points = points;
    b.states = delayStates;
    b.states.insert(b.states.end(), distStates.begin(), distStates.end());
    b.A = Eigen::MatrixXd::Zero(nb, nb);
    b.A.topLeftCorner(np, np) = Ap;
    b.A.bottomRightCorner(nd, nd) = Ad;
    b.B = Eigen::MatrixXd::Zero(nb, Bp.cols());
    b.B.topRows(np) = Bp;
    b.C.resize(Cp.rows(), nb);
    b.C << Cp, Cd;
    b.K.resize(lq.K.rows(), nb);
    b.K << lq.K, Kd;
    b.L = Eigen::MatrixXd::Zero(nb, Cp.rows());
    b.L.bottomRows(nd) = kf.L;
    r.P = Eigen::MatrixXd::Zero(nb, nb);
    r.P.bottomRightCorner(nd, nd) = kf.P;
    b.P = r.P;
    b.Q = Eigen::MatrixXd::Zero(nb, nb);
    b.Q.bottomRightCorner(nd, nd) = Gd * Wd * Gd.transpose();
    b.V = V;
    b.P0 = Eigen::MatrixXd::Zero(nb, nb);
    Index offset = np;
    for (int i : points) {
        const Eigen::MatrixXd prior =
            plant.disturbances[static_cast<std::size_t>(i)].priorCovariance(kRandomWalkPriorMm2);
        b.P0.block(offset, offset, prior.rows(), prior.cols()) = prior;
        offset += prior.rows();
    }
    r.iterations = lq.iterations + kf.iterations;
    r.residual = std::max(lq.relativeResidual, kf.relativeResidual);
    return r;
}

void scatter(const LqgBlock& b, const Eigen::MatrixXd& Pb, LqgDesign& d) {
    for (std::size_t i = 0; i < b.states.size(); ++i) {
        for (std::size_t p = 0; p < b.points.size(); ++p) {
            d.K(b.points[p], b.states[i]) = b.K(static_cast<Index>(p), static_cast<Index>(i));
            d.L(b.states[i], b.points[p]) = b.L(static_cast<Index>(i), static_cast<Index>(p));
        }
        for (std::size_t j = 0; j < b.states.size(); ++j)
            d.P(b.states[i], b.states[j]) = Pb(static_cast<Index>(i), static_cast<Index>(j));
    }
}

}  // namespace

void validateWeights(const RunToRunPlant& plant, const LqgWeights& w) {
    const Index m = plant.pointCount();
    auto check = [m](const Eigen::MatrixXd& R, const char* name) {
        if (R.rows() != m || R.cols() != m)
            throw std::invalid_argument(std::string("weights: ") + name + " must be " + std::to_string(m) + "x" +
                                        std::to_string(m) + " (one row per control point)");
        if (!R.allFinite()) throw std::invalid_argument(std::string("weights: ") + name + " has a NaN or Inf");
        if ((R - R.transpose()).norm() > 1e-12 * std::max(1.0, R.norm()))
            throw std::invalid_argument(std::string("weights: ") + name + " must be symmetric");
    };
    check(w.R1, "R1");
    check(w.R2, "R2");
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> e1(w.R1, Eigen::EigenvaluesOnly);
    if (e1.eigenvalues().minCoeff() < -1e-12 * std::max(1.0, w.R1.norm()))
        throw std::invalid_argument("weights: R1 (output weight) must not be negative");
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> e2(w.R2, Eigen::EigenvaluesOnly);
    if (e2.eigenvalues().minCoeff() <= 0.0)
        throw std::invalid_argument("weights: R2 (correction weight) must be positive at every point");
}

LqgDesign designLqg(const RunToRunPlant& plant, const LqgWeights& weights) {
    validateWeights(plant, weights);
    const Index n = plant.stateCount();
    const Index m = plant.pointCount();
    LqgDesign d;
    d.K = Eigen::MatrixXd::Zero(m, n);
    d.L = Eigen::MatrixXd::Zero(n, m);
    d.P = Eigen::MatrixXd::Zero(n, n);
    for (const std::vector<int>& group : coupledGroups(plant, weights)) {
        BlockResult r = designBlock(plant, weights, group);
        scatter(r.block, r.P, d);
        d.riccatiIterations += r.iterations;
        d.maxRelativeResidual = std::max(d.maxRelativeResidual, r.residual);
        d.blocks.push_back(std::move(r.block));
    }
    return d;
}

LqgDesign designLqgDense(const RunToRunPlant& plant, const LqgWeights& weights) {
    validateWeights(plant, weights);
    const LqRegulator lq = lqry(plant.A, plant.B, plant.C, plant.D, weights.R1, weights.R2);
    const KalmanDesign kf = designKalman(plant.A, plant.C, plant.G, plant.W, plant.V);
    LqgDesign d;
    d.K = lq.K;
    d.L = kf.L;
    d.P = kf.P;
    d.riccatiIterations = lq.iterations + kf.iterations;
    d.maxRelativeResidual = std::max(lq.relativeResidual, kf.relativeResidual);
    LqgBlock b;
    b.points.resize(static_cast<std::size_t>(plant.pointCount()));
    std::iota(b.points.begin(), b.points.end(), 0);
    b.states.resize(static_cast<std::size_t>(plant.stateCount()));
    std::iota(b.states.begin(), b.states.end(), Index{0});
    b.A = plant.A;
    b.B = plant.B;
    b.C = plant.C;
    b.K = d.K;
    b.L = d.L;
    b.P = kf.P;
    b.Q = plant.G * plant.W * plant.G.transpose();
    b.V = plant.V;
    b.P0 = Eigen::MatrixXd::Zero(plant.stateCount(), plant.stateCount());
    for (int i = 0; i < plant.pointCount(); ++i) {
        const auto& L = plant.layout[static_cast<std::size_t>(i)];
        b.P0.block(L.disturbanceStart, L.disturbanceStart, L.disturbanceCount, L.disturbanceCount) =
            plant.disturbances[static_cast<std::size_t>(i)].priorCovariance(kRandomWalkPriorMm2);
    }
    d.blocks.push_back(std::move(b));
    return d;
}

}  // namespace tt::core
