#include "core/loop/mismatch_monitor.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>

#include "core/common/text_format.h"

namespace tt::core {

const char* mismatchActionName(MismatchAction action) {
    return action == MismatchAction::Hold ? "hold" : "alarm";
}

MismatchAction mismatchActionFromName(const std::string& name) {
    if (name == "hold") return MismatchAction::Hold;
    if (name == "alarm") return MismatchAction::AlarmOnly;
    throw std::invalid_argument("unknown mismatch action '" + name + "' (hold, alarm)");
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
    const auto own = m_applied.find(innovation.partNumber);
    const auto before = m_applied.find(innovation.partNumber - 1);
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
    for (std::size_t i = 0; i < m; ++i) {
        const auto ii = static_cast<Eigen::Index>(i);
        const double nu = innovation.valueMm(ii);
        const double s = innovation.varianceMm2(ii);
        if (!std::isfinite(nu) || !std::isfinite(s) || s <= 0.0) continue;
        const double root = std::sqrt(s);
        const double e = nu / root;
        const Eigen::Vector2d x(own->second[i] / root, before->second[i] / root);
        t.pointM[i] = x * x.transpose();
        t.pointB[i] = x * e;
        t.pointNis[i] = e * e;
        t.pointValues[i] = 1;
        t.M += t.pointM[i];
        t.b += t.pointB[i];
        t.nis += e * e;
        ++t.values;
    }
    if (t.values == 0) return std::nullopt;
    return t;
}

std::optional<MismatchFinding> MismatchMonitor::add(const Innovation& innovation) {
    if (!m_config.enabled || m_tripped) return std::nullopt;
    std::optional<PartTerms> t = terms(innovation);
    if (!t) return std::nullopt;
    m_window.push_back(std::move(*t));
    while (m_window.size() > static_cast<std::size_t>(m_config.windowParts))
        m_window.pop_front();
    if (m_window.size() < static_cast<std::size_t>(m_config.minParts)) return std::nullopt;
    std::optional<MismatchFinding> finding = test(innovation.partNumber);
    if (finding) m_tripped = true;
    return finding;
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
