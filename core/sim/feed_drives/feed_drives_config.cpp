#include "core/sim/feed_drives/feed_drives_config.h"

#include <stdexcept>
#include <string>

#include "core/common/text_format.h"

namespace tt::core {

const char* toString(FeedAxis axis) {
    return axis == FeedAxis::X ? "x" : "z";
}

FeedAxis feedAxisFromString(const char* text) {
    const std::string s = text;
    if (s == "x" || s == "X") return FeedAxis::X;
    if (s == "z" || s == "Z") return FeedAxis::Z;
    throw std::invalid_argument("axis '" + s + "' is neither x nor z");
}

FeedDriveAxisConfig defaultZDrive() {
    FeedDriveAxisConfig z;
    z.inertiaKgM2 = 0.02;
    z.torqueConstantNmPerA = 1.2;
    z.viscousFrictionNmSPerRad = 0.15;
    z.coulombFrictionNm = 2.0;
    z.staticFrictionNm = 5.0;
    z.stribeckSpeedRadPerS = 3.0;
    z.velocityGainAPerRadPerS = 1.0;
    return z;
}

void validateFeedDrives(const FeedDrivesConfig& config) {
    validateFeedDriveAxis(config.x, "X");
    validateFeedDriveAxis(config.z, "Z");
    if (!(config.stepS >= 1e-6 && config.stepS <= kMaxFeedDriveStepS))
        throw std::invalid_argument("integration step " + formatSignificant(config.stepS * 1e3, 6) +
                                    " ms is outside 0.001 .. 0.1 ms");
}

const FeedDriveAxisConfig& axisConfig(const FeedDrivesConfig& config, FeedAxis axis) {
    return axis == FeedAxis::X ? config.x : config.z;
}

FeedDriveAxisConfig& axisConfig(FeedDrivesConfig& config, FeedAxis axis) {
    return axis == FeedAxis::X ? config.x : config.z;
}

void scaleFriction(FeedDrivesConfig& config, FeedAxis axis, double factor) {
    if (!(factor >= 0.1 && factor <= 10.0))
        throw std::invalid_argument("friction factor " + formatSignificant(factor, 6) + " is outside 0.1 .. 10");
    FeedDriveAxisConfig& c = axisConfig(config, axis);
    c.viscousFrictionNmSPerRad *= factor;
    c.coulombFrictionNm *= factor;
    c.staticFrictionNm *= factor;
}

}  // namespace tt::core
