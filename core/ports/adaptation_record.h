#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/common/notice.h"

namespace tt::core {

/// One control point of a plant model as recorded: y(k) = gain u(k - lag) + ARMA(p, q) noise (mm of diameter
/// per radial mm; the ARMA coefficients in the form y = a_1 y(k-1) + .. + e + b_1 e(k-1) + ..). Standard errors
/// are NaN for a model that was not identified (the preset's).
struct PointModelRecord {
    double gain = 2.0;
    double gainStdErr = std::numeric_limits<double>::quiet_NaN();
    /// The gain's standard error with the disturbance free too (equal to gainStdErr unless the disturbance was kept).
    double gainStdErrJoint = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> ar, ma;  ///< empty lists with a NaN noise variance: not an ARMA model
    std::vector<double> arStdErr, maStdErr;
    double noiseVarianceMm2 = std::numeric_limits<double>::quiet_NaN();  ///< variance of e, mm^2
    double meanMm = std::numeric_limits<double>::quiet_NaN();            ///< identified mean, mm
};

/// The controller's model of the plant before or after an adaptation.
struct PlantModelRecord {
    int delayParts = 1;  ///< the plant delay the design uses: the loop's z + lagParts
    int lagParts = 0;    ///< a correction sent for part k acts on part k + lagParts
    std::vector<PointModelRecord> points;
    /// Correlation of the points' prediction errors, row by row (points x points); empty: independent.
    std::vector<double> innovationCorrelation;
    std::string source;     ///< "preset paper-2012", "parts 101 .. 1100 of run 7"
    std::string criterion;  ///< "bic", "aic" for an identified model; empty otherwise
};

/// Robustness of a design as recorded: the worst channel (NaN: no such margin, the loop tolerates any change).
struct MarginsRecord {
    double gain = std::numeric_limits<double>::quiet_NaN();        ///< smallest upper gain margin
    double gainLower = std::numeric_limits<double>::quiet_NaN();   ///< largest lower gain margin
    double phaseDeg = std::numeric_limits<double>::quiet_NaN();    ///< smallest phase margin, degrees
    double delayParts = std::numeric_limits<double>::quiet_NaN();  ///< smallest delay margin, parts
    int extraPartsTolerated = 0;                                   ///< whole extra parts of delay tolerated
};

/// What the adaptive loop did, stored with the run (and read into the audit trail): switched to the fallback on a
/// model mismatch, adapted to an identified model, proposed one for an engineer's Apply, refused a design that
/// failed its margins, took a proposal the engineer accepted, or refined an adapted model as its data grew.
struct AdaptationRecord {
    /// "fallback", "adapted", "proposed", "refused", "accepted", "refined".
    std::string kind;
    std::int64_t partNumber = 0;  ///< the part the controller changes at (the alarm's part for "refused")
    double timeS = 0.0;           ///< the loop's clock, s
    std::string reason;           ///< why, in stable English (the alarm, the identification, the margins)
    std::string fallback;         ///< the fallback controller in use ("ewma 0.23"); empty: none
    double fallbackWeight = std::numeric_limits<double>::quiet_NaN();
    PlantModelRecord modelBefore;
    std::optional<PlantModelRecord> modelAfter;  ///< the identified model (none: the fallback alone)
    MarginsRecord margins;  ///< of the controller taking over (the fallback's, or the new design's)
    bool applied = false;   ///< the loop's controller changed
    Notice notice;          ///< the same as a kind with data (the UI words it)
};

/// The kinds of an adaptation record.
namespace adaptation_kind {
inline constexpr const char* kFallback = "fallback";
inline constexpr const char* kAdapted = "adapted";
inline constexpr const char* kProposed = "proposed";
inline constexpr const char* kRefused = "refused";
inline constexpr const char* kAccepted = "accepted";
inline constexpr const char* kRefined = "refined";
}  // namespace adaptation_kind

}  // namespace tt::core
