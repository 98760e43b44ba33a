#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace tt::core {

/// One known load on the cross slide and the current difference it produced: a load of known
/// size (dynamometer, hydraulic jack with a gauge) pushes the tool towards the axis like the
/// cutting force, the cross feed dithers, and ΔI = (I_fwd − I_rev) / 2 is read at constant
/// velocity (DitherForceEstimator with k_p = 1 gives it as its force).
struct KpPoint {
    double loadN = 0.0;               ///< known radial load, N (towards the axis: positive)
    double currentDifferenceA = 0.0;  ///< (I_fwd − I_rev) / 2, A
};

/// The current-to-force gain from known loads (paper 001: k_p "found experimentally";
/// P = k_p (I_fwd − I_rev) / 2): least squares P = k_p ΔI + offset.
struct KpFit {
    double kpNPerA = 0.0;
    double offsetN = 0.0;  ///< force at ΔI = 0 (drive asymmetry); ideally near 0
    double r2 = 0.0;
    std::vector<double> residualsN;  ///< load − fitted, per point
    double rmsResidualN = 0.0;
};

/// Why known loads give no k_p.
enum class KpFitProblem {
    TooFewLoads,           ///< fewer than 3 points (count)
    TooFewDifferentLoads,  ///< fewer than 2 different loads
    NotANumber,            ///< a point is not a number (point)
    ConstantCurrent,       ///< ΔI is the same at every load: the current is not read
    FallsWithLoad,         ///< ΔI falls as the load grows (slope): the load acts the other way
};

/// A refused k_p fit: the kind and its data, with the reason in English for the CLI and logs.
class KpFitRefused : public std::invalid_argument {
public:
    KpFitRefused(KpFitProblem problem, const std::string& message, int count = 0, double slopeNPerA = 0.0)
        : std::invalid_argument(message), m_problem(problem), m_count(count), m_slope(slopeNPerA) {}
    KpFitProblem problem() const { return m_problem; }
    /// TooFewLoads: the points given; NotANumber: the point (from 1).
    int count() const { return m_count; }
    /// FallsWithLoad: the fitted slope, N/A.
    double slopeNPerA() const { return m_slope; }

private:
    KpFitProblem m_problem;
    int m_count;
    double m_slope;
};

/// The fewest known loads a k_p fit takes.
inline constexpr int kMinKpLoads = 3;

/// Fits k_p; throws KpFitRefused (a std::invalid_argument) when there are fewer than 3 points, fewer than 2
/// different loads, a non-finite value, or when ΔI does not grow with the load (k_p ≤ 0: the
/// load acts the other way or the current sign is reversed).
KpFit fitKp(const std::vector<KpPoint>& points);

}  // namespace tt::core
