#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace tt::core {

/// The verdict on a measured outer diameter against its tolerance zone (kept apart from a reading's
/// "accepted/rejected", which only says whether the reading is plausible and used by the controller).
enum class ToleranceVerdict {
    Good,    ///< within the limits (a value on a limit is inside)
    Rework,  ///< above the upper limit: material left on the outer diameter, can be turned again
    Scrap,   ///< below the lower limit: too much material removed
};

/// The tolerance zone of one diameter, mm: limits = nominal + deviation (ISO 286-1 terms: es = upper,
/// ei = lower deviation).
struct ToleranceZone {
    double nominalMm = 0.0;
    double upperDeviationMm = 0.0;  ///< es, > lowerDeviationMm
    double lowerDeviationMm = 0.0;  ///< ei

    /// nominal + es, mm.
    double upperLimitMm() const { return nominalMm + upperDeviationMm; }
    /// nominal + ei, mm.
    double lowerLimitMm() const { return nominalMm + lowerDeviationMm; }
};

/// The largest nominal diameter a tolerance zone takes, mm.
inline constexpr double kMaxToleranceNominalMm = 1.0e4;
/// The largest |deviation| of a tolerance zone, mm.
inline constexpr double kMaxToleranceDeviationMm = 100.0;

/// Throws std::invalid_argument, naming the value and its limit, unless 0 < nominal <= 10000 mm,
/// |es|, |ei| <= 100 mm, all finite, and ei < es.
void checkToleranceZone(const ToleranceZone& zone);

/// The verdict on a measured OUTER diameter: above the upper limit rework, below the lower limit scrap,
/// else good (the limits themselves are good). Throws std::invalid_argument on a value that is not finite.
ToleranceVerdict outerDiameterVerdict(const ToleranceZone& zone, double measuredMm);

/// The worse of two verdicts (scrap > rework > good): a part's verdict over its control points.
ToleranceVerdict worseVerdict(ToleranceVerdict a, ToleranceVerdict b);

/// How many parts got each verdict (the Run page, `trueturn simulate`, `trueturn report`).
struct VerdictCounts {
    std::int64_t good = 0;
    std::int64_t rework = 0;
    std::int64_t scrap = 0;

    /// Counts one part.
    void add(ToleranceVerdict verdict);
    /// good + rework + scrap.
    std::int64_t total() const { return good + rework + scrap; }
    /// First-pass yield good / total, 0..1; none before the first judged part.
    std::optional<double> yield() const;
};

/// Stable name stored in the history and written in reports: "good", "rework", "scrap".
std::string toleranceVerdictName(ToleranceVerdict verdict);
/// The verdict of a stored name; none for an unknown name.
std::optional<ToleranceVerdict> toleranceVerdictFromName(const std::string& name);

}  // namespace tt::core
