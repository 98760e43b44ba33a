#pragma once

// Published data sets of the quality tests, typed from the books (each checked by the sums the book prints).

#include <vector>

namespace tt::core::test {

/// Montgomery, Introduction to Statistical Quality Control, 6th ed. (2009), Table 6.3: inside diameters
/// (mm) of forged automobile-engine piston rings, 25 subgroups of 5, in production order. The book's sums:
/// sum of the (three-decimal) subgroup means 1850.028, sum of the ranges 0.581, s-bar 0.0094.
inline const std::vector<double> kPistonRings = {
    74.030, 74.002, 74.019, 73.992, 74.008, 73.995, 73.992, 74.001, 74.011, 74.004,  //  1,  2
    73.988, 74.024, 74.021, 74.005, 74.002, 74.002, 73.996, 73.993, 74.015, 74.009,  //  3,  4
    73.992, 74.007, 74.015, 73.989, 74.014, 74.009, 73.994, 73.997, 73.985, 73.993,  //  5,  6
    73.995, 74.006, 73.994, 74.000, 74.005, 73.985, 74.003, 73.993, 74.015, 73.988,  //  7,  8
    74.008, 73.995, 74.009, 74.005, 74.004, 73.998, 74.000, 73.990, 74.007, 73.995,  //  9, 10
    73.994, 73.998, 73.994, 73.995, 73.990, 74.004, 74.000, 74.007, 74.000, 73.996,  // 11, 12
    73.983, 74.002, 73.998, 73.997, 74.012, 74.006, 73.967, 73.994, 74.000, 73.984,  // 13, 14
    74.012, 74.014, 73.998, 73.999, 74.007, 74.000, 73.984, 74.005, 73.998, 73.996,  // 15, 16
    73.994, 74.012, 73.986, 74.005, 74.007, 74.006, 74.010, 74.018, 74.003, 74.000,  // 17, 18
    73.984, 74.002, 74.003, 74.005, 73.997, 74.000, 74.010, 74.013, 74.020, 74.003,  // 19, 20
    73.982, 74.001, 74.015, 74.005, 73.996, 74.004, 73.999, 73.990, 74.006, 74.009,  // 21, 22
    74.010, 73.989, 73.990, 74.009, 74.014, 74.015, 74.008, 73.993, 74.000, 74.010,  // 23, 24
    73.982, 73.984, 73.995, 74.017, 74.013,                                          // 25
};

/// Montgomery (2009), Section 6.4, the individuals example: weekly mortgage-loan processing costs, 20
/// values. The book: x-bar 300.5, MR-bar 7.79, I chart 279.78 .. 321.22, MR chart UCL 25.45.
inline const std::vector<double> kLoanCosts = {310, 288, 297, 298, 307, 303, 294, 297, 308, 306,
                                               294, 299, 297, 299, 314, 295, 293, 306, 301, 304};

/// Montgomery (2009), Table 9.1: 30 observations, the first 20 from N(10, 1), the last 10 from N(11, 1);
/// the tabular CUSUM of Table 9.2 (mu0 = 10, sigma = 1, k = 0.5, h = 5) signals at observation 29 with
/// C+ = 5.28 and N+ = 7.
inline const std::vector<double> kCusumTable91 = {9.45,  7.99,  9.29,  11.66, 12.16, 10.18, 8.04,  11.46, 9.20,  10.34,
                                                  9.03,  11.47, 10.51, 9.40,  10.08, 9.37,  10.62, 10.31, 8.52,  10.84,
                                                  10.90, 9.33,  12.29, 11.50, 10.60, 11.08, 10.38, 11.62, 11.31, 10.52};

}  // namespace tt::core::test
