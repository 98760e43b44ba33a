#pragma once

#include <cstdint>
#include <random>
#include <vector>

namespace tt::core::test {

/// A simulated ARMA(1, 1) series y(t) = a y(t-1) + e(t) + b e(t-1), e ~ N(0, sigma^2), after a burn-in of
/// 500 values (std::mt19937_64 with `seed`, std::normal_distribution).
inline std::vector<double> simulateArma11(double a, double b, double sigma, std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    std::vector<double> y;
    double previousY = 0.0;
    double previousE = 0.0;
    for (std::size_t t = 0; t < n + 500; ++t) {
        const double e = noise(rng);
        const double v = a * previousY + e + b * previousE;
        previousY = v;
        previousE = e;
        if (t >= 500) y.push_back(v);
    }
    return y;
}

}  // namespace tt::core::test
