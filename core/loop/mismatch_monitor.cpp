#include "core/loop/mismatch_monitor.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>

#include "core/common/text_format.h"

namespace tt::core {

const char* mismatchActionName(MismatchAction action) {
    switch (action) {
        case MismatchAction::Hold:
            return "hold";
        case MismatchAction::AlarmOnly:
            return "alarm";
        case MismatchAction::Adapt:
            return "adapt";
        case MismatchAction::Propose:
            return "propose";
    }
    return "adapt";
}

MismatchAction mismatchActionFromName(const std::string& name) {
    if (name == "hold") return MismatchAction::Hold;
    if (name == "alarm") return MismatchAction::AlarmOnly;
    if (name == "adapt") return MismatchAction::Adapt;
    if (name == "propose") return MismatchAction::Propose;
    throw std::invalid_argument("unknown mismatch action '" + name + "' (adapt, propose, hold, alarm)");
}

void MismatchMonitorConfig::validate() const {
    if (windowParts < 10 || windowParts > 1000)
        throw std::invalid_argument("the mismatch window must be 10 .. 1000 parts, got " + std::to_string(windowParts));
    if (minParts < 5 || minParts > windowParts)
        throw std::invalid_argument("the mismatch test needs 5 .. " + std::to_string(windowParts) +
                                    " parts before it starts, got " + std::to_string(minParts));
    if (!std::isfinite(falseAlarmProbability) || falseAlarmProbability < 1e-12 || falseAlarmProbability > 1e-2)
        throw std::invalid_argument("the mismatch false-alarm probability must be 1e-12 .. 0.01, got " +
                                    formatSignificant(falseAlarmProbability, 3));
    if (!std::isfinite(pointCorrelation) || pointCorrelation < 0.0 || pointCorrelation > kMaxPointCorrelation)
        throw std::invalid_argument("the points' expected correlation must be 0 .. " +
                                    formatSignificant(kMaxPointCorrelation, 3) + ", got " +
                                    formatSignificant(pointCorrelation, 3));
}

double correlationStatistic(const Eigen::Matrix2d& M, const Eigen::Vector2d& b) {
    const double ridge = 1e-12 * M.trace() + 1e-300;
    const Eigen::Matrix2d R = M + ridge * Eigen::Matrix2d::Identity();
    const double value = b.dot(R.ldlt().solve(b));
    return std::isfinite(value) && value > 0.0 ? value : 0.0;
}

double chernoffChiSquareFactor(int n, double alpha) {
    if (n < 1 || !(alpha > 0.0 && alpha < 1.0)) throw std::invalid_argument("Chernoff bound: n >= 1, 0 < alpha < 1");
    const double target = -2.0 * std::log(alpha) / n;  // c - 1 - ln c, increasing for c > 1
    double lo = 1.0;
    double hi = 2.0;
    while (hi - 1.0 - std::log(hi) < target)
        hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (mid - 1.0 - std::log(mid) < target ? lo : hi) = mid;
    }
    return hi;
}

MismatchMonitor::MismatchMonitor(const MismatchMonitorConfig& config) : m_config(config) {
    config.validate();
    m_correlationLimit = -2.0 * std::log(config.falseAlarmProbability);  // chi-square, 2 dof: P(T > x) = e^-x/2
}

double MismatchMonitor::varianceLimit(int n) const {
    return chernoffChiSquareFactor(n, m_config.falseAlarmProbability) * n;
}

void MismatchMonitor::reset() {
    m_applied.clear();
    m_window.clear();
    m_tripped = false;
}

void MismatchMonitor::partStarted(std::int64_t partNumber, const std::vector<double>& appliedMm) {
    m_applied[partNumber] = appliedMm;
    const std::int64_t keep = 2 * (m_config.windowParts + 16);
    while (!m_applied.empty() && m_applied.begin()->first < partNumber - keep)
        m_applied.erase(m_applied.begin());
}

std::optional<MismatchMonitor::PartTerms> MismatchMonitor::terms(const Innovation& innovation) const {
    // The corrections that acted on the part and on the one before: sent for part k - lag and k - lag - 1.
    const std::int64_t actedOn = innovation.partNumber - innovation.lagParts;
    const auto own = m_applied.find(actedOn);
    const auto before = m_applied.find(actedOn - 1);
    if (own == m_applied.end() || before == m_applied.end()) return std::nullopt;
    const std::size_t m = static_cast<std::size_t>(innovation.valueMm.size());
    if (own->second.size() != m || before->second.size() != m ||
        innovation.varianceMm2.size() != innovation.valueMm.size())
        return std::nullopt;
    PartTerms t;
    t.pointM.assign(m, Eigen::Matrix2d::Zero());
    t.pointB.assign(m, Eigen::Vector2d::Zero());
    t.pointNis.assign(m, 0.0);
    t.pointValues.assign(m, 0);
    std::vector<Eigen::Index> present;
    Eigen::VectorXd e(static_cast<Eigen::Index>(m));
    Eigen::MatrixXd X(static_cast<Eigen::Index>(m), 2);
    for (std::size_t i = 0; i < m; ++i) {
        const auto ii = static_cast<Eigen::Index>(i);
        const double nu = innovation.valueMm(ii);
        const double s = innovation.varianceMm2(ii);
        if (!std::isfinite(nu) || !std::isfinite(s) || s <= 0.0) continue;
        const double root = std::sqrt(s);
        e(ii) = nu / root;
        X.row(ii) << own->second[i] / root, before->second[i] / root;
        const Eigen::Vector2d x = X.row(ii).transpose();
        t.pointM[i] = x * x.transpose();
        t.pointB[i] = x * e(ii);
        t.pointNis[i] = e(ii) * e(ii);
        t.pointValues[i] = 1;
        present.push_back(ii);
    }
    if (present.empty()) return std::nullopt;
    t.values = static_cast<int>(present.size());
    const bool correlated = innovation.correlation.rows() == static_cast<Eigen::Index>(m) &&
                            innovation.correlation.cols() == static_cast<Eigen::Index>(m);
    if (!correlated) {
        for (std::size_t i = 0; i < m; ++i) {
            t.M += t.pointM[i];
            t.b += t.pointB[i];
            t.nis += t.pointNis[i];
        }
        if (present.size() == m) t.whitened = e;
        return t;
    }
    // Generalised least squares with the model's correlation R of the points present:
    // b = X' R^-1 e, M = X' R^-1 X, NIS = e' R^-1 e (chi-square with as many degrees of freedom as points).
    const auto k = static_cast<Eigen::Index>(present.size());
    Eigen::MatrixXd R(k, k);
    Eigen::VectorXd ep(k);
    Eigen::MatrixXd Xp(k, 2);
    for (Eigen::Index a = 0; a < k; ++a) {
        ep(a) = e(present[static_cast<std::size_t>(a)]);
        Xp.row(a) = X.row(present[static_cast<std::size_t>(a)]);
        for (Eigen::Index c = 0; c < k; ++c)
            R(a, c) =
                innovation.correlation(present[static_cast<std::size_t>(a)], present[static_cast<std::size_t>(c)]);
    }
    const Eigen::LLT<Eigen::MatrixXd> llt(R);
    if (llt.info() != Eigen::Success) return std::nullopt;
    const Eigen::VectorXd Re = llt.solve(ep);
    const Eigen::MatrixXd RX = llt.solve(Xp);
    if (!Re.allFinite() || !RX.allFinite()) return std::nullopt;
    t.b = Xp.transpose() * Re;
    t.M = Xp.transpose() * RX;
    t.nis = ep.dot(Re);
    if (k == static_cast<Eigen::Index>(m)) t.whitened = llt.matrixL().solve(ep);
    return t;
}

std::optional<MismatchFinding> MismatchMonitor::add(const Innovation& innovation) {
    if (!m_config.enabled || m_tripped) return std::nullopt;
    std::optional<PartTerms> t;
    if (innovation.correlation.size() == 0 && m_config.pointCorrelation > 0.0) {
        // The lathe's points move together: every pair correlated alike (a common share of the variation).
        Innovation expected = innovation;
        const Eigen::Index m = innovation.valueMm.size();
        expected.correlation = Eigen::MatrixXd::Constant(m, m, m_config.pointCorrelation);
        expected.correlation.diagonal().setOnes();
        t = terms(expected);
    } else {
        t = terms(innovation);
    }
    if (!t) return std::nullopt;
    m_window.push_back(std::move(*t));
    while (m_window.size() > static_cast<std::size_t>(m_config.windowParts))
        m_window.pop_front();
    if (m_window.size() < static_cast<std::size_t>(m_config.minParts)) return std::nullopt;
    std::optional<MismatchFinding> finding = test(innovation.partNumber);
    if (!finding) finding = independence(innovation.partNumber);
    if (finding) m_tripped = true;
    return finding;
}

std::optional<MismatchFinding> MismatchMonitor::independence(std::int64_t part) const {
    Eigen::MatrixXd S;
    int n = 0;
    for (const PartTerms& t : m_window) {
        if (t.whitened.size() < 2) continue;
        if (S.size() == 0) S = Eigen::MatrixXd::Zero(t.whitened.size(), t.whitened.size());
        if (t.whitened.size() != S.rows()) continue;
        S.noalias() += t.whitened * t.whitened.transpose();
        ++n;
    }
    if (n < m_config.minParts || S.size() == 0) return std::nullopt;
    const Eigen::Index m = S.rows();
    const Eigen::VectorXd scale = S.diagonal().cwiseSqrt().cwiseInverse();
    if (!scale.allFinite()) return std::nullopt;
    const Eigen::MatrixXd r = scale.asDiagonal() * S * scale.asDiagonal();
    double lm = 0.0;
    Eigen::VectorXd share = Eigen::VectorXd::Zero(m);
    for (Eigen::Index i = 0; i < m; ++i)
        for (Eigen::Index j = i + 1; j < m; ++j) {
            lm += n * r(i, j) * r(i, j);
            share(i) += r(i, j) * r(i, j);
            share(j) += r(i, j) * r(i, j);
        }
    const int dof = static_cast<int>(m * (m - 1) / 2);
    const double limit = chernoffChiSquareFactor(dof, m_config.falseAlarmProbability) * dof;
    if (!(lm > limit)) return std::nullopt;
    MismatchFinding f;
    f.partNumber = part;
    f.windowParts = static_cast<int>(m_window.size());
    f.test = MismatchTest::Independence;
    f.statistic = lm;
    f.threshold = limit;
    Eigen::Index worst = 0;
    share.maxCoeff(&worst);
    f.point = static_cast<int>(worst) + 1;
    return f;
}

std::optional<MismatchFinding> MismatchMonitor::test(std::int64_t part) const {
    const std::size_t m = m_window.back().pointM.size();
    Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    double nis = 0.0;
    int values = 0;
    std::vector<Eigen::Matrix2d> pointM(m, Eigen::Matrix2d::Zero());
    std::vector<Eigen::Vector2d> pointB(m, Eigen::Vector2d::Zero());
    std::vector<double> pointNis(m, 0.0);
    std::vector<int> pointValues(m, 0);
    for (const PartTerms& t : m_window) {
        M += t.M;
        b += t.b;
        nis += t.nis;
        values += t.values;
        for (std::size_t i = 0; i < m && i < t.pointM.size(); ++i) {
            pointM[i] += t.pointM[i];
            pointB[i] += t.pointB[i];
            pointNis[i] += t.pointNis[i];
            pointValues[i] += t.pointValues[i];
        }
    }
    MismatchFinding f;
    f.partNumber = part;
    f.windowParts = static_cast<int>(m_window.size());
    const double score = correlationStatistic(M, b);
    const double varianceLimitValue = varianceLimit(values);
    if (score > m_correlationLimit) {
        f.correlation = true;
        f.test = MismatchTest::Correlation;
        f.statistic = score;
        f.threshold = m_correlationLimit;
    } else if (nis > varianceLimitValue) {
        f.statistic = nis;
        f.threshold = varianceLimitValue;
    } else {
        return std::nullopt;
    }
    double worst = -1.0;
    for (std::size_t i = 0; i < m; ++i) {
        if (pointValues[i] == 0) continue;
        const double share = f.correlation ? correlationStatistic(pointM[i], pointB[i]) : pointNis[i] / pointValues[i];
        if (share > worst) {
            worst = share;
            f.point = static_cast<int>(i) + 1;
        }
    }
    return f;
}

}  // namespace tt::core
