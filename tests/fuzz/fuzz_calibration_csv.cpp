// libFuzzer target: the CSV readers of the boring feature, on arbitrary text: calibration pairs
// (reference_um,adc_code) when the first byte is even, the tool table otherwise.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "core/calibration/calibration_csv.h"
#include "core/model/tool_table_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        if (data[0] % 2 == 0) {
            for (const tt::core::CalibrationPoint& p : tt::core::parseCalibrationCsv(text))
                if (p.line <= 0) __builtin_trap();
        } else {
            for (const tt::core::ToolCsvRow& row : tt::core::parseToolCsv(text))
                if (row.line <= 0) __builtin_trap();
        }
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
