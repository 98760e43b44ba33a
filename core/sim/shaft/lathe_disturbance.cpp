#include "core/sim/shaft/lathe_disturbance.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/linalg/stein.h"
#include "core/sim/shaft/lathe_random.h"

namespace tt::core {

namespace {

constexpr std::size_t kRecentParts = 512;

void requireFinite(const Eigen::MatrixXd& m, const char* what) {
    if (!m.allFinite()) throw std::invalid_argument(std::string("the disturbance matrix ") + what + " is not finite");
}

/// L with L L' = W for a positive semi-definite W (eigen-decomposition, so singular W works).
Eigen::MatrixXd covarianceFactor(const Eigen::MatrixXd& w) {
    if (w.rows() == 0) return w;
    if ((w - w.transpose()).cwiseAbs().maxCoeff() > 1e-12 * (1.0 + w.cwiseAbs().maxCoeff()))
        throw std::invalid_argument("the disturbance noise covariance W is not symmetric");
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(w);
    const double tolerance = 1e-12 * (1.0 + eig.eigenvalues().cwiseAbs().maxCoeff());
    if (eig.eigenvalues().minCoeff() < -tolerance)
        throw std::invalid_argument("the disturbance noise covariance W has a negative eigenvalue");
    return eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
}

}  // namespace

LatheDisturbanceModel LatheDisturbanceModel::none(int points) {
    LatheDisturbanceModel m;
    m.A = Eigen::MatrixXd::Zero(0, 0);
    m.G = Eigen::MatrixXd::Zero(0, 0);
    m.C = Eigen::MatrixXd::Zero(points, 0);
    m.H = Eigen::MatrixXd::Zero(points, 0);
    m.W = Eigen::MatrixXd::Zero(0, 0);
    return m;
}

LatheDisturbanceModel LatheDisturbanceModel::fromPointModels(const std::vector<DisturbanceModel>& points) {
    if (points.empty()) throw std::invalid_argument("the disturbance needs at least one control point");
    std::vector<DisturbanceRealisation> parts;
    for (const DisturbanceModel& p : points)
        parts.push_back(p.realise());
    DisturbanceRealisation stacked = stackRealisations(parts);
    LatheDisturbanceModel m;
    m.A = std::move(stacked.A);
    m.G = std::move(stacked.G);
    m.C = std::move(stacked.C);
    m.H = Eigen::MatrixXd::Zero(m.C.rows(), m.G.cols());
    m.W = std::move(stacked.W);
    return m;
}

LatheDisturbanceModel LatheDisturbanceModel::fromPointModels(const std::vector<DisturbanceModel>& points,
                                                             double commonShare) {
    if (!std::isfinite(commonShare) || commonShare < 0.0 || commonShare > 1.0)
        throw std::invalid_argument("the common share of the disturbance must lie in 0 .. 1");
    if (commonShare == 0.0) return fromPointModels(points);
    if (points.empty()) throw std::invalid_argument("the disturbance needs at least one control point");
    std::vector<DisturbanceRealisation> parts;
    Eigen::Index n = 0;
    for (const DisturbanceModel& p : points) {
        parts.push_back(p.realise());
        n += parts.back().A.rows();
        if (parts.back().W.rows() != parts.front().W.rows())
            throw std::invalid_argument(
                "a common share of the disturbance needs the same kind of model at every control point");
    }
    const Eigen::Index q = parts.front().W.rows();
    const auto count = static_cast<Eigen::Index>(points.size());
    // States: the common realisations of all points, then the independent ones. Noise: q shared unit
    // inputs, then q unit inputs per point.
    LatheDisturbanceModel m;
    m.A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    m.G = Eigen::MatrixXd::Zero(2 * n, q * (count + 1));
    m.C = Eigen::MatrixXd::Zero(count, 2 * n);
    m.H = Eigen::MatrixXd::Zero(count, q * (count + 1));
    m.W = Eigen::MatrixXd::Identity(q * (count + 1), q * (count + 1));
    const double common = std::sqrt(commonShare), own = std::sqrt(1.0 - commonShare);
    Eigen::Index s = 0;
    for (Eigen::Index i = 0; i < count; ++i) {
        const DisturbanceRealisation& r = parts[static_cast<std::size_t>(i)];
        const Eigen::Index ns = r.A.rows();
        const Eigen::MatrixXd scaledG = r.G * covarianceFactor(r.W);
        m.A.block(s, s, ns, ns) = r.A;
        m.A.block(n + s, n + s, ns, ns) = r.A;
        m.G.block(s, 0, ns, q) = common * scaledG;
        m.G.block(n + s, q * (i + 1), ns, q) = own * scaledG;
        m.C.block(i, s, 1, ns) = r.C;
        m.C.block(i, n + s, 1, ns) = r.C;
        s += ns;
    }
    return m;
}

LatheDisturbanceModel LatheDisturbanceModel::scaled(double factor) const {
    if (!std::isfinite(factor) || factor < 0.0) throw std::invalid_argument("a disturbance scale must be >= 0");
    LatheDisturbanceModel m = *this;
    m.C *= factor;
    m.H *= factor;
    return m;
}

LatheDisturbanceModel LatheDisturbanceModel::withWhiteNoise(const std::vector<double>& varianceMm2) const {
    const Eigen::Index points = pointCount();
    if (static_cast<Eigen::Index>(varianceMm2.size()) != points)
        throw std::invalid_argument("one white-noise variance per control point is needed");
    const Eigen::Index q = W.rows();
    LatheDisturbanceModel m = *this;
    m.G.conservativeResize(Eigen::NoChange, q + points);
    m.G.rightCols(points).setZero();
    m.H.conservativeResize(Eigen::NoChange, q + points);
    m.H.rightCols(points) = Eigen::MatrixXd::Identity(points, points);
    m.W = Eigen::MatrixXd::Zero(q + points, q + points);
    m.W.topLeftCorner(q, q) = W;
    for (Eigen::Index i = 0; i < points; ++i) {
        const double v = varianceMm2[static_cast<std::size_t>(i)];
        if (!std::isfinite(v) || v < 0.0)
            throw std::invalid_argument("a white-noise variance is negative or not finite");
        m.W(q + i, q + i) = v;
    }
    return m;
}

LatheDisturbance::LatheDisturbance(LatheDisturbanceModel model, std::uint64_t seed)
    : m_model(std::move(model)), m_seed(seed) {
    const auto n = m_model.A.rows();
    const auto q = m_model.W.rows();
    if (m_model.A.cols() != n || m_model.G.rows() != n || m_model.G.cols() != q || m_model.C.cols() != n ||
        m_model.H.cols() != q || m_model.C.rows() != m_model.H.rows() || m_model.W.cols() != q)
        throw std::invalid_argument("the disturbance model matrices A, G, C, H, W have inconsistent sizes");
    if (m_model.H.rows() < 1) throw std::invalid_argument("the disturbance model needs at least one control point");
    requireFinite(m_model.A, "A");
    requireFinite(m_model.G, "G");
    requireFinite(m_model.C, "C");
    requireFinite(m_model.H, "H");
    requireFinite(m_model.W, "W");
    m_noiseFactor = covarianceFactor(m_model.W);
    m_stationary =
        n == 0 || Eigen::EigenSolver<Eigen::MatrixXd>(m_model.A).eigenvalues().cwiseAbs().maxCoeff() < 1.0 - 1e-9;
    restart();
}

Eigen::VectorXd LatheDisturbance::stationaryVarianceMm2() const {
    if (!m_stationary)
        throw std::logic_error("this disturbance model has no stationary variance (pole on the unit circle)");
    const Eigen::MatrixXd hw = m_model.H * m_noiseFactor;
    Eigen::MatrixXd cov = hw * hw.transpose();
    if (m_model.A.rows() > 0) {
        const Eigen::MatrixXd gw = m_model.G * m_noiseFactor;
        cov += m_model.C * solveDiscreteLyapunov(m_model.A, gw * gw.transpose()) * m_model.C.transpose();
    }
    return cov.diagonal();
}

void LatheDisturbance::restart() {
    const auto n = m_model.A.rows();
    m_state = Eigen::VectorXd::Zero(n);
    if (m_stationary && n > 0) {
        const Eigen::MatrixXd gw = m_model.G * m_noiseFactor;
        Eigen::MatrixXd p = solveDiscreteLyapunov(m_model.A, gw * gw.transpose());
        p = 0.5 * (p + p.transpose());
        const Eigen::MatrixXd factor = covarianceFactor(p);
        NormalStream normals = latheNormals(m_seed, LatheStream::InitialState);
        Eigen::VectorXd e(n);
        for (Eigen::Index i = 0; i < n; ++i)
            e(i) = normals.next();
        m_state = factor * e;
    }
    m_nextPart = 1;
    m_recent.clear();
}

void LatheDisturbance::advance() {
    NormalStream normals = latheNormals(m_seed, LatheStream::Disturbance, static_cast<std::uint64_t>(m_nextPart));
    Eigen::VectorXd e(m_noiseFactor.cols());
    for (Eigen::Index i = 0; i < e.size(); ++i)
        e(i) = normals.next();
    const Eigen::VectorXd w = m_noiseFactor * e;
    Eigen::VectorXd f = m_model.H * w;
    if (m_model.A.rows() > 0) {
        f += m_model.C * m_state;
        m_state = m_model.A * m_state + m_model.G * w;
    }
    m_recent.push_back(std::move(f));
    if (m_recent.size() > kRecentParts) m_recent.pop_front();
    ++m_nextPart;
}

Eigen::VectorXd LatheDisturbance::diameterMm(std::int64_t partNumber) {
    if (partNumber < 1) throw std::invalid_argument("part numbers start at 1 (got " + std::to_string(partNumber) + ")");
    const std::int64_t oldest = m_nextPart - static_cast<std::int64_t>(m_recent.size());
    if (partNumber < oldest) restart();
    while (m_nextPart <= partNumber)
        advance();
    const std::int64_t first = m_nextPart - static_cast<std::int64_t>(m_recent.size());
    return m_recent[static_cast<std::size_t>(partNumber - first)];
}

}  // namespace tt::core
