#include "core/sim/shaft/lathe_setup.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {

void positive(double v, const std::string& what, const char* unit) {
    if (!std::isfinite(v) || v <= 0.0) {
        std::ostringstream out;
        out << what << " must be a positive number of " << unit << " (got " << v << ")";
        throw std::invalid_argument(out.str());
    }
}

/// `v` within the physically sensible range lo .. hi (a positive number outside it is absurd for a
/// lathe, and makes the beam model singular or the cut a silent no-op).
void within(double v, double lo, double hi, const std::string& what, const char* unit) {
    positive(v, what, unit);
    if (v < lo || v > hi) {
        std::ostringstream out;
        out << what << " " << v << " " << unit << " is outside " << lo << " .. " << hi << " " << unit;
        throw std::invalid_argument(out.str());
    }
}

void finite(double v, const std::string& what) {
    if (!std::isfinite(v)) throw std::invalid_argument(what + " is not a finite number");
}

}  // namespace

void validateLatheSetup(const LatheSetup& s) {
    within(s.workpiece.lengthMm, 10.0, 20000.0, "the shaft length", "mm");
    within(s.workpiece.finishDiameterMm, 1.0, 2000.0, "the finished diameter", "mm");
    within(s.workpiece.youngModulusNPerMm2, 500.0, 1.2e6, "Young's modulus", "N/mm²");
    within(s.cutting.depthOfCutMm, 0.001, 50.0, "the depth of cut", "mm");
    if (s.cutting.depthOfCutMm >= 0.5 * s.workpiece.finishDiameterMm)
        throw std::invalid_argument("the depth of cut must be smaller than the finished radius");
    within(s.cutting.feedMmPerRev, 0.001, 10.0, "the feed", "mm/rev");
    within(s.cutting.cuttingSpeedMPerMin, 0.1, 2000.0, "the cutting speed", "m/min");
    within(s.stiffness.headstockNPerMm, 100.0, 1e7, "the headstock stiffness", "N/mm");
    within(s.stiffness.tailstockNPerMm, 100.0, 1e7, "the tailstock stiffness", "N/mm");
    within(s.stiffness.toolNPerMm, 100.0, 1e7, "the cutter stiffness", "N/mm");
    within(s.force.specificForceNPerMm2, 10.0, 1e4, "the specific cutting force", "N/mm²");
    within(s.force.referenceSpeedMPerMin, 1.0, 1000.0, "the reference cutting speed", "m/min");
    finite(s.warmUp.diameterShiftMm, "the warm-up shift");
    positive(s.warmUp.durationParts, "the warm-up duration", "parts");
    finite(s.wear.diameterGrowthMm, "the tool wear");
    if (s.wear.toolLifeParts < 1 || s.wear.toolLifeParts > 100000)
        throw std::invalid_argument("the tool life must be 1 .. 100000 parts (got " +
                                    std::to_string(s.wear.toolLifeParts) + ")");
    if (!std::isfinite(s.wear.changeRepeatabilityMm) || s.wear.changeRepeatabilityMm < 0.0)
        throw std::invalid_argument("the tool-change repeatability must be zero or positive");
    finite(s.toolSettingOffsetMm, "the tool setting offset");
    if (!std::isfinite(s.randomCommonShare) || s.randomCommonShare < 0.0 || s.randomCommonShare > 1.0)
        throw std::invalid_argument("the common share of the random variation must lie in 0 .. 1");
    if (!std::isfinite(s.randomScale) || s.randomScale < 0.0 || s.randomScale > 100.0)
        throw std::invalid_argument("the scale of the random variation must lie in 0 .. 100");
    positive(s.beamElementMm, "the element length of the shaft model", "mm");
    if (s.beamElementMm > s.workpiece.lengthMm / 10.0) {
        std::ostringstream out;
        out << "the element length of the shaft model " << s.beamElementMm << " mm is longer than a tenth of the "
            << s.workpiece.lengthMm << " mm shaft (at least 10 elements)";
        throw std::invalid_argument(out.str());
    }
    if (s.workpiece.lengthMm / s.beamElementMm > 20000.0)
        throw std::invalid_argument("the element length of the shaft model is too small for this shaft");
}

}  // namespace tt::core
