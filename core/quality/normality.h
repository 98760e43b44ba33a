#pragma once

#include <cstddef>
#include <span>

namespace tt::core {

/// The fewest values the Anderson-Darling test takes (D'Agostino & Stephens give its modified statistic
/// for n >= 8).
inline constexpr std::size_t kMinNormalityValues = 8;

/// The Anderson-Darling test of normality with the mean and variance estimated from the data.
struct NormalityTest {
    std::size_t count = 0;
    double a2 = 0.0;          ///< A^2
    double a2Adjusted = 0.0;  ///< A*^2 = A^2 (1 + 0.75/n + 2.25/n^2)
    double pValue = 0.0;      ///< probability of an A*^2 at least this large from normal data, 0..1
};

/// Anderson & Darling (1954) statistic for a normal distribution with estimated mean and standard
/// deviation (n - 1 divisor): z_(i) = (x_(i) - x-bar)/s ascending, A^2 = -n - (1/n) sum_i (2i - 1)
/// [ln Phi(z_(i)) + ln(1 - Phi(z_(n+1-i)))] (NIST/SEMATECH e-Handbook, section 1.3.5.14); the modified
/// a = A*^2 = A^2 (1 + 0.75/n + 2.25/n^2) and its p-value by D'Agostino & Stephens (1986),
/// Goodness-of-Fit Techniques, Table 4.9 (case 3): a >= 0.6: exp(1.2937 - 5.709 a + 0.0186 a^2);
/// 0.34 <= a < 0.6: exp(0.9177 - 4.279 a - 1.38 a^2); 0.2 <= a < 0.34: 1 - exp(-8.318 + 42.796 a -
/// 59.938 a^2); a < 0.2: 1 - exp(-13.436 + 101.14 a - 223.73 a^2); above a = 13 the p-value is 0 (it is
/// below 5e-31 there and the first formula would turn upwards further on). statsmodels' normal_ad uses the
/// same formulas. Throws std::invalid_argument on fewer than 8 values, bad values (checkValues) or values
/// that are all equal.
NormalityTest andersonDarlingNormality(std::span<const double> valuesMm);

/// The p-value of a modified statistic A*^2 >= 0 by the D'Agostino & Stephens formulas above (0..1).
/// Throws std::invalid_argument for a negative or non-finite A*^2.
double andersonDarlingPValue(double adjustedA2);

/// The same test on values already sorted in ascending order (saves the copy and sort when the caller
/// needs the sorted values as well). The order is not checked.
NormalityTest andersonDarlingNormalitySorted(std::span<const double> sortedValuesMm);

}  // namespace tt::core
