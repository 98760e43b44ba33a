#pragma once

#include <string>

namespace tt::core {

/// `value` with `decimals` digits after the point, as printf "%.*f" (0.12345 and 3 -> "0.123"): numbers
/// in messages and texts the operator reads, independent of the locale.
std::string formatFixed(double value, int decimals);

/// `value` with at most `digits` significant digits, as printf "%.*g" (what std::ostream prints with
/// that precision; 6 is the stream's default): 0.000123456 and 3 -> "0.000123", 1e7 and 6 -> "1e+07".
std::string formatSignificant(double value, int digits);

}  // namespace tt::core
