#include "core/common/tolerance.h"

#include <cmath>
#include <stdexcept>

#include "core/common/text_format.h"

namespace tt::core {

void checkToleranceZone(const ToleranceZone& zone) {
    if (!std::isfinite(zone.nominalMm) || zone.nominalMm <= 0.0 || zone.nominalMm > kMaxToleranceNominalMm)
        throw std::invalid_argument("the nominal diameter " + formatSignificant(zone.nominalMm, 6) +
                                    " mm of a tolerance must lie in (0, 10000] mm");
    for (const double deviation : {zone.upperDeviationMm, zone.lowerDeviationMm})
        if (!std::isfinite(deviation) || std::fabs(deviation) > kMaxToleranceDeviationMm)
            throw std::invalid_argument("a tolerance deviation of " + formatSignificant(deviation, 6) +
                                        " mm lies beyond +-100 mm");
    if (!(zone.lowerDeviationMm < zone.upperDeviationMm))
        throw std::invalid_argument("the lower deviation " + formatSignificant(zone.lowerDeviationMm, 6) +
                                    " mm of a tolerance must be below its upper deviation " +
                                    formatSignificant(zone.upperDeviationMm, 6) + " mm");
}

ToleranceVerdict outerDiameterVerdict(const ToleranceZone& zone, double measuredMm) {
    if (!std::isfinite(measuredMm)) throw std::invalid_argument("a measured diameter must be a finite number");
    if (measuredMm > zone.upperLimitMm()) return ToleranceVerdict::Rework;
    if (measuredMm < zone.lowerLimitMm()) return ToleranceVerdict::Scrap;
    return ToleranceVerdict::Good;
}

ToleranceVerdict worseVerdict(ToleranceVerdict a, ToleranceVerdict b) {
    return static_cast<int>(a) >= static_cast<int>(b) ? a : b;
}

void VerdictCounts::add(ToleranceVerdict verdict) {
    switch (verdict) {
        case ToleranceVerdict::Good:
            ++good;
            break;
        case ToleranceVerdict::Rework:
            ++rework;
            break;
        case ToleranceVerdict::Scrap:
            ++scrap;
            break;
    }
}

std::optional<double> VerdictCounts::yield() const {
    if (total() == 0) return std::nullopt;
    return static_cast<double>(good) / static_cast<double>(total());
}

std::string toleranceVerdictName(ToleranceVerdict verdict) {
    switch (verdict) {
        case ToleranceVerdict::Good:
            return "good";
        case ToleranceVerdict::Rework:
            return "rework";
        case ToleranceVerdict::Scrap:
            return "scrap";
    }
    return "good";
}

std::optional<ToleranceVerdict> toleranceVerdictFromName(const std::string& name) {
    for (const ToleranceVerdict v : {ToleranceVerdict::Good, ToleranceVerdict::Rework, ToleranceVerdict::Scrap})
        if (toleranceVerdictName(v) == name) return v;
    return std::nullopt;
}

}  // namespace tt::core
