#include "core/run/dither_check.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

/// V = c A / T for the trapezoid with constant-velocity fraction f: c = 8 / (1 + f) (DitherProfile).
double speedFactor(const DitherConfig& d) {
    return 8.0 / (1.0 + d.constantVelocityFraction);
}

/// Amplitude rounded up (down) to the micrometre.
double ceilUm(double mm) {
    return std::ceil(mm * 1000.0 - 1e-9) / 1000.0;
}
double floorUm(double mm) {
    return std::floor(mm * 1000.0 + 1e-9) / 1000.0;
}
/// Period rounded down (up) to 10 ms.
double floorPeriod(double s) {
    return std::floor(s * 100.0 + 1e-9) / 100.0;
}
double ceilPeriod(double s) {
    return std::ceil(s * 100.0 - 1e-9) / 100.0;
}

}  // namespace

DitherVerdict checkDither(const BoringScenario& scenario) {
    const DitherConfig& d = scenario.dither;
    const double c = speedFactor(d);
    const double dt = scenario.plcCycleS;
    const double windUpMm = 2.0 * scenario.drive.staticFrictionN / scenario.drive.transmissionStiffnessNPerMm;
    const double cyclesNeeded = static_cast<double>(scenario.estimator.minPlateauSamples);
    DitherVerdict v;
    v.plateauSpeedMmPerS = c * d.amplitudeMm / d.periodS;
    v.slideTravelMm = 2.0 * d.amplitudeMm - windUpMm;
    v.cyclesAtSpeed = std::max(0.0, v.slideTravelMm) / v.plateauSpeedMmPerS / dt;

    // (1) Travel (2A - w) / (c A / T) >= n dt  <=>  A (2 - n dt c / T) >= w, and >= the minimum stroke.
    const bool tooShort = v.slideTravelMm < scenario.estimator.minStrokeMm;
    if (tooShort || v.cyclesAtSpeed < cyclesNeeded) {
        v.problem = DitherProblem::TooSmallToResolve;
        const double denominator = 2.0 - cyclesNeeded * dt * c / d.periodS;
        const double forStroke = (scenario.estimator.minStrokeMm + windUpMm) / 2.0;
        if (denominator > 0.0) v.validAmplitudeMm = ceilUm(std::max(windUpMm / denominator, forStroke));
        if (!tooShort) v.validPeriodS = ceilPeriod(cyclesNeeded * dt * c * d.amplitudeMm / v.slideTravelMm);
        v.reason =
            "dither " + formatFixed(d.amplitudeMm, 3) + " mm / " + formatFixed(d.periodS, 2) +
            " s cannot be resolved: the slide moves " + formatFixed(std::max(0.0, v.slideTravelMm) * 1000.0, 1) +
            " µm per stroke (2 A less " + formatFixed(windUpMm * 1000.0, 1) +
            " µm of screw wind-up at static friction), " + formatFixed(v.cyclesAtSpeed, 1) + " PLC cycles at " +
            formatFixed(v.plateauSpeedMmPerS, 3) + " mm/s; at least " + formatFixed(cyclesNeeded, 0) +
            " cycles are needed: use an amplitude of at least " +
            (v.validAmplitudeMm ? formatFixed(*v.validAmplitudeMm, 3) + " mm" : std::string("(none at this period)")) +
            (v.validPeriodS ? " or a period of at least " + formatFixed(*v.validPeriodS, 2) + " s" : std::string());
        return v;
    }
    // (2) V >= k r  <=>  A >= k r T / c  or  T <= c A / (k r).
    const double rate = scenario.limits.maxRateMmPerS;
    if (v.plateauSpeedMmPerS < kDitherOverOffsetRate * rate - 1e-12) {
        v.problem = DitherProblem::SlowerThanOffset;
        v.validAmplitudeMm = ceilUm(kDitherOverOffsetRate * rate * d.periodS / c);
        v.validPeriodS = floorPeriod(c * d.amplitudeMm / (kDitherOverOffsetRate * rate));
        v.reason = "dither " + formatFixed(d.amplitudeMm, 3) + " mm / " + formatFixed(d.periodS, 2) +
                   " s moves the slide at " + formatFixed(v.plateauSpeedMmPerS, 3) +
                   " mm/s, slower than twice the offset's rate limit of " + formatFixed(rate, 3) +
                   " mm/s: the slide would not reverse while the offset moves: use an amplitude of at least " +
                   formatFixed(*v.validAmplitudeMm, 3) + " mm or a period of at most " +
                   formatFixed(*v.validPeriodS, 2) + " s";
        return v;
    }
    // (3) The dither is cut into the bore: 2 A on the diameter.
    const double tolerance = scenario.cut.boreToleranceMm;
    if (tolerance > 0.0 && 2.0 * d.amplitudeMm > tolerance + 1e-12) {
        v.problem = DitherProblem::RippleBeyondTolerance;
        v.validAmplitudeMm = floorUm(tolerance / 2.0);
        v.reason = "dither " + formatFixed(d.amplitudeMm, 3) + " mm cuts a ripple of " +
                   formatFixed(2.0 * d.amplitudeMm, 3) + " mm into the diameter, more than the bore tolerance of " +
                   formatFixed(tolerance, 3) + " mm: use an amplitude of at most " +
                   formatFixed(*v.validAmplitudeMm, 3) + " mm";
    }
    return v;
}

void requireResolvableDither(const BoringScenario& scenario) {
    const DitherVerdict v = checkDither(scenario);
    if (!v.ok()) throw std::invalid_argument(v.reason);
}

}  // namespace tt::core
