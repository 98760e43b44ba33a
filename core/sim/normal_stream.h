#pragma once

#include <cstdint>
#include <random>
#include <string>

namespace tt::core {

/// A seedable stream of standard normal numbers for the statistical run-to-run plant: 64-bit Mersenne
/// Twister (std::mt19937_64, specified bit-exactly by the C++ standard) and the Marsaglia polar method
/// written out here (std::normal_distribution differs between standard libraries), so a seed gives the
/// same run everywhere. The whole state can be saved and restored (resuming a simulation).
class NormalStream {
public:
    explicit NormalStream(std::uint64_t seed);

    /// The next N(0, 1) draw.
    double next();

    /// The complete generator state as text (engine state + cached second draw).
    std::string saveState() const;
    /// Restores a state from saveState(); throws std::invalid_argument when it is malformed.
    void restoreState(const std::string& state);

private:
    double uniformSigned();  // uniform in (-1, 1), 53-bit resolution

    std::mt19937_64 m_engine;
    bool m_hasSpare = false;
    double m_spare = 0.0;
};

}  // namespace tt::core
