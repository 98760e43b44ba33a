#include "core/control/corner_drift_monitor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

constexpr double kMadToSigma = 1.4826;

}  // namespace

void validateDriftMonitor(const DriftMonitorSettings& s) {
    if (s.windowCorners < 3 || s.windowCorners > 1000)
        throw std::invalid_argument("drift window " + std::to_string(s.windowCorners) +
                                    " corners is outside 3 .. 1000");
    if (!(s.thresholdFraction >= 0.001 && s.thresholdFraction <= 10.0))
        throw std::invalid_argument("drift threshold " + formatSignificant(s.thresholdFraction * 100.0, 4) +
                                    " % is outside 0.1 .. 1000 %");
    if (!(s.outlierMads >= 1.0 && s.outlierMads <= 20.0))
        throw std::invalid_argument("outlier limit " + formatSignificant(s.outlierMads, 4) +
                                    " MADs is outside 1 .. 20");
}

double median(std::vector<double> values) {
    if (values.empty()) throw std::invalid_argument("the median of no values");
    const std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
    const double upper = values[mid];
    if (values.size() % 2 == 1) return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
    return 0.5 * (lower + upper);
}

std::vector<int> hampelOutliers(const std::vector<double>& residuals, double k) {
    std::vector<int> out;
    if (residuals.empty()) return out;
    const double m = median(residuals);
    std::vector<double> deviations;
    deviations.reserve(residuals.size());
    for (double r : residuals)
        deviations.push_back(std::abs(r - m));
    const double mad = median(deviations);
    if (mad <= 0.0) return out;
    for (std::size_t i = 0; i < residuals.size(); ++i)
        if (deviations[i] > k * kMadToSigma * mad) out.push_back(static_cast<int>(i));
    return out;
}

CornerDriftMonitor::CornerDriftMonitor(const DriftMonitorSettings& settings) : m_settings(settings) {
    validateDriftMonitor(settings);
}

void CornerDriftMonitor::add(double predicted, double real) {
    if (!std::isfinite(predicted) || !std::isfinite(real) || predicted < 0.0 || real < 0.0)
        throw std::invalid_argument("a corner's predicted and real costs must be finite and not negative");
    m_predicted.push_back(predicted);
    m_real.push_back(real);
    while (size() > m_settings.windowCorners) {
        m_predicted.pop_front();
        m_real.pop_front();
    }
}

std::vector<bool> CornerDriftMonitor::outlierFlags() const {
    std::vector<double> residuals;
    for (int i = 0; i < size(); ++i)
        residuals.push_back(m_real[static_cast<std::size_t>(i)] - m_predicted[static_cast<std::size_t>(i)]);
    std::vector<bool> flags(residuals.size(), false);
    for (int i : hampelOutliers(residuals, m_settings.outlierMads))
        flags[static_cast<std::size_t>(i)] = true;
    return flags;
}

DriftCheck CornerDriftMonitor::check() const {
    DriftCheck c;
    c.corners = size();
    if (c.corners == 0) return c;
    const std::vector<bool> flags = outlierFlags();
    int kept = 0;
    for (int i = 0; i < c.corners; ++i) {
        if (flags[static_cast<std::size_t>(i)]) {
            ++c.outliers;
            continue;
        }
        c.meanPredicted += m_predicted[static_cast<std::size_t>(i)];
        c.meanReal += m_real[static_cast<std::size_t>(i)];
        ++kept;
    }
    c.meanPredicted /= kept;
    c.meanReal /= kept;
    c.differenceFraction = c.meanPredicted > 0.0 ? (c.meanReal - c.meanPredicted) / c.meanPredicted : 0.0;
    c.retrain = c.corners >= m_settings.windowCorners && std::abs(c.differenceFraction) > m_settings.thresholdFraction;
    if (c.retrain)
        c.reason = "mean real cost " + formatSignificant(c.meanReal * 1e3, 3) + " µm over the last " +
                   std::to_string(c.corners) + " corners (" + std::to_string(c.outliers) +
                   (c.outliers == 1 ? " miss" : " misses") + " removed) is " +
                   formatFixed(std::abs(c.differenceFraction) * 100.0, 1) +
                   (c.differenceFraction > 0.0 ? " % above" : " % below") + " the predicted " +
                   formatSignificant(c.meanPredicted * 1e3, 3) + " µm (threshold " +
                   formatFixed(m_settings.thresholdFraction * 100.0, 1) + " %)";
    return c;
}

std::vector<double> CornerDriftMonitor::relativeResiduals() const {
    std::vector<double> r;
    for (std::size_t i = 0; i < m_predicted.size(); ++i) {
        const double predicted = std::max(m_predicted[i], 1e-12);
        r.push_back((m_real[i] - predicted) / predicted);
    }
    return r;
}

int CornerDriftMonitor::changeStart(int minAfter) const {
    const std::vector<double> r = relativeResiduals();
    const int n = static_cast<int>(r.size());
    if (minAfter < 1 || n < minAfter + 1) return 0;
    // Squared deviations from the mean of r[a, b).
    const auto sse = [&r](int a, int b) {
        double mean = 0.0;
        for (int i = a; i < b; ++i)
            mean += r[static_cast<std::size_t>(i)];
        mean /= std::max(b - a, 1);
        double sum = 0.0;
        for (int i = a; i < b; ++i)
            sum += (r[static_cast<std::size_t>(i)] - mean) * (r[static_cast<std::size_t>(i)] - mean);
        return sum;
    };
    int best = 1;
    double bestSse = sse(0, 1) + sse(1, n);
    for (int split = 2; split <= n - minAfter; ++split) {
        const double v = sse(0, split) + sse(split, n);
        if (v < bestSse) {
            bestSse = v;
            best = split;
        }
    }
    return best;
}

std::vector<bool> CornerDriftMonitor::outlierFlagsFrom(int from) const {
    const std::vector<double> r = relativeResiduals();
    std::vector<bool> flags(r.size(), false);
    if (from < 0 || from >= static_cast<int>(r.size())) return flags;
    const std::vector<double> later(r.begin() + from, r.end());
    for (int i : hampelOutliers(later, m_settings.outlierMads))
        flags[static_cast<std::size_t>(from + i)] = true;
    return flags;
}

void CornerDriftMonitor::clear() {
    m_predicted.clear();
    m_real.clear();
}

}  // namespace tt::core
