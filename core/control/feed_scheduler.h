#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/model/deformation_model.h"

namespace tt::core {

/// Where a feed step is switched to the next (paper 004, Fig. 2, or centred on the level).
enum class FeedSwitchRule {
    /// The paper's rule: z_i from Y(a, f_i, z_i) = Yc, so Y runs from Yc down to about
    /// Yc (f / (f + f_mm))^0.6 on every segment (one-sided, below the level).
    AtLevel,
    /// Centred on the level: z_i from (Y(a, f_{i-1}, z_i) + Y(a, f_i, z_i)) / 2 = Yc, so each switch
    /// jumps from half a step below Yc to half a step above it: the same feeds, half the deviation.
    Centred,
};

/// "level" or "centred".
const char* feedSwitchRuleName(FeedSwitchRule rule);
/// The rule named `name`; throws std::invalid_argument listing the names.
FeedSwitchRule feedSwitchRuleFromName(const std::string& name);

/// What the process planner asks of the feed scheduling (paper 004): the pass at depth a from
/// z_start to z_end, the feed range and the machine's feed increment, and the stabilisation level
/// Yc given directly or as a fraction of [Y1, Y2].
struct FeedScheduleRequest {
    double depthMm = 1.0;                 ///< depth of cut a, mm (constant along the pass)
    double feedMinMmPerRev = 0.05;        ///< fmin, mm/rev
    double feedMaxMmPerRev = 0.4;         ///< fmax, mm/rev
    double feedStepMmPerRev = 0.01;       ///< f_mm, the machine's feed increment (eq. (2)), mm/rev, > 0
    double zStartMm = 380.0;              ///< z where the pass starts (z_н), mm
    double zEndMm = 60.0;                 ///< z where the pass ends (z_кр), mm; != zStartMm
    std::optional<double> levelUm;        ///< Yc, µm; exactly one of levelUm and levelFraction
    std::optional<double> levelFraction;  ///< q in [0, 1]: Yc = Y1 + q (Y2 - Y1)
    double minLengthMm = 0.0;             ///< L_min, mm: shorter segments are skipped, >= 0
    /// Where a feed step is switched (the paper's rule by default).
    FeedSwitchRule switchRule = FeedSwitchRule::AtLevel;
};

/// One segment of the schedule: constant feed from zFrom to zTo (in the order of travel).
struct FeedSegment {
    double zFromMm = 0.0;
    double zToMm = 0.0;
    double feedMmPerRev = 0.0;
    double yFromUm = 0.0;  ///< the model's Y at zFrom with this feed, µm (Yc where the feed was switched)
    double yToUm = 0.0;    ///< the model's Y at zTo with this feed, µm

    /// |zTo - zFrom|, mm.
    double lengthMm() const;
};

/// The schedule of paper 004: Y1, Y2, the level, the start and end feeds and the segments.
struct FeedSchedule {
    double y1Um = 0.0;                  ///< Y(a, fmin, z_start), µm
    double y2Um = 0.0;                  ///< Y(a, fmax, z_end), µm
    double levelUm = 0.0;               ///< Yc, µm
    double feedStartMmPerRev = 0.0;     ///< f_i(a, z_start, Yc), mm/rev
    double feedEndMmPerRev = 0.0;       ///< f_кр(a, z_end, Yc), mm/rev
    std::vector<FeedSegment> segments;  ///< from z_start to z_end, feeds rising
    int skippedShort = 0;               ///< feed steps whose segment was shorter than L_min (or empty)

    /// The feed in force with the tool at z (the later segment at a breakpoint), mm/rev.
    double feedAtMm(double zMm) const;
    /// The largest |Y - Yc| / Yc of the model at the segments' ends, percent: the share of the
    /// deviation that the feed step itself leaves (the model's own sawtooth), before any model error.
    double modelDeviationPct() const;
};

/// Machining time of the pass with the schedule and with a constant feed, s (t = L / (f n)).
struct MachiningTimes {
    double scheduleS = 0.0;
    double feedMinS = 0.0;  ///< constant fmin over the whole length
    double feedMaxS = 0.0;  ///< constant fmax over the whole length

    /// (feedMinS - scheduleS) / feedMinS, percent.
    double savedVsFeedMinPct() const;
};

/// Schedules the feed along the pass so that the force deformation stays at Yc (paper 004, Fig. 2):
/// Y1 = Y(a, fmin, z_start), Y2 = Y(a, fmax, z_end); Yc in [Y1, Y2]; the start feed from
/// Y(a, f, z_start) = Yc, the end feed f_кр from Y(a, f, z_end) = Yc; then f_i = f_{i-1} + f_mm
/// (eq. (2)) and z_i from Y(a, f_i, z_i) = Yc (the first crossing on the way, bracketed: see
/// firstCrossing), until f_i >= f_кр, where z_i = z_end; a z_i beyond z_end is clamped to it; a
/// segment shorter than L_min is skipped (the next feed step is tried from the same point), and a last
/// segment shorter than L_min is joined to the one before (keeping its lower feed). With
/// FeedSwitchRule::Centred the switch points are where the mean of the two feeds' Y is Yc, and the
/// steps go on while the next feed is at most fmax and that point comes before z_end. Throws
/// std::invalid_argument naming the value and the limit for every request that cannot be met:
/// values not finite, fmin <= 0, fmax <= fmin, f_mm <= 0 or more than 10000 steps, z_start = z_end,
/// L_min < 0, a, f or z outside the model's fitted range, Y1 > Y2 (no level exists), Yc outside
/// [Y1, Y2], no feed in [fmin, fmax] giving Yc at an end (no root in range), or a deformation that does
/// not fall along the pass (the end feed below the start feed).
FeedSchedule scheduleFeed(const DeformationModel& model, const FeedScheduleRequest& request);

/// The machining times of the schedule and of constant fmin and fmax at `spindleRpm` (1 .. 20000).
MachiningTimes machiningTimes(const FeedSchedule& schedule, const FeedScheduleRequest& request, double spindleRpm);

}  // namespace tt::core
