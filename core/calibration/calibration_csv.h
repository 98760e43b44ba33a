#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/calibration/probe_linearisation.h"

namespace tt::core {

/// Parses calibration pairs from CSV text: a header naming the columns `reference_um` and
/// `adc_code` (any order, other columns ignored), separated by ',' or ';'; blank lines and lines
/// starting with '#' are skipped. Each point keeps its line number. Throws std::invalid_argument
/// naming the line and column of the first bad row ("line 7: adc_code 'x12' is not a number").
std::vector<CalibrationPoint> parseCalibrationCsv(std::string_view text);

/// Writes points as CSV with the header `reference_um,adc_code` (what parseCalibrationCsv reads).
std::string calibrationCsv(const std::vector<CalibrationPoint>& points);

}  // namespace tt::core
