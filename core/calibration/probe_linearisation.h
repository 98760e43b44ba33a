#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/calibration/linearisation_table.h"
#include "core/model/scaled_polynomial.h"

namespace tt::core {

/// One calibration pair of the probe mandrel (paper 001, way 2): the reference deflection of the
/// bar from a dial indicator or micrometer, and the ADC code the mandrel read at it.
struct CalibrationPoint {
    double referenceUm = 0.0;  ///< reference deflection, µm (sign = direction in the bending plane)
    double adcCode = 0.0;      ///< ADC code (may be an average of several readings)
    int line = 0;              ///< source line in a file, 0 when typed or captured
};

/// Degree 0 asks for the automatic choice by cross-validation.
inline constexpr int kAutoDegree = 0;

/// Why a linearisation was refused.
enum class LinearisationProblem { BadInput, TooFewPoints, NonMonotonic, OutOfRange };

/// A refused calibration set or fit, with the reason in the user's terms.
class LinearisationRefused : public std::invalid_argument {
public:
    LinearisationRefused(LinearisationProblem problem, const std::string& message)
        : std::invalid_argument(message), m_problem(problem) {}
    LinearisationProblem problem() const { return m_problem; }

private:
    LinearisationProblem m_problem;
};

/// Cross-validation score of one candidate degree.
struct DegreeScore {
    int degree = 0;
    double cvRmsUm = 0.0;            ///< leave-one-out prediction error, RMS, µm
    double cvStandardErrorUm = 0.0;  ///< standard error of the mean squared LOO error, as µm (sqrt)
    double rmsResidualUm = 0.0;      ///< in-sample residual RMS, µm (always falls with degree)
};

/// Where the fitted characteristic stops being monotonic.
struct Monotonicity {
    bool monotonic = true;
    bool increasing = true;  ///< code grows with deflection
    std::optional<double> turningDeflectionUm;
    std::optional<double> turningCode;
    bool insideCalibratedRange = false;  ///< it turns between the points (else beyond them, within the ADC range)
    std::string message;                 ///< why it is not monotonic, empty when it is
};

/// How the degree of a fit was chosen, for the words of the wizard.
enum class DegreeChoice {
    Asked,                ///< the degree asked for
    LowestError,          ///< the lowest leave-one-out error of the degrees tried
    WithinStandardError,  ///< a lower degree within one standard error of the best
    WithinHalfCode,       ///< a lower degree within half an ADC code of the best
};

/// The fitted static characteristic code = p(deflection) of the inductive sensor (paper 001:
/// polynomial of degree 2..4).
struct CharacteristicFit {
    int degree = 0;
    bool chosenAutomatically = false;
    std::string choiceReason;  ///< how the degree was chosen, in English for the CLI
    DegreeChoice choice = DegreeChoice::Asked;
    int bestDegree = 0;               ///< the degree with the lowest leave-one-out error (auto)
    std::vector<DegreeScore> scores;  ///< every degree tried (auto) or just the one asked for
    int adcBits = 0;
    /// p: code as a polynomial of the deflection in µm (stored centred and scaled).
    ScaledPolynomial characteristic;
    /// p in power form: code = Σ c_i · deflection_µm^i, ascending powers.
    Eigen::VectorXd coefficients;
    double calibratedMinUm = 0.0;     ///< smallest reference deflection, µm
    double calibratedMaxUm = 0.0;     ///< largest reference deflection, µm
    std::vector<double> residualsUm;  ///< per point: fitted reading minus reference, µm
    double rmsResidualUm = 0.0;
    Monotonicity monotonicity;

    /// The fitted ADC code at a deflection, µm.
    double codeAt(double deflectionUm) const;
    /// The fitted slope d code / d deflection at a deflection, codes per µm.
    double slopeAt(double deflectionUm) const;
};

/// Calibration points a fit of `degree` needs (its coefficients and two degrees of freedom).
int pointsNeeded(int degree);
/// Different reference deflections a fit of `degree` needs.
int referencesNeeded(int degree);

/// Checks the points and fits the characteristic of the given degree (2, 3, 4) or, with
/// kAutoDegree, the degree with the best leave-one-out cross-validation under the one-standard-
/// error rule (Hastie, Tibshirani, Friedman, "The Elements of Statistical Learning", §7.10):
/// the lowest degree whose LOO error is within one standard error of the best — or within half an
/// ADC code, below which the ADC cannot tell the curves apart. Checks the
/// monotonicity over the ADC range. Throws LinearisationRefused for bad points (NaN, code
/// outside 0 .. 2^bits − 1, too few points or distinct references); a non-monotonic fit is
/// returned with monotonicity.monotonic == false (buildTable refuses it).
CharacteristicFit fitCharacteristic(const std::vector<CalibrationPoint>& points, int adcBits, int degree);

/// A complete linearisation: the fit, the table and its error figures.
struct Linearisation {
    CharacteristicFit fit;
    LinearisationTable table;
    double maxTableErrorUm = 0.0;       ///< max |table(code_i) − reference_i| over the points, µm
    double tableResolutionUm = 0.0;     ///< worst half step between adjacent codes + half a table unit, µm
    std::vector<double> tableErrorsUm;  ///< per point: table(code_i) − reference_i, µm
    int extrapolatedEntries = 0;        ///< codes whose deflection lies outside the calibrated range
    std::vector<std::string> warnings;  ///< e.g. much of the table is extrapolated
};

/// Builds the table from a monotonic fit: entry c = p⁻¹(c) on the monotonic branch holding the
/// calibration points. Throws LinearisationRefused (NonMonotonic) when the fit turns inside the
/// ADC range, with the code and deflection where it turns.
LinearisationTable buildTable(const CharacteristicFit& fit);

/// Above this share of extrapolated table entries a linearisation warns.
inline constexpr double kExtrapolatedWarningShare = 0.2;

/// fitCharacteristic + buildTable + the error figures.
Linearisation linearise(const std::vector<CalibrationPoint>& points, int adcBits, int degree);
/// buildTable + the error figures of a fit made from `points` (throws as buildTable).
Linearisation lineariseFit(CharacteristicFit fit, const std::vector<CalibrationPoint>& points);

}  // namespace tt::core
