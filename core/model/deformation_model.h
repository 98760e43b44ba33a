#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/model/polynomial_regression.h"
#include "core/model/scaled_polynomial.h"

namespace tt::core {

/// The three factors of the force-deformation model (paper 004, eq. (1)).
enum class DeformationFactor { Depth = 0, Feed = 1, Axial = 2 };

/// One term of the model: a^i f^j z^k in the coded variables (exponents 0..3).
struct DeformationTerm {
    int depthPower = 0;  ///< i, power of the coded depth of cut a
    int feedPower = 0;   ///< j, power of the coded feed f
    int axialPower = 0;  ///< k, power of the coded axial coordinate z

    /// "1", "a", "f*z", "a*f*z^2", ... (the coded variables).
    std::string name() const;
    /// Total degree i + j + k.
    int degree() const { return depthPower + feedPower + axialPower; }
    /// Same exponents.
    bool operator==(const DeformationTerm&) const = default;
};

/// Which terms a fit starts from (before any stepwise removal).
enum class DeformationTermSet {
    Linear,        ///< 1, a, f, z
    Interactions,  ///< linear plus every product of different factors: af, az, fz, afz
    Quadratic,     ///< the full quadratic: 1, a, f, z, a², f², z², af, az, fz
    CubicZ,        ///< the full quadratic in a and f (1, a, f, a², f², af) times 1, z, z², z³ (24 terms)
    CubicFZ,       ///< at one depth of cut: 1, f, f², f³ times 1, z, z², z³ (16 terms, no a)
};

/// The terms of a set, intercept first.
std::vector<DeformationTerm> deformationTerms(DeformationTermSet set);
/// "linear", "interactions", "quadratic", "cubic-z", "cubic-fz".
std::string deformationTermSetName(DeformationTermSet set);
/// The set named `name` (as deformationTermSetName); throws std::invalid_argument listing the names.
DeformationTermSet deformationTermSetFromName(const std::string& name);

/// How a factor is coded for the regression: x = (value - centre) / halfRange, so the experiment's
/// range maps to [-1, 1]; min and max are the range the model was fitted on (its validity). A factor
/// held at one value (min = max, a model of one depth of cut) is coded 0 there and no term may use it.
struct FactorCoding {
    double centre = 0.0;     ///< natural units (mm, mm/rev, mm)
    double halfRange = 1.0;  ///< natural units, > 0
    double min = -1.0;       ///< smallest value in the experiment
    double max = 1.0;        ///< largest value in the experiment

    /// The coding of values spanning [lo, hi]; throws std::invalid_argument unless lo < hi, both finite.
    static FactorCoding spanning(double lo, double hi);
    /// The coding of a factor held at `value` (min = max = centre = value, half range 1); throws
    /// std::invalid_argument unless the value is finite.
    static FactorCoding at(double value);
    /// Whether the factor was held at one value (min = max).
    bool fixed() const { return min == max; }
    /// (value - centre) / halfRange.
    double coded(double value) const { return (value - centre) / halfRange; }
};

/// The force-deformation model Y(a, f, z) of paper 004, eq. (1): Y in µm, depth of cut a in mm, feed f
/// in mm/rev, axial coordinate z in mm, a polynomial in the coded factors. Immutable.
class DeformationModel {
public:
    /// Throws std::invalid_argument when the terms and coefficients differ in number, the first term
    /// is not the intercept, a term repeats, an exponent is outside 0..3, a value is not finite, or a
    /// term uses a factor held at one value.
    DeformationModel(std::array<FactorCoding, 3> coding, std::vector<DeformationTerm> terms,
                     Eigen::VectorXd coefficients);

    /// Y(a, f, z), µm.
    double deformationUm(double depthMm, double feedMmPerRev, double zMm) const;
    /// Y along z at fixed a and f, as a polynomial in z (mm) -> µm.
    ScaledPolynomial alongAxis(double depthMm, double feedMmPerRev) const;
    /// Y against the feed at fixed a and z, as a polynomial in f (mm/rev) -> µm.
    ScaledPolynomial againstFeed(double depthMm, double zMm) const;

    /// The design row of the model's terms at (a, f, z) (coded powers).
    Eigen::VectorXd termRow(double depthMm, double feedMmPerRev, double zMm) const;

    /// The terms, intercept first.
    const std::vector<DeformationTerm>& terms() const { return m_terms; }
    /// Coefficients in the coded variables, µm, one per term.
    const Eigen::VectorXd& coefficients() const { return m_coefficients; }
    /// The coding (and fitted range) of a factor.
    const FactorCoding& coding(DeformationFactor factor) const { return m_coding[static_cast<std::size_t>(factor)]; }
    /// The codings of a, f and z, in that order.
    const std::array<FactorCoding, 3>& codings() const { return m_coding; }

private:
    ScaledPolynomial slice(DeformationFactor free, double depthMm, double feedMmPerRev, double zMm) const;

    std::array<FactorCoding, 3> m_coding;
    std::vector<DeformationTerm> m_terms;
    Eigen::VectorXd m_coefficients;
};

/// Measured deformations: one row (a, f, z, Y) per measurement.
struct DeformationSamples {
    Eigen::VectorXd depthMm;
    Eigen::VectorXd feedMmPerRev;
    Eigen::VectorXd zMm;
    Eigen::VectorXd deformationUm;

    /// Number of rows; throws std::invalid_argument when the columns differ in length.
    Eigen::Index size() const;
};

/// A term removed by the stepwise elimination, with its |t| when it was removed.
struct RemovedTerm {
    DeformationTerm term;
    double tValue = 0.0;
};

/// A fitted force-deformation model with the statistics of its regression.
struct DeformationFit {
    DeformationModel model;
    LinearRegression regression;  ///< R², adjusted R², F, standard errors and t-values per term, sigma
    DeformationTermSet termSet = DeformationTermSet::CubicZ;
    bool stepwise = false;
    std::vector<RemovedTerm> removed;  ///< in the order of removal

    /// Residual 2σ, µm: the band the model states for a new measurement.
    double twoSigmaUm() const { return 2.0 * regression.residualSigma; }
};

/// Fits Y(a, f, z) by least squares (fitLinearRegression) on the terms of `set` in the coded factors.
/// With `stepwise`, backward elimination: while a term other than the intercept has |t| below
/// t(0.975; n-p), the one with the smallest |t| is removed and the model refitted. A factor that no
/// term of the set uses (the depth in "cubic-fz") may have one level: the model is then valid at that
/// value only. Throws std::invalid_argument naming the problem: too few rows, a value not finite or
/// outside its limits (a in (0, 20] mm, f in (0, 5] mm/rev, |z| <= 10000 mm, |Y| <= 1e6 µm), a factor
/// a term uses with one level only, or a term the levels cannot separate (a² needs three depths, z³
/// four positions).
DeformationFit fitDeformationModel(const DeformationSamples& samples, DeformationTermSet set, bool stepwise);

/// As fitDeformationModel, with the coding (and so the validity range) given instead of taken from the
/// data: the region a targeted experiment was planned for (every sample must lie inside it; a factor no
/// term uses may be held at one value). Throws std::invalid_argument as fitDeformationModel does, and
/// naming the first sample outside the region.
DeformationFit fitDeformationModel(const DeformationSamples& samples, DeformationTermSet set, bool stepwise,
                                   const std::array<FactorCoding, 3>& region);

}  // namespace tt::core
