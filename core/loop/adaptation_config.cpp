#include "core/loop/adaptation_config.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/text_format.h"
#include "core/control/adaptive_design.h"

namespace tt::core {

PlantIdentificationOptions AdaptationConfig::identification(int loopDelay, const RunToRunPlantSpec& model) const {
    PlantIdentificationOptions o;
    o.loopDelay = loopDelay;
    o.priorLag = std::max(0, model.delay - loopDelay);
    o.maxExtraLag = maxExtraLag;
    o.maxArmaOrder = maxArmaOrder;
    o.criterion = criterion;
    for (const ControlPointSpec& p : model.points) {
        o.priorGain.push_back(p.gain);
        const std::optional<ArmaForm> a = armaForm(p.disturbance);
        o.priorAr.push_back(a ? a->ar : std::vector<double>{});
        o.priorMa.push_back(a ? a->ma : std::vector<double>{});
    }
    o.maxGainRelativeStdErr = maxGainRelativeStdErr;
    o.minDelayEvidence = minDelayEvidence;
    o.minParts = static_cast<std::size_t>(minParts);
    return o;
}

void AdaptationConfig::validate() const {
    auto range = [](int v, int lo, int hi, const std::string& what) {
        if (v < lo || v > hi)
            throw std::invalid_argument(what + " must be " + std::to_string(lo) + " .. " + std::to_string(hi) +
                                        ", got " + std::to_string(v));
    };
    range(windowParts, 200, 100000, "the adaptation's identification window (parts)");
    range(retryParts, 1, 10000, "the parts between identification attempts");
    range(transferParts, 1, 1000, "the parts a controller switch fades over");
    range(maxExtraLag, 0, 4, "the extra plant delay the identification tries (parts)");
    range(maxArmaOrder, 0, kMaxArmaOrder, "the largest ARMA order of the disturbance");
    range(minParts, 70, 100000, "the parts the identification needs at least");
    range(refineParts, 10, 100000, "the parts between refinements of an adapted model");
    if (!std::isfinite(refineBelow) || refineBelow < 0.0 || refineBelow > 1.0)
        throw std::invalid_argument("the gain uncertainty a refinement aims at must be 0 .. 1 of the gain");
    if (minParts > windowParts)
        throw std::invalid_argument("the identification needs " + std::to_string(minParts) +
                                    " parts, more than its window of " + std::to_string(windowParts));
    if (!std::isfinite(ditherShare) || ditherShare < 0.0 || ditherShare > kMaxDitherShare)
        throw std::invalid_argument("the dither must be 0 .. " + formatSignificant(kMaxDitherShare, 2) +
                                    " of the tolerance zone, got " + formatSignificant(ditherShare, 3));
    if (!(maxGainRelativeStdErr > 0.0 && maxGainRelativeStdErr <= 1.0))
        throw std::invalid_argument("the largest standard error of an identified gain must be in (0, 1] of the gain");
    if (!std::isfinite(minDelayEvidence) || minDelayEvidence < 0.0)
        throw std::invalid_argument("the evidence the identified delay needs must be >= 0");
    if (!std::isfinite(minGainMargin) || minGainMargin < 1.05 || minGainMargin > kMaxMinGainMargin)
        throw std::invalid_argument("the gain margin a new design must have must be 1.05 .. " +
                                    formatSignificant(kMaxMinGainMargin, 3) + ", got " +
                                    formatSignificant(minGainMargin, 3));
}

}  // namespace tt::core
