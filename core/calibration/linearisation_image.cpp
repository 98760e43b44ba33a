#include "core/calibration/linearisation_image.h"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "core/common/crc16.h"
#include "core/common/crc32c.h"

namespace tt::core {

namespace {

constexpr std::uint8_t kMagic[4] = {'T', 'T', 'L', 'T'};
constexpr std::uint8_t kFlagDecreasing = 0x01;

void put16(std::vector<std::uint8_t>& out, std::uint16_t v) {
    out.push_back(static_cast<std::uint8_t>(v & 0xFF));
    out.push_back(static_cast<std::uint8_t>(v >> 8));
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<std::uint8_t>((v >> (8 * i)) & 0xFF));
}

void put64(std::vector<std::uint8_t>& out, std::uint64_t v) {
    for (int i = 0; i < 8; ++i)
        out.push_back(static_cast<std::uint8_t>((v >> (8 * i)) & 0xFF));
}

std::uint64_t get(std::span<const std::uint8_t> b, std::size_t at, int bytes) {
    std::uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i)
        v = (v << 8) | b[at + static_cast<std::size_t>(i)];
    return v;
}

constexpr std::size_t kCrc32At = 28;  ///< format 2: CRC-32C field in the header

void checkFormat(std::uint8_t format) {
    if (format != kTableImageFormat && format != kTableImageFormatCrc16)
        throw std::invalid_argument("image format " + std::to_string(format) + " is not supported (1 or 2)");
}

/// Format 2: CRC-32C of the image without its CRC field (bytes 28..31).
std::uint32_t format2Crc(std::span<const std::uint8_t> bytes) {
    return crc32c(bytes.subspan(kCrc32At + 4), crc32c(bytes.first(kCrc32At)));
}

/// CRC width of a format, bits.
int crcBits(std::uint8_t format) {
    return format == kTableImageFormatCrc16 ? 16 : 32;
}

void checkTable(const LinearisationTable& table) {
    if (table.adcBits < kMinAdcBits || table.adcBits > kMaxAdcBits)
        throw std::invalid_argument("table ADC resolution " + std::to_string(table.adcBits) + " bits is outside " +
                                    std::to_string(kMinAdcBits) + " .. " + std::to_string(kMaxAdcBits));
    if (table.entries.size() != (std::size_t{1} << table.adcBits))
        throw std::invalid_argument("a " + std::to_string(table.adcBits) + "-bit table needs " +
                                    std::to_string(std::size_t{1} << table.adcBits) + " entries, got " +
                                    std::to_string(table.entries.size()));
    if (table.scaleNm == 0) throw std::invalid_argument("table scale must be above 0 nm");
}

bool decreasing(const LinearisationTable& table) {
    return table.entries.back() < table.entries.front();
}

/// The scales the specification allows, nm per table unit (docs/protocols/linearisation-table.md).
constexpr std::uint16_t kScalesNm[] = {10, 20, 50, 100, 200, 500, 1000, 2000, 5000};
/// The latest creation time an image may carry: 9999-12-31 23:59:59 UTC, s.
constexpr std::int64_t kLatestCreatedUnixS = 253'402'300'799;

[[noreturn]] void fieldOutOfSpec(const char* field, std::size_t offset, long long value, const std::string& allowed) {
    throw std::invalid_argument("image field '" + std::string(field) + "' (offset " + std::to_string(offset) + ") is " +
                                std::to_string(value) + "; the specification allows " + allowed);
}

/// The identification fields within the specification; throws naming the field, its value and what is allowed.
void checkInfo(const TableImageInfo& info) {
    if (info.plane > 1) fieldOutOfSpec("bending plane", 7, info.plane, "0 (X) or 1 (Y)");
    if (info.version < 1) fieldOutOfSpec("table version", 8, info.version, "1 .. 65535");
    if (info.createdUnixS < 0 || info.createdUnixS > kLatestCreatedUnixS)
        fieldOutOfSpec("created", 12, info.createdUnixS, "0 .. " + std::to_string(kLatestCreatedUnixS) + " s");
    if (info.degree == 1 || info.degree > 4) fieldOutOfSpec("degree", 22, info.degree, "2 .. 4 (0: not recorded)");
}

/// The header fields of an image that the CRC cannot vouch for (a writer that got them wrong made a
/// valid CRC over them): reserved bytes, scale, flags against the entries, and the identification.
void checkImageFields(std::span<const std::uint8_t> bytes, const TableImage& image) {
    if (get(bytes, 10, 2) != 0) fieldOutOfSpec("reserved", 10, static_cast<long long>(get(bytes, 10, 2)), "0");
    if (image.format == kTableImageFormatCrc16 && get(bytes, kCrc32At, 4) != 0)
        fieldOutOfSpec("reserved (format 1)", kCrc32At, static_cast<long long>(get(bytes, kCrc32At, 4)), "0");
    bool knownScale = false;
    for (std::uint16_t s : kScalesNm)
        knownScale = knownScale || s == image.table.scaleNm;
    if (!knownScale)
        fieldOutOfSpec("scale", 20, image.table.scaleNm, "10, 20, 50, 100, 200, 500, 1000, 2000 or 5000 nm");
    const std::uint8_t flags = bytes[23];
    if ((flags & ~kFlagDecreasing) != 0) fieldOutOfSpec("flags", 23, flags, "bit 0 only");
    if (((flags & kFlagDecreasing) != 0) != decreasing(image.table))
        fieldOutOfSpec("flags", 23, flags,
                       std::string("bit 0 = ") + (decreasing(image.table) ? "1" : "0") +
                           " for these entries (deflection " + (decreasing(image.table) ? "decreasing" : "increasing") +
                           " with the code)");
    checkInfo(image.info);
}

}  // namespace

std::size_t tableImageBytes(int adcBits, std::uint8_t format) {
    checkFormat(format);
    if (adcBits < kMinAdcBits || adcBits > kMaxAdcBits)
        throw std::invalid_argument("table ADC resolution " + std::to_string(adcBits) + " bits is outside " +
                                    std::to_string(kMinAdcBits) + " .. " + std::to_string(kMaxAdcBits));
    return kTableImageHeaderBytes + 2 * (std::size_t{1} << adcBits) + (format == kTableImageFormatCrc16 ? 2 : 0);
}

std::vector<std::uint8_t> encodeTableImage(const LinearisationTable& table, const TableImageInfo& info,
                                           std::uint8_t format) {
    checkFormat(format);
    checkTable(table);
    checkInfo(info);
    std::vector<std::uint8_t> out;
    out.reserve(tableImageBytes(table.adcBits, format));
    for (std::uint8_t m : kMagic)  // 0: magic "TTLT"
        out.push_back(m);
    out.push_back(format);                                             // 4: format
    out.push_back(static_cast<std::uint8_t>(kTableImageHeaderBytes));  // 5: header size
    out.push_back(static_cast<std::uint8_t>(table.adcBits));           // 6: ADC bits
    out.push_back(info.plane);                                         // 7: plane
    put16(out, info.version);                                          // 8: table version
    put16(out, 0);                                                     // 10: reserved
    put64(out, static_cast<std::uint64_t>(info.createdUnixS));         // 12: created
    put16(out, table.scaleNm);                                         // 20: nm per unit
    out.push_back(info.degree);                                        // 22: degree
    out.push_back(decreasing(table) ? kFlagDecreasing : 0);            // 23: flags
    put32(out, static_cast<std::uint32_t>(table.entries.size()));      // 24: entry count
    put32(out, 0);  // 28: format 2: CRC-32C (filled in below); format 1: reserved
    for (std::int16_t e : table.entries)
        put16(out, static_cast<std::uint16_t>(e));
    if (format == kTableImageFormatCrc16) {
        put16(out, crc16Ccitt(out));
    } else {
        const std::uint32_t crc = format2Crc(out);
        for (std::size_t i = 0; i < 4; ++i)
            out[kCrc32At + i] = static_cast<std::uint8_t>((crc >> (8 * i)) & 0xFF);
    }
    return out;
}

std::uint32_t tableImageCrc(std::span<const std::uint8_t> bytes) {
    if (bytes.size() >= kTableImageHeaderBytes && bytes[4] == kTableImageFormat)
        return static_cast<std::uint32_t>(get(bytes, kCrc32At, 4));
    if (bytes.size() < 2) throw std::invalid_argument("the image is too short to carry a CRC");
    return static_cast<std::uint32_t>(get(bytes, bytes.size() - 2, 2));  // format 1: the trailing CRC-16
}

TableImage decodeTableImage(std::span<const std::uint8_t> bytes) {
    if (bytes.size() < kTableImageHeaderBytes + 2)
        throw std::invalid_argument("the image has " + std::to_string(bytes.size()) + " bytes, less than a header");
    for (std::size_t i = 0; i < 4; ++i)
        if (bytes[i] != kMagic[i]) throw std::invalid_argument("not a linearisation table image (no TTLT mark)");
    const std::uint8_t format = bytes[4];
    if (format != kTableImageFormat && format != kTableImageFormatCrc16)
        throw std::invalid_argument("image format " + std::to_string(format) +
                                    " is not supported (this program reads formats 1 and 2)");
    if (bytes[5] != kTableImageHeaderBytes) throw std::invalid_argument("image header size is wrong");
    const int bits = bytes[6];
    if (bits < kMinAdcBits || bits > kMaxAdcBits)
        throw std::invalid_argument("image ADC resolution " + std::to_string(bits) + " bits is outside " +
                                    std::to_string(kMinAdcBits) + " .. " + std::to_string(kMaxAdcBits));
    const std::uint64_t count = get(bytes, 24, 4);
    if (count != (std::uint64_t{1} << bits))
        throw std::invalid_argument("image entry count " + std::to_string(count) + " does not match " +
                                    std::to_string(bits) + " bits");
    const std::size_t expected = tableImageBytes(bits, format);
    if (bytes.size() != expected)
        throw std::invalid_argument("the image has " + std::to_string(bytes.size()) + " bytes, expected " +
                                    std::to_string(expected));
    const std::uint32_t carried = tableImageCrc(bytes);
    const std::uint32_t computed =
        format == kTableImageFormatCrc16 ? crc16Ccitt(bytes.first(bytes.size() - 2)) : format2Crc(bytes);
    if (carried != computed)
        throw std::invalid_argument("CRC mismatch: image says " + crcText(carried, crcBits(format)) +
                                    ", content gives " + crcText(computed, crcBits(format)));
    TableImage image;
    image.format = format;
    image.crc = carried;
    image.info.plane = bytes[7];
    image.info.version = static_cast<std::uint16_t>(get(bytes, 8, 2));
    image.info.createdUnixS = static_cast<std::int64_t>(get(bytes, 12, 8));
    image.table.scaleNm = static_cast<std::uint16_t>(get(bytes, 20, 2));
    image.info.degree = bytes[22];
    image.table.adcBits = bits;
    image.table.entries.resize(count);
    for (std::size_t i = 0; i < count; ++i)
        image.table.entries[i] = static_cast<std::int16_t>(get(bytes, kTableImageHeaderBytes + 2 * i, 2));
    checkImageFields(bytes, image);
    return image;
}

std::uint32_t tableUploadCrc(std::span<const std::uint8_t> image) {
    return crc32c(image);
}

std::string crcText(std::uint32_t crc, int bits) {
    char buf[16];
    if (bits == 16 && crc <= 0xFFFF)
        std::snprintf(buf, sizeof buf, "0x%04X", static_cast<unsigned>(crc));
    else
        std::snprintf(buf, sizeof buf, "0x%08X", static_cast<unsigned>(crc));
    return buf;
}

std::string tableToCsv(const LinearisationTable& table) {
    checkTable(table);
    std::ostringstream out;
    out << "adc_code,deflection_um\n";
    char buf[32];
    for (std::size_t c = 0; c < table.entries.size(); ++c) {
        std::snprintf(buf, sizeof buf, "%.3f", table.deflectionUm(static_cast<int>(c)));
        out << c << ',' << buf << '\n';
    }
    return out.str();
}

std::string tableToCHeader(const LinearisationTable& table, const TableImageInfo& info) {
    const std::vector<std::uint8_t> image = encodeTableImage(table, info);
    std::ostringstream out;
    out << "/* Probe mandrel linearisation table, generated by TrueTurn.\n"
        << " * ADC code -> deflection: deflection_nm = tt_lin_table[code] * TT_LIN_TABLE_SCALE_NM.\n"
        << " * Plane " << int(info.plane) << (info.plane == 0 ? " (X, radial)" : " (Y, tangential)")
        << ", fitted characteristic of degree " << int(info.degree) << ". */\n"
        << "#ifndef TT_LIN_TABLE_H\n#define TT_LIN_TABLE_H\n\n#include <stdint.h>\n\n"
        << "#define TT_LIN_TABLE_BITS " << table.adcBits << "\n"
        << "#define TT_LIN_TABLE_ENTRIES " << table.entries.size() << "u\n"
        << "#define TT_LIN_TABLE_SCALE_NM " << table.scaleNm << "\n"
        << "#define TT_LIN_TABLE_VERSION " << info.version << "u\n"
        << "#define TT_LIN_TABLE_CREATED " << info.createdUnixS << "LL\n"
        << "#define TT_LIN_TABLE_IMAGE_FORMAT " << int(kTableImageFormat) << "\n"
        << "#define TT_LIN_TABLE_IMAGE_CRC " << crcText(tableImageCrc(image)) << "u /* CRC-32C */\n\n"
        << "static const int16_t tt_lin_table[TT_LIN_TABLE_ENTRIES] = {\n";
    for (std::size_t c = 0; c < table.entries.size(); ++c) {
        if (c % 12 == 0) out << "   ";
        out << ' ' << table.entries[c] << (c + 1 < table.entries.size() ? "," : "");
        if (c % 12 == 11 || c + 1 == table.entries.size()) out << '\n';
    }
    out << "};\n\n#endif /* TT_LIN_TABLE_H */\n";
    return out.str();
}

}  // namespace tt::core
