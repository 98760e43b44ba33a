#pragma once

#include <cstdint>
#include <random>
#include <string>

namespace tt::core {

/// The seedable stream of standard normal numbers of every simulator (the statistical run-to-run plant,
/// the lathe's disturbance, micrometer and tool changes): 64-bit Mersenne Twister (std::mt19937_64,
/// specified bit-exactly by the C++ standard) and the Box–Muller transform written out here on two
/// 53-bit uniforms in (0, 1) (std::normal_distribution differs between standard libraries), so a seed
/// gives the same run everywhere. The whole state can be saved and restored (resuming a simulation).
class NormalStream {
public:
    /// The stream of `seed` (the same numbers on every platform).
    explicit NormalStream(std::uint64_t seed);

    /// The next N(0, 1) draw: sqrt(-2 ln u1) cos(2 pi u2).
    double next();

    /// The complete generator state as text.
    std::string saveState() const;
    /// Restores a state from saveState(); throws std::invalid_argument when it is malformed.
    void restoreState(const std::string& state);

private:
    double uniformOpen();  // uniform in (0, 1), 53-bit resolution

    std::mt19937_64 m_engine;
};

}  // namespace tt::core
