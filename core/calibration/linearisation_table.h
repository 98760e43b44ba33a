#pragma once

#include <cstdint>
#include <vector>

namespace tt::core {

/// The supported ADC resolutions of the mandrel's microcontroller, bits.
inline constexpr int kMinAdcBits = 10;
inline constexpr int kMaxAdcBits = 16;

/// The table ADC code → deflection that the mandrel's microcontroller reads (paper 001, fig. 5):
/// 2^bits signed 16-bit entries of `scaleNm` nanometres each.
struct LinearisationTable {
    int adcBits = 0;
    std::uint16_t scaleNm = 0;          ///< nanometres per table unit
    std::vector<std::int16_t> entries;  ///< one per ADC code 0 .. 2^bits − 1

    /// Deflection at a code, µm; throws std::out_of_range outside the table.
    double deflectionUm(int code) const;
    /// Deflection at a (possibly fractional, possibly out-of-range) code: clamped and linearly
    /// interpolated, µm. What the host does with an averaged code.
    double interpolatedUm(double code) const;
};

}  // namespace tt::core
