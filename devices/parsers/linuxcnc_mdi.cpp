#include "devices/parsers/linuxcnc_mdi.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace tt::devices::linuxcnc {

namespace {

constexpr std::size_t kValuesPerWrite = 8;
constexpr std::size_t kValuesPerCheck = 5;
/// The written literal and what LinuxCNC holds are the same double; anything beyond this is a different value.
constexpr const char* kCheckTolerance = "0.0000001";
constexpr double kLargestMm = 1000.0;

void checkValue(double radialMm, const std::string& what) {
    if (!std::isfinite(radialMm) || std::fabs(radialMm) > kLargestMm)
        throw std::invalid_argument(what + " is not a number within 1000 mm");
}

/// The radial correction as the program reads it: in its units, doubled in diameter mode.
double programValue(double radialMm, const ProgramConventions& c) {
    const double value = c.inch ? radialMm / 25.4 : radialMm;
    return c.diameterMode ? 2.0 * value : value;
}

/// The radial mm LinuxCNC holds for a literal written in the program's units and X mode.
double heldMm(const std::string& literal, const ProgramConventions& c) {
    double value = std::strtod(literal.c_str(), nullptr);
    if (c.diameterMode) value /= 2.0;
    return c.inch ? value * 25.4 : value;
}

std::string modesOf(const ProgramConventions& c) {
    return std::string(c.inch ? "G20" : "G21") + (c.diameterMode ? " G7" : " G8");
}

/// `#<check>=[1/[[ABS[a-x]+ABS[b-y]...] LT tol]]` over `terms` ("#500-0.012300").
std::string checkLine(const std::vector<std::string>& terms) {
    std::string line = kCheckParameter;
    line += "=[1/[[";
    for (std::size_t i = 0; i < terms.size(); ++i) {
        if (i > 0) line += '+';
        line += "ABS[";
        line += terms[i];
        line += ']';
    }
    line += "] LT ";
    line += kCheckTolerance;
    line += "]]";
    return line;
}

}  // namespace

std::string sixDecimals(double value) {
    char text[48];
    std::snprintf(text, sizeof text, "%.6f", value);
    std::string s(text);
    if (s == "-0.000000") s = "0.000000";
    return s;
}

std::string parameterName(int number) {
    std::string name(1, '#');
    name += std::to_string(number);
    return name;
}

ParameterWrite parameterWrite(int first, std::span<const double> radialMm, std::int64_t token,
                              const ProgramConventions& conventions) {
    if (radialMm.empty()) throw std::invalid_argument("no corrections to write");
    const long last = static_cast<long>(first) + static_cast<long>(radialMm.size());  // the token's parameter
    if (first < kFirstFreeParameter || last > kLastFreeParameter)
        throw std::invalid_argument("the corrections need parameters #" + std::to_string(first) + " .. #" +
                                    std::to_string(last) + "; LinuxCNC programs may use #31 .. #5000");
    if (token < 1) throw std::invalid_argument("the part number written with the corrections must be at least 1");
    ParameterWrite w;
    std::vector<std::string> terms;
    std::string line;
    for (std::size_t i = 0; i < radialMm.size(); ++i) {
        const int number = first + static_cast<int>(i);
        checkValue(radialMm[i], "the correction for " + parameterName(number));
        const std::string literal = sixDecimals(programValue(radialMm[i], conventions));
        w.literals.push_back(literal);
        w.writtenMm.push_back(heldMm(literal, conventions));
        if (!line.empty()) line += ' ';
        line += parameterName(number);
        line += '=';
        line += literal;
        if ((i + 1) % kValuesPerWrite == 0 && i + 1 < radialMm.size()) {
            w.lines.push_back(line);
            line.clear();
        }
        terms.push_back(parameterName(number) + "-" + literal);
        if (terms.size() == kValuesPerCheck) {
            w.checks.push_back(checkLine(terms));
            terms.clear();
        }
    }
    const std::string tokenText = std::to_string(token);
    line += " " + parameterName(static_cast<int>(last)) + "=" + tokenText;
    w.lines.push_back(line);
    terms.push_back(parameterName(static_cast<int>(last)) + "-" + tokenText);
    w.checks.push_back(checkLine(terms));
    return w;
}

WearWrite wearWrite(int tool, int wearTool, double radialMm, const ProgramConventions& conventions) {
    if (tool < 1 || wearTool < 1) throw std::invalid_argument("tool numbers start at 1");
    checkValue(radialMm, "the wear correction");
    WearWrite w;
    w.modes = modesOf(conventions);
    w.literal = sixDecimals(programValue(radialMm, conventions));
    w.writtenMm = heldMm(w.literal, conventions);
    w.line = "G10 L1 P" + std::to_string(wearTool) + " X" + w.literal;
    // #5420 is the programmed X, a radius in the program's units whatever the X mode: applying the wear moves
    // the tool out by it, so the programmed X of the same machine position drops by the radial wear.
    const std::string radial = conventions.diameterMode ? "[" + w.literal + "/2]" : w.literal;
    w.verify = {"G43 H" + std::to_string(tool), std::string(kReferenceParameter) + "=#5420",
                "G43.2 H" + std::to_string(wearTool),
                checkLine({"[" + std::string(kReferenceParameter) + "-#5420]-" + radial})};
    return w;
}

std::string debugLine(const std::string& tag, std::span<const std::string> parameters) {
    std::string line = "(DEBUG,";
    line += tag;
    for (const std::string& p : parameters) {
        line += ' ';
        line += p;
    }
    line += ')';
    return line;
}

}  // namespace tt::devices::linuxcnc
