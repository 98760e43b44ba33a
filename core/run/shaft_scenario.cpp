#include "core/run/shaft_scenario.h"

namespace tt::core {

LatheShopSpec ShaftScenario::shopSpec(std::uint64_t seed) const {
    LatheShopSpec spec;
    spec.lathe = lathe;
    spec.plant = control.plant;
    spec.nominalDiameterMm = nominalDiameterMm;
    spec.partLengthMm = partLengthMm;
    spec.timing = timing;
    spec.seed = seed;
    spec.mismatch = plantMismatch;
    return spec;
}

LoopConfig ShaftScenario::loopConfig(bool feedForward, std::optional<std::int64_t> lastPartNumber) const {
    LoopConfig c;
    for (const ControlPointSpec& p : control.plant.points)
        c.pointZMm.push_back(p.xMm);
    c.partLengthMm = partLengthMm;
    c.nominalDiameterMm = nominalDiameterMm;
    c.delayParts = control.plant.delay;
    if (feedForward) c.systematicModel = systematicModel;
    c.interpolation = interpolation;
    c.pathStepMm = pathStepMm;
    c.plausibleRangeMm = plausibleRangeMm;
    c.limits = control.limits;
    c.gaugeTimeoutS = gaugeTimeoutS;
    c.lastPartNumber = lastPartNumber;
    c.tolerances = pointTolerances();
    c.pauseOnScrap = pauseOnScrap;
    c.mismatch = mismatchMonitor;
    c.adaptation = adaptation;
    validateLoopConfig(c);
    return c;
}

std::vector<ToleranceZone> ShaftScenario::pointTolerances() const {
    if (!tolerances.empty()) return tolerances;
    return std::vector<ToleranceZone>(control.plant.points.size(),
                                      ToleranceZone{nominalDiameterMm, toleranceMm, -toleranceMm});
}

}  // namespace tt::core
