#include "core/quality/iso286.h"

#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

constexpr std::size_t kRanges = 13;

/// Upper ends of the nominal size ranges of ISO 286-1:2010 Tables 1 and 2 (main ranges), mm.
constexpr std::array<double, kRanges> kRangeUpperMm = {3, 6, 10, 18, 30, 50, 80, 120, 180, 250, 315, 400, 500};

/// ISO 286-1:2010 Table 1: standard tolerances IT1..IT18 in micrometres per range.
constexpr std::array<std::array<double, kRanges>, 18> kItUm = {{
    {0.8, 1, 1, 1.2, 1.5, 1.5, 2, 2.5, 3.5, 4.5, 6, 7, 8},
    {1.2, 1.5, 1.5, 2, 2.5, 2.5, 3, 4, 5, 7, 8, 9, 10},
    {2, 2.5, 2.5, 3, 4, 4, 5, 6, 8, 10, 12, 13, 15},
    {3, 4, 4, 5, 6, 7, 8, 10, 12, 14, 16, 18, 20},
    {4, 5, 6, 8, 9, 11, 13, 15, 18, 20, 23, 25, 27},
    {6, 8, 9, 11, 13, 16, 19, 22, 25, 29, 32, 36, 40},
    {10, 12, 15, 18, 21, 25, 30, 35, 40, 46, 52, 57, 63},
    {14, 18, 22, 27, 33, 39, 46, 54, 63, 72, 81, 89, 97},
    {25, 30, 36, 43, 52, 62, 74, 87, 100, 115, 130, 140, 155},
    {40, 48, 58, 70, 84, 100, 120, 140, 160, 185, 210, 230, 250},
    {60, 75, 90, 110, 130, 160, 190, 220, 250, 290, 320, 360, 400},
    {100, 120, 150, 180, 210, 250, 300, 350, 400, 460, 520, 570, 630},
    {140, 180, 220, 270, 330, 390, 460, 540, 630, 720, 810, 890, 970},
    {250, 300, 360, 430, 520, 620, 740, 870, 1000, 1150, 1300, 1400, 1550},
    {400, 480, 580, 700, 840, 1000, 1200, 1400, 1600, 1850, 2100, 2300, 2500},
    {600, 750, 900, 1100, 1300, 1600, 1900, 2200, 2500, 2900, 3200, 3600, 4000},
    {1000, 1200, 1500, 1800, 2100, 2500, 3000, 3500, 4000, 4600, 5200, 5700, 6300},
    {1400, 1800, 2200, 2700, 3300, 3900, 4600, 5400, 6300, 7200, 8100, 8900, 9700},
}};

/// ISO 286-1:2010 Table 2 (shafts), fundamental deviations in micrometres per range: the upper deviation es
/// of d..h, the lower deviation ei of m, n, p; k is +ei only for grades 4..7 (0 otherwise and up to 3 mm).
struct Letter {
    const char* name;
    bool upper;  ///< the table gives es (else ei)
    std::array<double, kRanges> deviationUm;
};
constexpr std::array<Letter, 9> kLetters = {{
    {"d", true, {-20, -30, -40, -50, -65, -80, -100, -120, -145, -170, -190, -210, -230}},
    {"e", true, {-14, -20, -25, -32, -40, -50, -60, -72, -85, -100, -110, -125, -135}},
    {"f", true, {-6, -10, -13, -16, -20, -25, -30, -36, -43, -50, -56, -62, -68}},
    {"g", true, {-2, -4, -5, -6, -7, -9, -10, -12, -14, -15, -17, -18, -20}},
    {"h", true, {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}},
    {"k", false, {0, 1, 1, 1, 2, 2, 2, 3, 3, 4, 4, 4, 5}},
    {"m", false, {2, 4, 6, 7, 8, 9, 11, 13, 15, 17, 20, 21, 23}},
    {"n", false, {4, 8, 10, 12, 15, 17, 20, 23, 27, 31, 34, 37, 40}},
    {"p", false, {6, 12, 15, 18, 22, 26, 32, 37, 43, 50, 56, 62, 68}},
}};

std::size_t rangeOf(double nominalMm) {
    if (!std::isfinite(nominalMm) || nominalMm <= 0.0 || nominalMm > kMaxIso286NominalMm)
        throw std::invalid_argument("the ISO 286 tables here cover nominal sizes over 0 up to 500 mm, not " +
                                    formatSignificant(nominalMm, 6) + " mm");
    std::size_t r = 0;
    while (nominalMm > kRangeUpperMm[r])
        ++r;
    return r;
}

}  // namespace

double iso286StandardToleranceMm(int grade, double nominalMm) {
    if (grade < 1 || grade > 18)
        throw std::invalid_argument("ISO 286 standard tolerance grade IT" + std::to_string(grade) +
                                    " is not covered (IT1 .. IT18)");
    return kItUm[static_cast<std::size_t>(grade - 1)][rangeOf(nominalMm)] / 1000.0;
}

ToleranceZone iso286ShaftZone(double nominalMm, const std::string& toleranceClass) {
    const std::string where = "tolerance class '" + toleranceClass + "': ";
    std::size_t digits = 0;
    while (digits < toleranceClass.size() && std::isalpha(static_cast<unsigned char>(toleranceClass[digits])))
        ++digits;
    const std::string letter = toleranceClass.substr(0, digits);
    const std::string gradeText = toleranceClass.substr(digits);
    if (letter.empty() || gradeText.empty() || gradeText.size() > 2 ||
        gradeText.find_first_not_of("0123456789") != std::string::npos)
        throw std::invalid_argument(where + "expected a shaft letter and a grade, such as h9 or js7");
    if (std::isupper(static_cast<unsigned char>(letter[0])))
        throw std::invalid_argument(where +
                                    "capital letters are hole classes; a turned shaft takes a shaft class "
                                    "such as h9");
    const int grade = std::stoi(gradeText);
    double itMm = 0.0;
    try {
        itMm = iso286StandardToleranceMm(grade, nominalMm);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(where + e.what());
    }
    ToleranceZone zone{nominalMm, 0.0, 0.0};
    if (letter == "js") {
        double itUm = std::round(itMm * 1000.0 * 10.0) / 10.0;
        if (grade >= 7 && grade <= 11 && std::fmod(itUm, 2.0) == 1.0) itUm -= 1.0;
        zone.upperDeviationMm = itUm / 2000.0;
        zone.lowerDeviationMm = -itUm / 2000.0;
        return zone;
    }
    const std::size_t range = rangeOf(nominalMm);
    for (const Letter& l : kLetters) {
        if (letter != l.name) continue;
        double deviationUm = l.deviationUm[range];
        if (letter == "k" && (grade < 4 || grade > 7)) deviationUm = 0.0;
        if (l.upper) {
            zone.upperDeviationMm = deviationUm / 1000.0;
            zone.lowerDeviationMm = zone.upperDeviationMm - itMm;
        } else {
            zone.lowerDeviationMm = deviationUm / 1000.0;
            zone.upperDeviationMm = zone.lowerDeviationMm + itMm;
        }
        return zone;
    }
    throw std::invalid_argument(where + "the shaft letter '" + letter +
                                "' is not in the tables here (d, e, f, g, h, js, k, m, n, p)");
}

}  // namespace tt::core
