#pragma once

#include <string_view>

namespace tt::devices {

/// Length unit an instrument reports in. Conversions are exact (1 in = 25.4 mm by definition,
/// international yard and pound agreement, 1959).
enum class LengthUnit { Millimetre, Inch };

inline constexpr double kMillimetresPerInch = 25.4;

/// `value` in `unit` expressed in millimetres.
constexpr double toMillimetres(double value, LengthUnit unit) {
    return unit == LengthUnit::Inch ? value * kMillimetresPerInch : value;
}

/// Short name for messages: "mm" or "in".
constexpr std::string_view unitSymbol(LengthUnit unit) {
    return unit == LengthUnit::Inch ? "in" : "mm";
}

/// Long name for messages: "millimetres" or "inches".
constexpr std::string_view unitName(LengthUnit unit) {
    return unit == LengthUnit::Inch ? "inches" : "millimetres";
}

}  // namespace tt::devices
