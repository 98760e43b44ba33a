#pragma once

#include <deque>
#include <string>
#include <vector>

namespace tt::core {

/// When the corrective pulse's network is retrained (paper 002: "the difference between the computed
/// error and the expectation of the real error over several corrections, misses removed").
struct DriftMonitorSettings {
    int windowCorners = 10;            ///< N: the last N corners are compared
    double thresholdFraction = 0.015;  ///< retrain when |mean real − mean predicted| > this × mean predicted
    double outlierMads = 3.0;  ///< a corner is a miss when its residual is this many scaled MADs from the median
};

/// Throws std::invalid_argument when the window is outside 3 .. 1000, the threshold outside 0.001 .. 10 or
/// the outlier limit outside 1 .. 20.
void validateDriftMonitor(const DriftMonitorSettings& settings);

/// The monitor's verdict over the window.
struct DriftCheck {
    int corners = 0;                  ///< corners in the window
    int outliers = 0;                 ///< removed as misses
    double meanPredicted = 0.0;       ///< over the kept corners, mm
    double meanReal = 0.0;            ///< over the kept corners, mm
    double differenceFraction = 0.0;  ///< (meanReal − meanPredicted) / meanPredicted
    bool retrain = false;             ///< window full and |difference| above the threshold
    std::string reason;               ///< what was found, in words (when retrain)
};

/// Median of `values` (not empty); the mean of the two middle values for an even count.
double median(std::vector<double> values);

/// Indices of the misses among `residuals`: |r − median| > k · 1.4826 · MAD (MAD = median |r − median|,
/// 1.4826 makes it the standard deviation for normal data; Hampel's rule). None when MAD is 0.
std::vector<int> hampelOutliers(const std::vector<double>& residuals, double k);

/// Compares the cost the controller predicted for each corner with the cost measured on the machine
/// over a sliding window of corners and says when the difference calls for retraining.
class CornerDriftMonitor {
public:
    explicit CornerDriftMonitor(const DriftMonitorSettings& settings);

    /// Adds a corner: the cost U the controller predicted and the one measured, mm (≥ 0; non-finite
    /// values throw).
    void add(double predictedMm, double realMm);
    /// The verdict over the corners in the window.
    DriftCheck check() const;
    /// Whether corner `i` of the window (0 = oldest) is a miss.
    std::vector<bool> outlierFlags() const;
    /// Index (0 = oldest) of the first corner after the change in the window: the relative residuals
    /// (real − predicted) / predicted are split into an earlier and a later level where the squared
    /// deviations from the two means are least, with at least `minAfter` corners after the split
    /// (two-segment least squares; before Hampel's rule, which would take the first corners after a
    /// sudden change for misses). What the machine is now is what the later corners show. 0 when the
    /// window has fewer than minAfter + 1 corners.
    int changeStart(int minAfter) const;
    /// Whether corner `i` of the window is a miss among the corners from `from` on, by Hampel's rule on
    /// their relative residuals (false for the corners before `from`).
    std::vector<bool> outlierFlagsFrom(int from) const;
    /// Forgets the window (after a retraining).
    void clear();
    /// Corners in the window.
    int size() const { return static_cast<int>(m_predicted.size()); }
    const DriftMonitorSettings& settings() const { return m_settings; }

private:
    std::vector<double> relativeResiduals() const;

    DriftMonitorSettings m_settings;
    std::deque<double> m_predicted;
    std::deque<double> m_real;
};

}  // namespace tt::core
