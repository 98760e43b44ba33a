#pragma once

#include <cstddef>
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

/// The binary image's fixed values. Format 2 (written by default) carries a CRC-32C of the whole
/// image in the header; format 1 (the first release, up to 14-bit tables on probe protocol 1)
/// ends in a CRC-16. Both are read.
inline constexpr std::uint8_t kTableImageFormat = 2;
inline constexpr std::uint8_t kTableImageFormatCrc16 = 1;
inline constexpr std::size_t kTableImageHeaderBytes = 32;

/// A decoded image: the table, its identification and the CRC it carries.
struct TableImage {
    TableImageInfo info;
    LinearisationTable table;
    std::uint8_t format = kTableImageFormat;
    std::uint32_t crc = 0;  ///< format 2: CRC-32C at offset 28; format 1: the trailing CRC-16/CCITT-FALSE
};

/// Size of an image of a `adcBits` table in `format`, bytes (format 2: 32 + 2 · 2^bits; format 1:
/// two more for the trailing CRC). Throws std::invalid_argument for bits outside 10..16 or an
/// unknown format.
std::size_t tableImageBytes(int adcBits, std::uint8_t format = kTableImageFormat);

/// The image uploaded to the mandrel over the probe protocol: 32-byte header, 2^bits int16
/// entries, all little-endian; format 2 with the CRC-32C of everything else at offset 28, format 1
/// with a trailing CRC-16/CCITT-FALSE (for mandrel firmware of probe protocol 1). Layout:
/// docs/protocols/linearisation-table.md. Throws std::invalid_argument for an inconsistent table,
/// identification fields outside the specification or an unknown format.
std::vector<std::uint8_t> encodeTableImage(const LinearisationTable& table, const TableImageInfo& info,
                                           std::uint8_t format = kTableImageFormat);

/// Decodes and checks an image of format 1 or 2 (magic, format, sizes, bits, CRC, then every header
/// field against docs/protocols/linearisation-table.md: plane, version, reserved, created, scale,
/// degree, flags); throws std::invalid_argument saying what is wrong ("CRC mismatch: image says
/// 0x1A2B3C4D, content gives 0x…", "image field 'scale' (offset 20) is 7; the specification allows …").
TableImage decodeTableImage(std::span<const std::uint8_t> bytes);

/// The CRC an image carries (format 2: the CRC-32C at offset 28; format 1, and
/// anything else: the last two bytes); throws std::invalid_argument when fewer than two bytes.
std::uint32_t tableImageCrc(std::span<const std::uint8_t> bytes);

/// The CRC the probe protocol announces for an upload and the mandrel reports back (protocol 2:
/// TABLE_BEGIN_32 / TABLE_INFO_32): CRC-32C of every byte of the image, its own CRC included
/// (the image is opaque to the protocol).
std::uint32_t tableUploadCrc(std::span<const std::uint8_t> image);

/// Printable CRC: "0x1A2B3C4D" (8 hex digits), or "0x1A2B" for a value that fits 16 bits when
/// `bits` is 16.
std::string crcText(std::uint32_t crc, int bits = 32);

/// The table as CSV: header `adc_code,deflection_um`, one row per code.
std::string tableToCsv(const LinearisationTable& table);

/// The table as a C header for the mandrel's microcontroller (C99, <stdint.h>): the entries as
/// `static const int16_t`, the scale, the size, the version, the image format and the CRC-32C of
/// the format-2 image of the same table as macros.
std::string tableToCHeader(const LinearisationTable& table, const TableImageInfo& info);

}  // namespace tt::core
