#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tt::core {

/// Shape of a tool holder's cross-section.
enum class SectionShape { Round, Rectangular };

/// Cross-section of a boring bar or tool holder (paper 001, eq. 1).
/// Round: diameterMm. Rectangular: widthMm (b, across the radial force) × heightMm (h, along
/// the radial force), so the radial bending uses I = b h³ / 12.
struct HolderSection {
    SectionShape shape = SectionShape::Round;
    double diameterMm = 0.0;  ///< round section diameter d, mm
    double widthMm = 0.0;     ///< rectangular width b (perpendicular to the radial force), mm
    double heightMm = 0.0;    ///< rectangular height h (along the radial force), mm

    /// A round section of diameter d, mm.
    static HolderSection round(double diameterMm);
    /// A rectangular section b × h, mm (h along the radial cutting force).
    static HolderSection rectangular(double widthMm, double heightMm);
};

/// Bending plane of the holder: radial = the plane of the radial cutting force (X, bore
/// diameter), tangential = the plane of the main cutting force (Y).
enum class BendingPlane { Radial, Tangential };

/// Second moment of area of the section, mm⁴ (paper 001: round π d⁴ / 64, rectangular b h³ / 12
/// in the radial plane, h b³ / 12 in the tangential plane). Throws std::invalid_argument when a
/// dimension is not a positive finite number.
double secondMomentOfAreaMm4(const HolderSection& section, BendingPlane plane = BendingPlane::Radial);

/// Stiffness of a cantilever loaded at its free end, k = 3 E I / l³ (paper 001, eq. 1:
/// f = P l³ / (3 E I)), in N/mm for E in MPa (N/mm²), I in mm⁴ and l in mm.
/// Throws std::invalid_argument for non-positive or non-finite inputs.
double cantileverStiffnessNPerMm(double youngsModulusMpa, double secondMomentMm4, double overhangMm);

/// A holder material and its Young's modulus.
struct Material {
    std::string name;
    double youngsModulusMpa = 0.0;  ///< E, MPa (N/mm²)
};

/// The default materials list (editable by the user; the tool table stores E with each tool):
/// steel 210 000 MPa, tungsten heavy alloy 350 000 MPa, cemented carbide 600 000 MPa, grey cast
/// iron 110 000 MPa (typical handbook values of Young's modulus at room temperature).
std::vector<Material> defaultMaterials();

/// Plausible range of Young's modulus accepted for a holder material, MPa.
inline constexpr double kMinYoungsModulusMpa = 50'000.0;
/// Upper end of that range, MPa.
inline constexpr double kMaxYoungsModulusMpa = 800'000.0;

/// A stiffness measured on the machine (load and dial indicator), which overrides the
/// computed one; with when and by whom.
struct MeasuredStiffness {
    double stiffnessNPerMm = 0.0;
    std::string measuredOn;  ///< ISO date, "2025-03-14"
    std::string measuredBy;  ///< who measured it
};

/// One row of the tool stiffness table (paper 001: k_st "entered by the operator or computed",
/// k_p "found experimentally").
struct ToolRecord {
    std::string id;    ///< unique tool id, e.g. "T12"
    std::string name;  ///< free text, e.g. "Boring bar D80 L800"
    HolderSection section;
    double overhangMm = 0.0;  ///< overhang l from the clamp to the cutting edge, mm
    std::string material;     ///< material name (from the materials list)
    double youngsModulusMpa = 0.0;
    std::optional<MeasuredStiffness> measured;
    double currentToForceGainNPerA = 0.0;  ///< k_p of the cross-feed drive, N/A
};

/// k = 3 E I / l³ of the tool in `plane`, N/mm (ignores the measured override).
double computedStiffnessNPerMm(const ToolRecord& tool, BendingPlane plane = BendingPlane::Radial);

/// The stiffness the compensation uses in the radial plane: the measured one when present,
/// otherwise the computed one, N/mm.
double effectiveStiffnessNPerMm(const ToolRecord& tool);

/// Overhang-to-size ratio L/d (round) or L/h (rectangular).
double slendernessRatio(const ToolRecord& tool);

/// Every problem of the record in the user's terms ("overhang: 0 mm must be between 10 and
/// 3000 mm"); empty when the record is valid.
std::vector<std::string> validateTool(const ToolRecord& tool);

/// Text name of a section shape ("round", "rectangular"), used in files.
std::string toString(SectionShape shape);
/// Parses "round" / "rectangular"; throws std::invalid_argument otherwise.
SectionShape sectionShapeFromString(const std::string& text);

}  // namespace tt::core
