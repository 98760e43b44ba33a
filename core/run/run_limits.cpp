#include "core/run/run_limits.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tt::core {

void checkRunSpeed(double speed) {
    if (speed == 0.0) return;
    if (std::isfinite(speed) && speed >= kMinRunSpeed && speed <= kMaxRunSpeed) return;
    std::ostringstream why;
    why << "the simulation speed " << speed << " is outside its range: 0 (as fast as possible) or " << kMinRunSpeed
        << " .. " << kMaxRunSpeed << " simulated seconds per wall second";
    throw std::invalid_argument(why.str());
}

void checkRunParts(std::int64_t parts, std::int64_t warmupParts) {
    if (parts < 2 || parts > kMaxRunParts)
        throw std::invalid_argument("a study of " + std::to_string(parts) +
                                    " counted parts is outside its range; the limit is 2 .. " +
                                    std::to_string(kMaxRunParts) + " parts");
    if (warmupParts < 0 || warmupParts > kMaxWarmupParts)
        throw std::invalid_argument("a warm-up of " + std::to_string(warmupParts) +
                                    " parts is outside its range; the limit is 0 .. " +
                                    std::to_string(kMaxWarmupParts) + " parts");
}

}  // namespace tt::core
