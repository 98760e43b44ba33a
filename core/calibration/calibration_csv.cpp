#include "core/calibration/calibration_csv.h"

#include "core/common/text_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace tt::core {

namespace {

/// Why "12,5" is refused: numbers are read in the C locale only.
const std::string kCommaDecimal = kCLocaleNote;

/// Refuses a header column other than reference_um and adc_code (it would be silently ignored).
void requireKnownColumns(const std::vector<std::string_view>& names, std::size_t line) {
    for (std::string_view name : names)
        if (name != "reference_um" && name != "adc_code")
            throw std::invalid_argument("line " + std::to_string(line) + ": unknown column '" + std::string(name) +
                                        "'; a calibration file has only the columns reference_um and adc_code");
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> split(std::string_view line, char separator) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = line.find(separator, start);
        fields.push_back(trim(line.substr(start, end == std::string_view::npos ? end : end - start)));
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    return fields;
}

double parseNumber(std::string_view field, std::size_t line, const char* column) {
    double value = 0.0;
    const char* first = field.data();
    const char* last = field.data() + field.size();
    if (!field.empty() && *first == '+') ++first;
    const auto [ptr, ec] = std::from_chars(first, last, value);
    if (field.empty() || ec != std::errc() || ptr != last || !std::isfinite(value))
        throw std::invalid_argument("line " + std::to_string(line) + ": " + column + " '" + std::string(field) +
                                    "' is not a number" +
                                    (field.find(',') != std::string_view::npos ? kCommaDecimal : ""));
    return value;
}

}  // namespace

std::vector<CalibrationPoint> parseCalibrationCsv(std::string_view text) {
    std::vector<CalibrationPoint> points;
    std::size_t lineNumber = 0;
    std::size_t columns = 0;
    int referenceColumn = -1;
    int codeColumn = -1;
    char separator = ',';
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte order mark
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t end = text.find('\n', pos);
        const std::string_view raw =
            text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
        pos = end == std::string_view::npos ? text.size() + 1 : end + 1;
        ++lineNumber;
        const std::string_view line = trim(raw);
        if (line.empty() || line.front() == '#') continue;
        if (referenceColumn < 0) {
            separator =
                line.find(';') != std::string_view::npos && line.find(',') == std::string_view::npos ? ';' : ',';
            const std::vector<std::string_view> names = split(line, separator);
            for (std::size_t i = 0; i < names.size(); ++i) {
                if (names[i] == "reference_um") referenceColumn = static_cast<int>(i);
                if (names[i] == "adc_code") codeColumn = static_cast<int>(i);
            }
            if (referenceColumn < 0 || codeColumn < 0)
                throw std::invalid_argument("line " + std::to_string(lineNumber) +
                                            ": the header must name the columns reference_um and adc_code, got '" +
                                            std::string(line) + "'");
            requireKnownColumns(names, lineNumber);
            columns = names.size();
            continue;
        }
        const std::vector<std::string_view> fields = split(line, separator);
        const std::size_t needed = static_cast<std::size_t>(std::max(referenceColumn, codeColumn)) + 1;
        if (fields.size() > columns)
            throw std::invalid_argument("line " + std::to_string(lineNumber) + ": " + std::to_string(fields.size()) +
                                        " fields, the header names " + std::to_string(columns) +
                                        (separator == ',' ? kCommaDecimal : std::string()));
        if (fields.size() < needed)
            throw std::invalid_argument("line " + std::to_string(lineNumber) + ": expected " + std::to_string(needed) +
                                        " columns, got " + std::to_string(fields.size()));
        CalibrationPoint p;
        p.referenceUm = parseNumber(fields[static_cast<std::size_t>(referenceColumn)], lineNumber, "reference_um");
        p.adcCode = parseNumber(fields[static_cast<std::size_t>(codeColumn)], lineNumber, "adc_code");
        p.line = static_cast<int>(std::min<std::size_t>(lineNumber, std::numeric_limits<int>::max()));
        points.push_back(p);
    }
    if (referenceColumn < 0) throw std::invalid_argument("the file is empty: expected a header reference_um,adc_code");
    if (points.empty()) throw std::invalid_argument("the file has a header but no calibration points");
    return points;
}

std::string calibrationCsv(const std::vector<CalibrationPoint>& points) {
    std::ostringstream out;
    out.precision(10);
    out << "reference_um,adc_code\n";
    for (const CalibrationPoint& p : points)
        out << p.referenceUm << ',' << p.adcCode << '\n';
    return out.str();
}

}  // namespace tt::core
