#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/control/run_to_run_controller.h"

namespace tt::core {

/// The alarm kind of a detected model mismatch, stored with the run.
inline constexpr const char* kModelMismatchAlarm = "model-mismatch";
/// The alarm kind of what the adaptive loop did (fallback, adaptation, proposal, refusals), stored with the run.
inline constexpr const char* kAdaptationAlarm = "adaptation";

/// What the loop does when the plant no longer matches the controller's model.
enum class MismatchAction {
    Hold,       ///< alarm, then the CNC keeps the last correction until the run is restarted
    AlarmOnly,  ///< alarm, the controller goes on
    /// alarm, switch bumplessly to the robust fallback at the next part, identify the plant from the run's history
    /// and apply a design for it whose margins hold (the monitor then restarts on the new model)
    Adapt,
    /// as Adapt, but the new design is only proposed (recorded; an engineer applies it); the fallback goes on
    Propose
};

/// "hold", "alarm", "adapt", "propose"; and back (throws std::invalid_argument for another name).
const char* mismatchActionName(MismatchAction action);
MismatchAction mismatchActionFromName(const std::string& name);

/// Settings of the loop's model-mismatch monitor.
struct MismatchMonitorConfig {
    bool enabled = true;
    int windowParts = 50;  ///< innovations of the last this many parts are tested (10 .. 1000)
    int minParts = 10;     ///< no test before this many parts are in the window (5 .. windowParts)
    /// Probability that one test alarms although the plant matches the model (1e-12 .. 1e-2). Two tests
    /// per part, so the expected false alarms of a matching plant are at most 2 x this per part.
    double falseAlarmProbability = 1e-6;
    MismatchAction action = MismatchAction::Adapt;
    /// The correlation of the points' innovations the monitor expects when the controller's model gives none
    /// (0: independent points, the preset's model; at most kMaxPointCorrelation): a lathe whose points move together
    /// (a tool offset moves the whole shaft). An identified model's own correlation takes precedence.
    double pointCorrelation = 0.0;

    /// Throws std::invalid_argument naming the value and its range.
    void validate() const;
};

/// Largest expected correlation between the points' innovations (MismatchMonitorConfig::pointCorrelation).
inline constexpr double kMaxPointCorrelation = 0.95;

/// Which test of the mismatch monitor found a mismatch.
enum class MismatchTest {
    Variance,     ///< the normalised innovations are larger than the model says (NIS)
    Correlation,  ///< the innovations follow the corrections (a gain or delay error)
    Independence  ///< the points' innovations are correlated with each other more than the model says
};

/// A detected mismatch.
struct MismatchFinding {
    std::int64_t partNumber = 0;  ///< the part whose innovation tipped the test
    int point = 0;                ///< 1-based control point contributing most
    bool correlation = false;     ///< true: the correlation test (test == Correlation)
    MismatchTest test = MismatchTest::Variance;
    double statistic = 0.0;  ///< the test statistic
    double threshold = 0.0;  ///< its limit
    int windowParts = 0;     ///< parts in the window
};

/// Watches the controller's innovations for a plant that no longer matches the model, with two tests
/// over a sliding window of parts (innovations e = nu / sqrt(S), white with unit variance while the
/// model holds):
///  - correlation (score) test: e regressed on the corrections part k and part k - 1 received (both
///    fixed before part k was measured, so independent of e under the model): T = b' M^-1 b with
///    b = sum x e, M = sum x x'; T is chi-square with 2 degrees of freedom under the model, limit
///    -2 ln(alpha). A plant gain other than the model's shows as correlation with u(k), a longer plant
///    delay as correlation with u(k - 1).
///  - variance test: the normalised innovation squared summed over the window (chi-square with as many
///    degrees of freedom n as values), limit c n with the Chernoff bound exp(-n/2 (c - 1 - ln c)) = alpha,
///    so the false-alarm probability is at most alpha.
///  - independence test (Breusch & Pagan 1980, the LM test of cross-sectional independence): over the window's parts
///    with every point measured, LM = n sum_{i<j} r_ij^2 of the sample correlations of the innovations whitened with
///    the model's correlation (Innovation::correlation; identity for the preset's independent points), chi-square
///    with m(m-1)/2 degrees of freedom under the model; limit from the same Chernoff bound. A lathe whose points
///    move together (a tool offset moves the whole shaft) fails it at once against a model of independent points.
/// Innovations with a model correlation are whitened (generalised least squares) in all three tests.
/// Latches at the first finding until reset().
class MismatchMonitor {
public:
    /// Throws std::invalid_argument for a bad config.
    explicit MismatchMonitor(const MismatchMonitorConfig& config);

    /// Part `partNumber` was started with these radial corrections, mm per point.
    void partStarted(std::int64_t partNumber, const std::vector<double>& appliedMm);
    /// Adds the innovation of a measured part; a finding the first time a test exceeds its limit.
    std::optional<MismatchFinding> add(const Innovation& innovation);
    /// Forgets everything (a new run).
    void reset();
    /// A finding was made (latched).
    bool tripped() const { return m_tripped; }
    /// The limit of the correlation test.
    double correlationLimit() const { return m_correlationLimit; }
    /// The limit of the variance test for `n` values (c n, Chernoff bound).
    double varianceLimit(int n) const;
    const MismatchMonitorConfig& config() const { return m_config; }

private:
    struct PartTerms {
        Eigen::VectorXd whitened;  ///< the part's whitened innovations when every point has one (else empty)
        Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
        Eigen::Vector2d b = Eigen::Vector2d::Zero();
        double nis = 0.0;
        int values = 0;
        std::vector<Eigen::Matrix2d> pointM;
        std::vector<Eigen::Vector2d> pointB;
        std::vector<double> pointNis;
        std::vector<int> pointValues;
    };
    std::optional<PartTerms> terms(const Innovation& innovation) const;
    std::optional<MismatchFinding> test(std::int64_t part) const;
    std::optional<MismatchFinding> independence(std::int64_t part) const;

    MismatchMonitorConfig m_config;
    double m_correlationLimit = 0.0;
    std::map<std::int64_t, std::vector<double>> m_applied;
    std::deque<PartTerms> m_window;
    bool m_tripped = false;
};

/// The score statistic b' M^-1 b (a ridge of 1e-12 trace(M) keeps it finite and conservative when the
/// corrections are constant).
double correlationStatistic(const Eigen::Matrix2d& M, const Eigen::Vector2d& b);

/// The c > 1 with exp(-n/2 (c - 1 - ln c)) = alpha: P(chi2_n >= c n) <= alpha (Chernoff bound).
double chernoffChiSquareFactor(int n, double alpha);

}  // namespace tt::core
