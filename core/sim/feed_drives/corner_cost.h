#pragma once

namespace tt::core {

/// The control interval and the weights of the paper 002 cost U = k1·e_max + k2·e_mean (eq. 1). The
/// interval is the part of the tool's trajectory between the coordinates Zn = Z1 − Vz1·t1 (eq. 2) and
/// Zk = Z1 + Vz2·t2 (eq. 3): from t1 of travel before the tool reaches the corner Z1 to t2 of travel
/// after it (the tool lags the programmed point by the following error, so this is later than the
/// programmed velocity change).
struct CornerCostSettings {
    double beforeS = 0.035;   ///< t1 (paper: ok1 = 0.035 s)
    double afterS = 0.15;     ///< t2 (paper: ok2 = 0.15 s)
    double maxWeight = 0.25;  ///< k1, weight of the largest contour error
    double meanWeight = 1.0;  ///< k2, weight of the mean contour error
};

/// Throws std::invalid_argument when t1 or t2 is outside 1 ms .. 1 s or a weight outside 0 .. 100
/// (and not both zero).
void validateCornerCost(const CornerCostSettings& settings);

/// The contour error over the control interval and its cost.
struct CornerCost {
    double maxErrorMm = 0.0;   ///< e_max, mm
    double meanErrorMm = 0.0;  ///< e_mean (the paper's "mean trajectory error"), mm
    double cost = 0.0;         ///< U = k1 e_max + k2 e_mean, mm
};

/// Accumulates the contour error sampled at a constant time step while the tool is in the interval.
class CornerCostAccumulator {
public:
    /// The interval [Zn, Zk] in mm (the corner at Z1 = 0) and the weights k1, k2 of `settings`.
    CornerCostAccumulator(const CornerCostSettings& settings, double zStartMm, double zEndMm)
        : m_settings(settings), m_zStartMm(zStartMm), m_zEndMm(zEndMm) {}
    /// Adds the error of a sample with the tool at `zMm`, when Zn ≤ zMm ≤ Zk.
    void add(double zMm, double errorMm);
    /// The cost over the samples added (all zero when none).
    CornerCost result() const;

private:
    CornerCostSettings m_settings;
    double m_zStartMm;
    double m_zEndMm;
    double m_max = 0.0;
    double m_sum = 0.0;
    long m_count = 0;
};

}  // namespace tt::core
