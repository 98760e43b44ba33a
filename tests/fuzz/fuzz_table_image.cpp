// libFuzzer target: the linearisation table image decoder (docs/protocols/linearisation-table.md)
// on arbitrary bytes, and the re-encoding of every image it accepts.
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>

#include "core/calibration/linearisation_image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tt::core;
    try {
        const TableImage image = decodeTableImage(std::span<const std::uint8_t>(data, size));
        // An accepted image (format 1 or 2) encodes back in its format to the same size and CRC.
        const std::vector<std::uint8_t> again = encodeTableImage(image.table, image.info, image.format);
        if (again.size() != size) __builtin_trap();
        const TableImage back = decodeTableImage(again);  // what is written is read back
        if (back.format != image.format || back.table.entries != image.table.entries) __builtin_trap();
        (void)image.table.interpolatedUm(static_cast<double>(size % 70000) - 100.0);
    } catch (const std::invalid_argument&) {
    } catch (const std::out_of_range&) {
    }
    return 0;
}
