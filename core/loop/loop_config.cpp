#include "core/loop/loop_config.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tt::core {

void validateLoopConfig(const LoopConfig& c) {
    c.mismatch.validate();
    c.adaptation.validate();
    if (c.adaptation.ditherShare > 0.0 && c.tolerances.empty())
        throw std::invalid_argument("the adaptation's dither is a share of the tolerance zones: give the tolerances");
    auto positive = [](double v, const std::string& what) {
        if (!std::isfinite(v) || v <= 0.0) throw std::invalid_argument(what + " must be a positive number");
    };
    positive(c.partLengthMm, "the part length");
    positive(c.nominalDiameterMm, "the nominal diameter");
    positive(c.pathStepMm, "the path step");
    positive(c.plausibleRangeMm, "the plausible range of a reading");
    c.limits.validate();
    positive(c.gaugeTimeoutS, "the gauge timeout");
    if (c.pointZMm.empty() || c.pointZMm.size() > 16)
        throw std::invalid_argument("the loop needs 1 .. 16 control points (got " + std::to_string(c.pointZMm.size()) +
                                    ")");
    for (std::size_t i = 0; i < c.pointZMm.size(); ++i) {
        const double z = c.pointZMm[i];
        if (!std::isfinite(z) || z < 0.0 || z > c.partLengthMm)
            throw std::invalid_argument("control point " + std::to_string(i + 1) + " lies outside the part");
        if (i > 0 && !(z > c.pointZMm[i - 1]))
            throw std::invalid_argument("the control points must be strictly increasing along the part");
    }
    if (c.delayParts < 1 || c.delayParts > 8)
        throw std::invalid_argument("the delay z must be 1 .. 8 parts (got " + std::to_string(c.delayParts) + ")");
    if (c.firstPartNumber < 1) throw std::invalid_argument("part numbers start at 1");
    if (c.lastPartNumber && *c.lastPartNumber < c.firstPartNumber)
        throw std::invalid_argument("the last part number comes before the first");
    if (!c.tolerances.empty() && c.tolerances.size() != c.pointZMm.size())
        throw std::invalid_argument("the job has " + std::to_string(c.tolerances.size()) + " tolerance(s) for " +
                                    std::to_string(c.pointZMm.size()) + " control points; give one per point");
    for (std::size_t i = 0; i < c.tolerances.size(); ++i) {
        try {
            checkToleranceZone(c.tolerances[i]);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("control point " + std::to_string(i + 1) + ": " + e.what());
        }
    }
    if (c.pauseOnScrap && c.tolerances.empty())
        throw std::invalid_argument("pausing on scrap needs the tolerances of the control points");
}

}  // namespace tt::core
