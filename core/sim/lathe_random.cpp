#include "core/sim/lathe_random.h"

#include <cmath>
#include <numbers>

namespace tt::core {

std::uint64_t splitMix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
}

std::mt19937_64 latheGenerator(std::uint64_t seed, LatheStream stream, std::uint64_t a, std::uint64_t b) {
    std::uint64_t h = splitMix64(seed);
    h = splitMix64(h ^ static_cast<std::uint64_t>(stream));
    h = splitMix64(h ^ a);
    h = splitMix64(h ^ b);
    return std::mt19937_64(h);
}

namespace {
double uniformOpen(std::mt19937_64& g) {
    // 53 random bits mapped into (0, 1).
    return (static_cast<double>(g() >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}
}  // namespace

double standardNormal(std::mt19937_64& generator) {
    const double u1 = uniformOpen(generator);
    const double u2 = uniformOpen(generator);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace tt::core
