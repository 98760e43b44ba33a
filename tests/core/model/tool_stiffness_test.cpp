// Tool stiffness table: k = 3 E I / l³ (paper 001, eq. 1) against hand-calculated values.
#include "core/model/tool_stiffness.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace tt::core {
namespace {

TEST(ToolStiffness, RoundSectionBoringBarByHand) {
    // d = 80 mm: I = π · 80⁴ / 64 = π · 40 960 000 / 64 = π · 640 000 = 2 010 619.30 mm⁴.
    const HolderSection bar = HolderSection::round(80.0);
    EXPECT_NEAR(secondMomentOfAreaMm4(bar), 2'010'619.30, 0.01);
    // l = 800 mm, steel E = 210 000 MPa: k = 3 · 210 000 · 2 010 619.30 / 800³
    //   = 1.266 690 16e12 / 5.12e8 = 2474.004 N/mm.
    EXPECT_NEAR(cantileverStiffnessNPerMm(210'000.0, secondMomentOfAreaMm4(bar), 800.0), 2474.004, 0.001);
    // A round bar bends the same in both planes.
    EXPECT_DOUBLE_EQ(secondMomentOfAreaMm4(bar, BendingPlane::Tangential), secondMomentOfAreaMm4(bar));
}

TEST(ToolStiffness, RectangularSectionByHandInBothPlanes) {
    // b = 40 mm across the radial force, h = 60 mm along it: I = 40 · 60³ / 12 = 40 · 216 000 / 12 = 720 000 mm⁴.
    const HolderSection shank = HolderSection::rectangular(40.0, 60.0);
    EXPECT_DOUBLE_EQ(secondMomentOfAreaMm4(shank, BendingPlane::Radial), 720'000.0);
    // Tangential plane: I = 60 · 40³ / 12 = 60 · 64 000 / 12 = 320 000 mm⁴.
    EXPECT_DOUBLE_EQ(secondMomentOfAreaMm4(shank, BendingPlane::Tangential), 320'000.0);
    // l = 300 mm, E = 210 000 MPa: k = 630 000 · 720 000 / 27 000 000 = 16 800 N/mm exactly,
    // and 630 000 · 320 000 / 27 000 000 = 7 466.667 N/mm in the tangential plane.
    ToolRecord tool;
    tool.id = "T3";
    tool.section = shank;
    tool.overhangMm = 300.0;
    tool.youngsModulusMpa = 210'000.0;
    tool.currentToForceGainNPerA = 150.0;
    EXPECT_NEAR(computedStiffnessNPerMm(tool), 16'800.0, 1e-9);
    EXPECT_NEAR(computedStiffnessNPerMm(tool, BendingPlane::Tangential), 7'466.6667, 1e-4);
    EXPECT_DOUBLE_EQ(slendernessRatio(tool), 5.0);  // 300 / 60
}

TEST(ToolStiffness, StiffnessFallsWithTheCubeOfTheOverhang) {
    // Paper 001: stiffness is inversely proportional to the third power of the overhang.
    const double i = secondMomentOfAreaMm4(HolderSection::round(40.0));
    EXPECT_NEAR(cantileverStiffnessNPerMm(210'000.0, i, 200.0) / cantileverStiffnessNPerMm(210'000.0, i, 400.0), 8.0,
                1e-12);
    // A 300 N radial force on the D80 × 800 bar deflects it f = P / k = 300 / 2474.004 = 0.12126 mm.
    EXPECT_NEAR(300.0 / cantileverStiffnessNPerMm(210'000.0, secondMomentOfAreaMm4(HolderSection::round(80.0)), 800.0),
                0.12126, 1e-5);
}

TEST(ToolStiffness, MeasuredStiffnessOverridesTheComputedOne) {
    ToolRecord tool;
    tool.id = "T12";
    tool.section = HolderSection::round(80.0);
    tool.overhangMm = 800.0;
    tool.youngsModulusMpa = 210'000.0;
    tool.currentToForceGainNPerA = 150.0;
    EXPECT_NEAR(effectiveStiffnessNPerMm(tool), 2474.004, 0.001);
    tool.measured = MeasuredStiffness{2300.0, "2025-03-14", "I. Petrenko"};
    EXPECT_DOUBLE_EQ(effectiveStiffnessNPerMm(tool), 2300.0);
    EXPECT_TRUE(validateTool(tool).empty());
}

TEST(ToolStiffness, ValidationNamesEveryProblemWithUnits) {
    ToolRecord tool;
    tool.section = HolderSection::round(0.0);
    tool.overhangMm = 0.0;
    tool.youngsModulusMpa = 1.0;
    tool.currentToForceGainNPerA = -1.0;
    tool.measured = MeasuredStiffness{-5.0, "14.03.2025", ""};
    const std::vector<std::string> problems = validateTool(tool);
    ASSERT_EQ(problems.size(), 8u);
    EXPECT_EQ(problems[0], "id: must not be empty");
    EXPECT_EQ(problems[1], "diameter d: 0 mm must be between 5 and 500 mm");
    EXPECT_EQ(problems[2], "overhang l: 0 mm must be between 10 and 5000 mm");
    EXPECT_EQ(problems[3], "Young's modulus E: 1 MPa must be between 50000 and 800000 MPa");
    EXPECT_NE(problems[4].find("k_p"), std::string::npos);
    EXPECT_NE(problems[5].find("measured stiffness"), std::string::npos);
    EXPECT_EQ(problems[6], "measured on: '14.03.2025' is not a date like 2025-03-14");
    EXPECT_EQ(problems[7], "measured by: must name who measured the stiffness");
}

TEST(ToolStiffness, RefusesNonPhysicalInputs) {
    EXPECT_THROW(secondMomentOfAreaMm4(HolderSection::round(-1.0)), std::invalid_argument);
    EXPECT_THROW(secondMomentOfAreaMm4(HolderSection::rectangular(10.0, 0.0)), std::invalid_argument);
    EXPECT_THROW(cantileverStiffnessNPerMm(210'000.0, 1000.0, 0.0), std::invalid_argument);
    EXPECT_THROW(cantileverStiffnessNPerMm(std::numeric_limits<double>::quiet_NaN(), 1000.0, 100.0),
                 std::invalid_argument);
    EXPECT_THROW(sectionShapeFromString("square"), std::invalid_argument);
    EXPECT_EQ(sectionShapeFromString(toString(SectionShape::Rectangular)), SectionShape::Rectangular);
}

TEST(ToolStiffness, DefaultMaterialsHaveHandbookModuli) {
    const std::vector<Material> materials = defaultMaterials();
    ASSERT_GE(materials.size(), 3u);
    EXPECT_EQ(materials[0].name, "Steel");
    EXPECT_DOUBLE_EQ(materials[0].youngsModulusMpa, 210'000.0);
    for (const Material& m : materials) {
        EXPECT_GE(m.youngsModulusMpa, kMinYoungsModulusMpa);
        EXPECT_LE(m.youngsModulusMpa, kMaxYoungsModulusMpa);
    }
}

}  // namespace
}  // namespace tt::core
