#pragma once

#include <string>

namespace tt::core {

/// Appended to a refusal of a row with too many fields or a number with a comma: every file is read in
/// the C locale, so "12,5" is not twelve and a half.
inline constexpr const char* kCLocaleNote = " (numbers are read in the C locale: the decimal point is '.', not ',')";

/// `value` with `decimals` digits after the point, as printf "%.*f" (0.12345 and 3 -> "0.123"): numbers
/// in messages and texts the operator reads, independent of the locale.
std::string formatFixed(double value, int decimals);

/// `value` with at most `digits` significant digits, as printf "%.*g" (what std::ostream prints with
/// that precision; 6 is the stream's default): 0.000123456 and 3 -> "0.000123", 1e7 and 6 -> "1e+07".
std::string formatSignificant(double value, int digits);

}  // namespace tt::core
