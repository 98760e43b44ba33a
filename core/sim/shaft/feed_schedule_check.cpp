#include "core/sim/shaft/feed_schedule_check.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {

/// A position and the feed in force there.
struct Sample {
    double zMm;
    double feedMmPerRev;
};

/// The checked positions in the order of travel: every segment's start and end with its own feed (so
/// a breakpoint is checked with the feed before and after the change) and the shaft's nodes inside.
std::vector<Sample> samples(const LathePass& pass, const FeedSchedule& schedule) {
    std::vector<Sample> out;
    for (const FeedSegment& s : schedule.segments) {
        out.push_back({s.zFromMm, s.feedMmPerRev});
        const double lo = std::min(s.zFromMm, s.zToMm);
        const double hi = std::max(s.zFromMm, s.zToMm);
        std::vector<double> inside;
        for (double z : pass.gridZMm())
            if (z > lo && z < hi) inside.push_back(z);
        if (s.zToMm < s.zFromMm) std::reverse(inside.begin(), inside.end());
        for (double z : inside)
            out.push_back({z, s.feedMmPerRev});
        out.push_back({s.zToMm, s.feedMmPerRev});
    }
    return out;
}

}  // namespace

FeedScheduleCheck checkFeedSchedule(const LathePass& pass, const FeedSchedule& schedule,
                                    const FeedScheduleRequest& request) {
    if (schedule.segments.empty()) throw std::invalid_argument("the feed schedule has no segments to machine");
    if (std::abs(pass.depthMm() - request.depthMm) > 1e-9)
        throw std::invalid_argument("the simulated pass is cut at " + std::to_string(pass.depthMm()) +
                                    " mm but the schedule was made for " + std::to_string(request.depthMm) + " mm");
    const double level = schedule.levelUm;
    if (!(level > 0.0)) throw std::invalid_argument("the level Yc must be above 0 µm to be checked in percent");
    FeedScheduleCheck check;
    for (const Sample& s : samples(pass, schedule)) {
        const double y = 1000.0 * pass.deformationMm(s.zMm, s.feedMmPerRev);
        const double yMax = 1000.0 * pass.deformationMm(s.zMm, request.feedMaxMmPerRev);
        const double yMin = 1000.0 * pass.deformationMm(s.zMm, request.feedMinMmPerRev);
        check.zMm.push_back(s.zMm);
        check.scheduleUm.push_back(y);
        check.feedMaxUm.push_back(yMax);
        check.feedMinUm.push_back(yMin);
        const double deviation = 100.0 * std::abs(y - level) / level;
        if (check.zMm.size() == 1 || deviation > check.maxDeviationPct) {
            check.maxDeviationPct = deviation;
            check.worstZMm = s.zMm;
            check.worstYUm = y;
        }
        const double excess = 100.0 * (yMax - level) / level;
        if (check.zMm.size() == 1 || excess > check.feedMaxExcessPct) {
            check.feedMaxExcessPct = excess;
            check.feedMaxWorstZMm = s.zMm;
        }
        check.feedMinShortfallPct = std::max(check.feedMinShortfallPct, 100.0 * (level - yMin) / level);
    }
    return check;
}

}  // namespace tt::core
