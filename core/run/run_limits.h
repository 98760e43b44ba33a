#pragma once

#include <cstdint>

namespace tt::core {

/// Parts a headless study counts at most (10 million: about 2 h of wall time as fast as possible).
inline constexpr std::int64_t kMaxRunParts = 10'000'000;
/// Parts machined first and not counted, at most.
inline constexpr std::int64_t kMaxWarmupParts = 1'000'000;
/// Slowest pacing of a simulated run, simulated s per wall s (1: the lathe's own pace; 0 means no pacing).
inline constexpr double kMinRunSpeed = 1.0;
/// Fastest pacing of a simulated run, simulated s per wall s.
inline constexpr double kMaxRunSpeed = 1e9;

/// Checks a run's pacing: 0 (as fast as possible) or kMinRunSpeed .. kMaxRunSpeed. Throws
/// std::invalid_argument naming the value and the limits (a tiny speed would wait for ages, and one of
/// 1e-300 turns every wait into infinity).
void checkRunSpeed(double speed);

/// Checks the parts of a study before any work: `parts` counted (2 .. kMaxRunParts) and `warmupParts`
/// (0 .. kMaxWarmupParts). Throws std::invalid_argument naming the value and the limit.
void checkRunParts(std::int64_t parts, std::int64_t warmupParts);

}  // namespace tt::core
