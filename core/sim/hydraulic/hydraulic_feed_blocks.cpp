#include "core/sim/hydraulic/hydraulic_feed_blocks.h"

#include <algorithm>
#include <cmath>

namespace tt::core {

double magnetCurrentRate(double currentA, double voltageV, double inductanceH, double resistanceOhm) {
    return (voltageV - resistanceOhm * currentA) / inductanceH;
}

double armatureForce(double currentA, double gainNPerA2) {
    return gainNPerA2 * currentA * currentA;
}

double spoolAcceleration(double positionM, double velocityMPerS, double forceN, double timeConstantS,
                         double dampingRatio, double gainMPerN) {
    return (gainMPerN * forceN - positionM - 2.0 * dampingRatio * timeConstantS * velocityMPerS) /
           (timeConstantS * timeConstantS);
}

double slotOpening(double spoolPositionM, double overlapM, double maxOpeningM) {
    return std::clamp(spoolPositionM - overlapM, 0.0, maxOpeningM);
}

double slotFlow(double openingM, double slotGainM2PerS) {
    return slotGainM2PerS * openingM;
}

double leakageFlow(double loadN, double leakagePerNewtonM3PerS) {
    return leakagePerNewtonM3PerS * loadN;
}

double cylinderAcceleration(double feedMPerS, double flowM3PerS, double leakageM3PerS, double timeConstantS,
                            double gainPerM2) {
    return (gainPerM2 * (flowM3PerS - leakageM3PerS) - feedMPerS) / timeConstantS;
}

double sensedForce(double loadN, double feedMPerS, double setFeedMPerS, double feedExponent) {
    if (feedExponent == 0.0) return loadN;
    if (feedMPerS <= 0.0) return 0.0;
    return loadN * std::pow(feedMPerS / setFeedMPerS, feedExponent);
}

}  // namespace tt::core
