#include "devices/parsers/gauge_ascii.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tt::devices {

namespace {

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

std::string printable(std::string_view text) {
    std::string out;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u < 0x7F) {
            out.push_back(c);
        } else {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02X", u);
            out += hex;
        }
    }
    return out;
}

/// Strips an optional unit suffix ("mm", "in", with or without a space before it).
std::optional<LengthUnit> takeUnitSuffix(std::string_view& body) {
    auto strip = [&](std::string_view suffix) {
        if (body.size() < suffix.size()) return false;
        const std::string_view tail = body.substr(body.size() - suffix.size());
        for (std::size_t i = 0; i < suffix.size(); ++i)
            if ((tail[i] | 0x20) != suffix[i]) return false;
        body.remove_suffix(suffix.size());
        while (!body.empty() && body.back() == ' ')
            body.remove_suffix(1);
        return true;
    };
    if (strip("mm")) return LengthUnit::Millimetre;
    if (strip("in")) return LengthUnit::Inch;
    return std::nullopt;
}

}  // namespace

ParseResult<AsciiGaugeFrame> parseAsciiGaugeLine(std::string_view line) {
    using Result = ParseResult<AsciiGaugeFrame>;
    const std::string shown = printable(line.substr(0, 32));
    if (line.size() < 5) return Result::failure("gauge line '" + shown + "' is too short");
    if (line.size() > 24) return Result::failure("gauge line '" + shown + "...' is too long");
    if (!isDigit(line[0]) || !isDigit(line[1]))
        return Result::failure("gauge line '" + shown + "' does not start with a two-digit channel");
    if (line[2] < 'A' || line[2] > 'Z')
        return Result::failure("gauge line '" + shown + "' has no measurement item letter at position 3");
    if (line[3] != '+' && line[3] != '-')
        return Result::failure("gauge line '" + shown + "' has sign '" + printable(line.substr(3, 1)) +
                               "', expected '+' or '-'");
    std::string_view body = line.substr(4);
    AsciiGaugeFrame frame;
    frame.unit = takeUnitSuffix(body);
    if (body.empty() || body.size() > 12)
        return Result::failure("gauge line '" + shown + "' has a value field of " + std::to_string(body.size()) +
                               " characters, expected 1 to 12");
    double magnitude = 0.0;
    int decimals = -1;
    int digits = 0;
    for (const char c : body) {
        if (c == '.') {
            if (decimals >= 0) return Result::failure("gauge line '" + shown + "' has two decimal points");
            decimals = 0;
            continue;
        }
        if (!isDigit(c))
            return Result::failure("gauge line '" + shown + "' has '" + printable(std::string_view(&c, 1)) +
                                   "' in its value, expected digits");
        magnitude = magnitude * 10.0 + (c - '0');
        ++digits;
        if (decimals >= 0) ++decimals;
    }
    if (digits == 0) return Result::failure("gauge line '" + shown + "' has no digits in its value");
    if (decimals < 0) decimals = 0;
    frame.channel = (line[0] - '0') * 10 + (line[1] - '0');
    frame.item = line[2];
    frame.decimals = decimals;
    frame.value = (line[3] == '-' ? -1.0 : 1.0) * magnitude / std::pow(10.0, decimals);
    return Result::success(frame);
}

std::string formatAsciiGaugeLine(double value, int decimals, int width, int channel, char item,
                                 std::optional<LengthUnit> unitSuffix) {
    if (!std::isfinite(value)) throw std::invalid_argument("gauge line: the value is not a finite number");
    if (decimals < 0 || decimals > 6) throw std::invalid_argument("gauge line: decimals must be 0 to 6");
    if (width < 1 || width > 12) throw std::invalid_argument("gauge line: the value width must be 1 to 12");
    if (channel < 0 || channel > 99) throw std::invalid_argument("gauge line: the channel must be 0 to 99");
    if (item < 'A' || item > 'Z') throw std::invalid_argument("gauge line: the item must be a letter A to Z");
    char number[64];
    std::snprintf(number, sizeof number, "%0*.*f", width, decimals, std::fabs(value));
    const std::string digits(number);
    if (static_cast<int>(digits.size()) > width)
        throw std::invalid_argument("gauge line: " + digits + " does not fit " + std::to_string(width) + " characters");
    const bool negative = std::signbit(value) && std::stod(digits) != 0.0;
    char head[8];
    std::snprintf(head, sizeof head, "%02d%c%c", channel, item, negative ? '-' : '+');
    std::string line = head + digits;
    if (unitSuffix) line += std::string(unitSymbol(*unitSuffix));
    line.push_back('\r');
    return line;
}

}  // namespace tt::devices
