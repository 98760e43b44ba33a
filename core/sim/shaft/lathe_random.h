#pragma once

#include <cstdint>

#include "core/sim/statistics/normal_stream.h"

namespace tt::core {

/// Independent, reproducible random streams of the simulator. Every draw comes from a NormalStream
/// seeded by (seed, stream, a, b) through SplitMix64 (Steele, Lea & Flood 2014), so a part's
/// micrometer noise or a tool's setting error does not depend on what was drawn before: a resumed
/// run reproduces the uninterrupted one.
enum class LatheStream : std::uint64_t { Disturbance = 1, Micrometer = 2, ToolChange = 3, InitialState = 4 };

/// SplitMix64 finaliser of x.
std::uint64_t splitMix64(std::uint64_t x);

/// The standard normal stream of the given stream and indices (its seed is SplitMix64 chained over
/// seed, stream, a and b).
NormalStream latheNormals(std::uint64_t seed, LatheStream stream, std::uint64_t a = 0, std::uint64_t b = 0);

}  // namespace tt::core
