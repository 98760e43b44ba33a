#include "core/control/feed_scheduler.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/model/level_crossing.h"

namespace tt::core {

namespace {

constexpr double kMaxSteps = 10000.0;
/// Values within this relative margin of a fitted range's end count as inside it (typed rounding).
constexpr double kRangeMargin = 1e-9;
/// Relative difference of two deformations that is rounding, not a different level.
constexpr double kLevelTolerance = 1e-12;

std::string num(double v) {
    std::ostringstream out;
    out.precision(6);
    out << v;
    return out.str();
}

[[noreturn]] void refuse(const std::string& why) {
    throw std::invalid_argument(why);
}

void requireFinite(double v, const char* what) {
    if (!std::isfinite(v)) refuse(std::string(what) + " is not a finite number");
}

void requireInModelRange(const DeformationModel& model, DeformationFactor factor, double v, const char* what,
                         const char* unit) {
    const FactorCoding& c = model.coding(factor);
    const double margin = kRangeMargin * (c.max - c.min);
    if (v < c.min - margin || v > c.max + margin)
        refuse(std::string(what) + " " + num(v) + " " + unit + " is outside the model's range " + num(c.min) + " .. " +
               num(c.max) + " " + unit + " (the experiments it was fitted on)");
}

void checkRequest(const DeformationModel& model, const FeedScheduleRequest& r) {
    requireFinite(r.depthMm, "the depth of cut");
    requireFinite(r.feedMinMmPerRev, "fmin");
    requireFinite(r.feedMaxMmPerRev, "fmax");
    requireFinite(r.feedStepMmPerRev, "the feed step f_mm");
    requireFinite(r.zStartMm, "z_start");
    requireFinite(r.zEndMm, "z_end");
    requireFinite(r.minLengthMm, "L_min");
    if (!(r.feedMinMmPerRev > 0.0)) refuse("fmin " + num(r.feedMinMmPerRev) + " mm/rev must be above 0");
    if (!(r.feedMaxMmPerRev > r.feedMinMmPerRev))
        refuse("fmax " + num(r.feedMaxMmPerRev) + " mm/rev must be above fmin " + num(r.feedMinMmPerRev) + " mm/rev");
    if (!(r.feedStepMmPerRev > 0.0))
        refuse("the feed step f_mm " + num(r.feedStepMmPerRev) + " mm/rev must be above 0 (eq. (2) needs f_mm > 0)");
    if ((r.feedMaxMmPerRev - r.feedMinMmPerRev) / r.feedStepMmPerRev > kMaxSteps)
        refuse("the feed step f_mm " + num(r.feedStepMmPerRev) + " mm/rev is too fine: at most " + num(kMaxSteps) +
               " steps from fmin to fmax (at least " + num((r.feedMaxMmPerRev - r.feedMinMmPerRev) / kMaxSteps) +
               " mm/rev)");
    if (r.zStartMm == r.zEndMm) refuse("z_start and z_end are both " + num(r.zStartMm) + " mm: the pass has no length");
    if (r.minLengthMm < 0.0) refuse("L_min " + num(r.minLengthMm) + " mm must not be negative");
    if (r.levelUm.has_value() == r.levelFraction.has_value())
        refuse("give the level either in µm or as a fraction of [Y1, Y2], not both and not neither");
    if (r.levelUm) requireFinite(*r.levelUm, "the level Yc");
    if (r.levelFraction) {
        requireFinite(*r.levelFraction, "the level fraction");
        if (*r.levelFraction < 0.0 || *r.levelFraction > 1.0)
            refuse("the level fraction " + num(*r.levelFraction) + " is outside 0 .. 1");
    }
    requireInModelRange(model, DeformationFactor::Depth, r.depthMm, "the depth of cut", "mm");
    requireInModelRange(model, DeformationFactor::Feed, r.feedMinMmPerRev, "fmin", "mm/rev");
    requireInModelRange(model, DeformationFactor::Feed, r.feedMaxMmPerRev, "fmax", "mm/rev");
    requireInModelRange(model, DeformationFactor::Axial, r.zStartMm, "z_start", "mm");
    requireInModelRange(model, DeformationFactor::Axial, r.zEndMm, "z_end", "mm");
}

/// The feed that gives Y = Yc at z: the first feed from fmin upwards where Y reaches Yc.
double feedForLevel(const DeformationModel& model, const FeedScheduleRequest& r, double zMm, double levelUm,
                    const char* where) {
    const ScaledPolynomial y = model.againstFeed(r.depthMm, zMm);
    std::optional<double> f = firstCrossing(y, levelUm, r.feedMinMmPerRev, r.feedMaxMmPerRev, CrossingSide::AtOrAbove);
    // Yc = Y2 reaches the level exactly at fmax: rounding must not turn that into "no root".
    if (!f && std::abs(y.value(r.feedMaxMmPerRev) - levelUm) <= kLevelTolerance * std::max(1.0, std::abs(levelUm)))
        f = r.feedMaxMmPerRev;
    if (!f)
        refuse(std::string("no feed between fmin ") + num(r.feedMinMmPerRev) + " and fmax " + num(r.feedMaxMmPerRev) +
               " mm/rev gives Yc = " + num(levelUm) + " µm at " + where + " = " + num(zMm) + " mm (the model gives " +
               num(y.value(r.feedMinMmPerRev)) + " .. " + num(y.value(r.feedMaxMmPerRev)) + " µm there)");
    return *f;
}

FeedSegment segment(const DeformationModel& model, double depthMm, double from, double to, double feed) {
    return {from, to, feed, model.deformationUm(depthMm, feed, from), model.deformationUm(depthMm, feed, to)};
}

/// Where the feed `next` takes over from `current` on the way from zFrom (empty: not before z_end): the
/// paper's Y(next, z) = Yc, or the centred rule's (Y(current, z) + Y(next, z)) / 2 = Yc.
std::optional<double> switchPoint(const DeformationModel& model, const FeedScheduleRequest& r, double levelUm,
                                  double current, double next, double zFrom) {
    const ScaledPolynomial nextY = model.alongAxis(r.depthMm, next);
    if (r.switchRule == FeedSwitchRule::AtLevel)
        return firstCrossing(nextY, levelUm, zFrom, r.zEndMm, CrossingSide::AtOrBelow);
    // Both slices share the z coding, so their mean is the mean of the coefficients.
    const ScaledPolynomial currentY = model.alongAxis(r.depthMm, current);
    const ScaledPolynomial mean(0.5 * (currentY.scaledCoefficients() + nextY.scaledCoefficients()), nextY.centre(),
                                nextY.scale());
    return firstCrossing(mean, levelUm, zFrom, r.zEndMm, CrossingSide::AtOrBelow);
}

}  // namespace

double FeedSegment::lengthMm() const {
    return std::abs(zToMm - zFromMm);
}

double FeedSchedule::feedAtMm(double zMm) const {
    if (segments.empty()) throw std::logic_error("the feed schedule has no segments");
    const double direction = segments.front().zToMm > segments.front().zFromMm ? 1.0 : -1.0;
    for (const FeedSegment& s : segments)
        if (direction * (zMm - s.zToMm) < 0.0) return s.feedMmPerRev;
    return segments.back().feedMmPerRev;
}

double FeedSchedule::modelDeviationPct() const {
    double worst = 0.0;
    if (!(levelUm > 0.0)) return worst;
    for (const FeedSegment& s : segments)
        worst = std::max({worst, std::abs(s.yFromUm - levelUm), std::abs(s.yToUm - levelUm)});
    return 100.0 * worst / levelUm;
}

const char* feedSwitchRuleName(FeedSwitchRule rule) {
    return rule == FeedSwitchRule::Centred ? "centred" : "level";
}

FeedSwitchRule feedSwitchRuleFromName(const std::string& name) {
    if (name == "level") return FeedSwitchRule::AtLevel;
    if (name == "centred") return FeedSwitchRule::Centred;
    throw std::invalid_argument("unknown switch rule '" + name + "' (level, centred)");
}

double MachiningTimes::savedVsFeedMinPct() const {
    return feedMinS > 0.0 ? 100.0 * (feedMinS - scheduleS) / feedMinS : 0.0;
}

FeedSchedule scheduleFeed(const DeformationModel& model, const FeedScheduleRequest& r) {
    checkRequest(model, r);
    FeedSchedule s;
    // Y1 and Y2 from the same polynomials the feeds are solved on, so Yc = Y1 or Y2 is met exactly at fmin, fmax.
    s.y1Um = model.againstFeed(r.depthMm, r.zStartMm).value(r.feedMinMmPerRev);
    s.y2Um = model.againstFeed(r.depthMm, r.zEndMm).value(r.feedMaxMmPerRev);
    if (s.y1Um > s.y2Um)
        refuse("no level can be held from z_start to z_end: Y1 = Y(fmin, z_start) = " + num(s.y1Um) +
               " µm is above Y2 = Y(fmax, z_end) = " + num(s.y2Um) +
               " µm (shorten the pass, widen the feed range or lower the depth of cut)");
    s.levelUm = r.levelUm ? *r.levelUm : s.y1Um + *r.levelFraction * (s.y2Um - s.y1Um);
    if (s.levelUm < s.y1Um || s.levelUm > s.y2Um)
        refuse("the level Yc = " + num(s.levelUm) + " µm is outside [Y1, Y2] = [" + num(s.y1Um) + ", " + num(s.y2Um) +
               "] µm");
    s.feedStartMmPerRev = feedForLevel(model, r, r.zStartMm, s.levelUm, "z_start");
    s.feedEndMmPerRev = feedForLevel(model, r, r.zEndMm, s.levelUm, "z_end");
    if (s.feedEndMmPerRev < s.feedStartMmPerRev)
        refuse("the deformation does not fall from z_start = " + num(r.zStartMm) + " mm to z_end = " + num(r.zEndMm) +
               " mm: Yc = " + num(s.levelUm) + " µm needs " + num(s.feedStartMmPerRev) + " mm/rev at the start but " +
               num(s.feedEndMmPerRev) + " mm/rev at the end (run the pass the other way)");

    const double direction = r.zEndMm > r.zStartMm ? 1.0 : -1.0;
    double zCurrent = r.zStartMm;
    double feedCurrent = s.feedStartMmPerRev;
    // The paper steps while f_i < f_кр; centred steps go on while the next feed is in range.
    const double lastFeed = r.switchRule == FeedSwitchRule::AtLevel
                                ? s.feedEndMmPerRev
                                : r.feedMaxMmPerRev + kRangeMargin * (r.feedMaxMmPerRev - r.feedMinMmPerRev);
    for (int step = 1;; ++step) {
        const double feed = s.feedStartMmPerRev + step * r.feedStepMmPerRev;  // eq. (2), without accumulated rounding
        double z = r.zEndMm;
        const bool stepping = r.switchRule == FeedSwitchRule::AtLevel ? feed < lastFeed : feed <= lastFeed;
        if (stepping) {
            const std::optional<double> root = switchPoint(model, r, s.levelUm, feedCurrent, feed, zCurrent);
            if (root && direction * (*root - r.zEndMm) < 0.0) z = *root;  // else clamped at the end
        }
        const bool atEnd = z == r.zEndMm;
        const double length = std::abs(z - zCurrent);
        if (!atEnd && (length == 0.0 || length < r.minLengthMm)) {
            ++s.skippedShort;
            continue;
        }
        s.segments.push_back(segment(model, r.depthMm, zCurrent, z, feedCurrent));
        if (atEnd) break;
        zCurrent = z;
        feedCurrent = feed;
    }
    // A last segment shorter than L_min joins the one before, which keeps its lower feed.
    if (s.segments.size() > 1 && s.segments.back().lengthMm() < r.minLengthMm) {
        s.segments.pop_back();
        const FeedSegment& last = s.segments.back();
        s.segments.back() = segment(model, r.depthMm, last.zFromMm, r.zEndMm, last.feedMmPerRev);
        ++s.skippedShort;
    }
    return s;
}

MachiningTimes machiningTimes(const FeedSchedule& schedule, const FeedScheduleRequest& request, double spindleRpm) {
    if (!std::isfinite(spindleRpm) || spindleRpm < 1.0 || spindleRpm > 20000.0)
        refuse("the spindle speed " + num(spindleRpm) + " rpm is outside 1 .. 20000 rpm");
    const double length = std::abs(request.zEndMm - request.zStartMm);
    auto seconds = [&](double lengthMm, double feed) { return 60.0 * lengthMm / (feed * spindleRpm); };
    MachiningTimes t;
    for (const FeedSegment& s : schedule.segments)
        t.scheduleS += seconds(s.lengthMm(), s.feedMmPerRev);
    t.feedMinS = seconds(length, request.feedMinMmPerRev);
    t.feedMaxS = seconds(length, request.feedMaxMmPerRev);
    return t;
}

}  // namespace tt::core
