#pragma once

#include <cstdint>
#include <random>

namespace tt::core {

/// Independent, reproducible random streams of the simulator. Every draw comes from a generator
/// seeded by (seed, stream, a, b) through SplitMix64 (Steele, Lea & Flood 2014), so a part's
/// micrometer noise or a tool's setting error does not depend on what was drawn before: a resumed
/// run reproduces the uninterrupted one.
enum class LatheStream : std::uint64_t { Disturbance = 1, Micrometer = 2, ToolChange = 3, InitialState = 4 };

/// SplitMix64 finaliser of x.
std::uint64_t splitMix64(std::uint64_t x);

/// A generator for the given stream and indices.
std::mt19937_64 latheGenerator(std::uint64_t seed, LatheStream stream, std::uint64_t a = 0, std::uint64_t b = 0);

/// One standard normal draw (Box–Muller on two 53-bit uniforms, so the value is the same on every
/// standard library).
double standardNormal(std::mt19937_64& generator);

}  // namespace tt::core
