#include "core/sim/shaft/lathe_random.h"

namespace tt::core {

std::uint64_t splitMix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
}

NormalStream latheNormals(std::uint64_t seed, LatheStream stream, std::uint64_t a, std::uint64_t b) {
    std::uint64_t h = splitMix64(seed);
    h = splitMix64(h ^ static_cast<std::uint64_t>(stream));
    h = splitMix64(h ^ a);
    h = splitMix64(h ^ b);
    return NormalStream(h);
}

}  // namespace tt::core
