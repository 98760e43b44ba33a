#include "core/calibration/linearisation_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tt::core {

double LinearisationTable::deflectionUm(int code) const {
    if (code < 0 || static_cast<std::size_t>(code) >= entries.size())
        throw std::out_of_range("ADC code " + std::to_string(code) + " is outside the table");
    return entries[static_cast<std::size_t>(code)] * (scaleNm / 1000.0);
}

double LinearisationTable::interpolatedUm(double code) const {
    if (entries.empty()) throw std::out_of_range("the linearisation table is empty");
    const double top = static_cast<double>(entries.size() - 1);
    const double c = std::clamp(code, 0.0, top);
    const int lo = static_cast<int>(std::floor(c));
    const int hi = std::min(lo + 1, static_cast<int>(top));
    const double w = c - lo;
    return (1.0 - w) * deflectionUm(lo) + w * deflectionUm(hi);
}

}  // namespace tt::core
