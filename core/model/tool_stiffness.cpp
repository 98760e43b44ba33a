#include "core/model/tool_stiffness.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

constexpr double kMinSectionMm = 5.0;
constexpr double kMaxSectionMm = 500.0;
constexpr double kMinOverhangMm = 10.0;
constexpr double kMaxOverhangMm = 5000.0;
constexpr double kMaxGainNPerA = 1.0e6;
constexpr double kMaxStiffnessNPerMm = 1.0e8;

void requirePositive(double value, const char* what) {
    if (!std::isfinite(value) || value <= 0.0)
        throw std::invalid_argument(std::string(what) + " must be a positive number");
}

bool within(double v, double lo, double hi) {
    return std::isfinite(v) && v >= lo && v <= hi;
}

std::string rangeProblem(const std::string& what, double v, double lo, double hi, const std::string& unit) {
    return what + ": " + (std::isfinite(v) ? formatSignificant(v, 6) + " " + unit : std::string("not a number")) +
           " must be between " + formatSignificant(lo, 6) + " and " + formatSignificant(hi, 6) + " " + unit;
}

bool isIsoDate(const std::string& s) {
    if (s.size() != 10 || s[4] != '-' || s[7] != '-') return false;
    for (std::size_t i : {0u, 1u, 2u, 3u, 5u, 6u, 8u, 9u})
        if (s[i] < '0' || s[i] > '9') return false;
    const int month = std::stoi(s.substr(5, 2));
    const int day = std::stoi(s.substr(8, 2));
    return month >= 1 && month <= 12 && day >= 1 && day <= 31;
}

}  // namespace

HolderSection HolderSection::round(double diameterMm) {
    HolderSection s;
    s.shape = SectionShape::Round;
    s.diameterMm = diameterMm;
    return s;
}

HolderSection HolderSection::rectangular(double widthMm, double heightMm) {
    HolderSection s;
    s.shape = SectionShape::Rectangular;
    s.widthMm = widthMm;
    s.heightMm = heightMm;
    return s;
}

double secondMomentOfAreaMm4(const HolderSection& section, BendingPlane plane) {
    if (section.shape == SectionShape::Round) {
        requirePositive(section.diameterMm, "section diameter");
        return std::numbers::pi * std::pow(section.diameterMm, 4) / 64.0;
    }
    requirePositive(section.widthMm, "section width b");
    requirePositive(section.heightMm, "section height h");
    const double along = plane == BendingPlane::Radial ? section.heightMm : section.widthMm;
    const double across = plane == BendingPlane::Radial ? section.widthMm : section.heightMm;
    return across * along * along * along / 12.0;
}

double cantileverStiffnessNPerMm(double youngsModulusMpa, double secondMomentMm4, double overhangMm) {
    requirePositive(youngsModulusMpa, "Young's modulus");
    requirePositive(secondMomentMm4, "second moment of area");
    requirePositive(overhangMm, "overhang");
    return 3.0 * youngsModulusMpa * secondMomentMm4 / (overhangMm * overhangMm * overhangMm);
}

std::vector<Material> defaultMaterials() {
    return {{"Steel", 210'000.0},
            {"Tungsten heavy alloy", 350'000.0},
            {"Cemented carbide", 600'000.0},
            {"Grey cast iron", 110'000.0}};
}

double computedStiffnessNPerMm(const ToolRecord& tool, BendingPlane plane) {
    return cantileverStiffnessNPerMm(tool.youngsModulusMpa, secondMomentOfAreaMm4(tool.section, plane),
                                     tool.overhangMm);
}

double effectiveStiffnessNPerMm(const ToolRecord& tool) {
    if (tool.measured) {
        requirePositive(tool.measured->stiffnessNPerMm, "measured stiffness");
        return tool.measured->stiffnessNPerMm;
    }
    return computedStiffnessNPerMm(tool);
}

double slendernessRatio(const ToolRecord& tool) {
    const double size = tool.section.shape == SectionShape::Round ? tool.section.diameterMm : tool.section.heightMm;
    requirePositive(size, "section size");
    return tool.overhangMm / size;
}

std::vector<std::string> validateTool(const ToolRecord& tool) {
    std::vector<std::string> problems;
    if (tool.id.empty()) problems.push_back("id: must not be empty");
    if (tool.section.shape == SectionShape::Round) {
        if (!within(tool.section.diameterMm, kMinSectionMm, kMaxSectionMm))
            problems.push_back(rangeProblem("diameter d", tool.section.diameterMm, kMinSectionMm, kMaxSectionMm, "mm"));
    } else {
        if (!within(tool.section.widthMm, kMinSectionMm, kMaxSectionMm))
            problems.push_back(rangeProblem("width b", tool.section.widthMm, kMinSectionMm, kMaxSectionMm, "mm"));
        if (!within(tool.section.heightMm, kMinSectionMm, kMaxSectionMm))
            problems.push_back(rangeProblem("height h", tool.section.heightMm, kMinSectionMm, kMaxSectionMm, "mm"));
    }
    if (!within(tool.overhangMm, kMinOverhangMm, kMaxOverhangMm))
        problems.push_back(rangeProblem("overhang l", tool.overhangMm, kMinOverhangMm, kMaxOverhangMm, "mm"));
    if (!within(tool.youngsModulusMpa, kMinYoungsModulusMpa, kMaxYoungsModulusMpa))
        problems.push_back(rangeProblem("Young's modulus E", tool.youngsModulusMpa, kMinYoungsModulusMpa,
                                        kMaxYoungsModulusMpa, "MPa"));
    if (!(std::isfinite(tool.currentToForceGainNPerA) && tool.currentToForceGainNPerA > 0.0 &&
          tool.currentToForceGainNPerA <= kMaxGainNPerA))
        problems.push_back("k_p: " + formatSignificant(tool.currentToForceGainNPerA, 6) +
                           " N/A must be above 0 and at most " + formatSignificant(kMaxGainNPerA, 6) + " N/A");
    if (tool.measured) {
        const MeasuredStiffness& m = *tool.measured;
        if (!(std::isfinite(m.stiffnessNPerMm) && m.stiffnessNPerMm > 0.0 && m.stiffnessNPerMm <= kMaxStiffnessNPerMm))
            problems.push_back("measured stiffness: " + formatSignificant(m.stiffnessNPerMm, 6) +
                               " N/mm must be above 0 and at most " + formatSignificant(kMaxStiffnessNPerMm, 6) +
                               " N/mm");
        if (!isIsoDate(m.measuredOn))
            problems.push_back("measured on: '" + m.measuredOn + "' is not a date like 2025-03-14");
        if (m.measuredBy.empty()) problems.push_back("measured by: must name who measured the stiffness");
    }
    return problems;
}

std::string toString(SectionShape shape) {
    return shape == SectionShape::Round ? "round" : "rectangular";
}

SectionShape sectionShapeFromString(const std::string& text) {
    if (text == "round") return SectionShape::Round;
    if (text == "rectangular") return SectionShape::Rectangular;
    throw std::invalid_argument("section '" + text + "' must be 'round' or 'rectangular'");
}

}  // namespace tt::core
