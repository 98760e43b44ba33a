#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/calibration/linearisation_table.h"

namespace tt::core {

/// What identifies a saved table besides its entries (docs/protocols/linearisation-table.md).
struct TableImageInfo {
    std::uint16_t version =
        1;  ///< table version, increases with every saved table of a probe (u16, as the probe protocol)
    std::int64_t createdUnixS = 0;  ///< when it was built, seconds since 1970-01-01 UTC
    std::uint8_t plane = 0;         ///< bending plane: 0 = X (radial), 1 = Y (tangential)
    std::uint8_t degree = 0;        ///< degree of the fitted characteristic
};

/// The binary image's fixed values.
inline constexpr std::uint8_t kTableImageFormat = 1;
inline constexpr std::size_t kTableImageHeaderBytes = 32;

/// A decoded image: the table, its identification and the CRC it carries.
struct TableImage {
    TableImageInfo info;
    LinearisationTable table;
    std::uint16_t crc = 0;  ///< CRC-16/CCITT-FALSE of header + entries (what the mandrel reports back)
};

/// The image uploaded to the mandrel over the probe protocol: 32-byte header, 2^bits int16
/// entries, CRC-16/CCITT-FALSE; all little-endian. Layout: docs/protocols/linearisation-table.md.
std::vector<std::uint8_t> encodeTableImage(const LinearisationTable& table, const TableImageInfo& info);

/// Decodes and checks an image (magic, format, sizes, bits, CRC); throws std::invalid_argument
/// saying what is wrong ("CRC mismatch: image says 0x1A2B, content gives 0x3C4D").
TableImage decodeTableImage(std::span<const std::uint8_t> bytes);

/// The CRC an image carries (its last two bytes); throws std::invalid_argument when too short.
std::uint16_t tableImageCrc(std::span<const std::uint8_t> bytes);

/// The CRC the probe protocol announces for an upload and the mandrel reports back
/// (TABLE_BEGIN / TABLE_INFO): CRC-16/CCITT-FALSE of every byte of the image, its own trailing
/// CRC included (the image is opaque to the protocol).
std::uint16_t tableUploadCrc(std::span<const std::uint8_t> image);

/// The table as CSV: header `adc_code,deflection_um`, one row per code.
std::string tableToCsv(const LinearisationTable& table);

/// The table as a C header for the mandrel's microcontroller (C99, <stdint.h>): the entries as
/// `static const int16_t`, the scale, the size, the version and the image CRC as macros.
std::string tableToCHeader(const LinearisationTable& table, const TableImageInfo& info);

}  // namespace tt::core
