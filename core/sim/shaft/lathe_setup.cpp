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

void finite(double v, const std::string& what) {
    if (!std::isfinite(v)) throw std::invalid_argument(what + " is not a finite number");
}

}  // namespace

void validateLatheSetup(const LatheSetup& s) {
    positive(s.workpiece.lengthMm, "the shaft length", "mm");
    positive(s.workpiece.finishDiameterMm, "the finished diameter", "mm");
    positive(s.workpiece.youngModulusNPerMm2, "Young's modulus", "N/mm²");
    positive(s.cutting.depthOfCutMm, "the depth of cut", "mm");
    if (s.cutting.depthOfCutMm >= 0.5 * s.workpiece.finishDiameterMm)
        throw std::invalid_argument("the depth of cut must be smaller than the finished radius");
    positive(s.cutting.feedMmPerRev, "the feed", "mm/rev");
    positive(s.cutting.cuttingSpeedMPerMin, "the cutting speed", "m/min");
    positive(s.stiffness.headstockNPerMm, "the headstock stiffness", "N/mm");
    positive(s.stiffness.tailstockNPerMm, "the tailstock stiffness", "N/mm");
    positive(s.stiffness.toolNPerMm, "the cutter stiffness", "N/mm");
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
    if (s.workpiece.lengthMm / s.beamElementMm > 20000.0)
        throw std::invalid_argument("the element length of the shaft model is too small for this shaft");
}

}  // namespace tt::core
