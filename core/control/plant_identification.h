#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/control/input_arma_fit.h"

namespace tt::core {

/// The closed-loop record of a run as the identification reads it: consecutive parts from `firstPart`, for each
/// the radial correction sent to the CNC for it (mm, one per control point) and the measured diameter deviation
/// the controller used (mm; NaN: no reading, or one the loop or the controller rejected).
struct LoopHistory {
    std::int64_t firstPart = 1;
    std::vector<Eigen::VectorXd> appliedMm;
    std::vector<Eigen::VectorXd> deviationMm;

    /// Number of parts held.
    std::size_t size() const { return appliedMm.size(); }
};

/// Which information criterion chooses the ARMA orders and the delay (Akaike 1974; Schwarz 1978).
enum class InformationCriterion { Aic, Bic };

/// "aic", "bic"; and back (throws std::invalid_argument for another name).
const char* informationCriterionName(InformationCriterion criterion);
InformationCriterion informationCriterionFromName(const std::string& name);

/// What the identification may choose and when it refuses.
struct PlantIdentificationOptions {
    int loopDelay = 1;     ///< z: the measurement of part k is used for part k + z (1 .. kMaxDelay)
    int maxExtraLag = 2;   ///< plant delays z .. z + maxExtraLag are tried (the plant cannot act before z)
    int maxArmaOrder = 2;  ///< p, q = 0 .. maxArmaOrder for the disturbance
    InformationCriterion criterion = InformationCriterion::Bic;
    std::vector<double> priorGain;  ///< per point, the model's gain k_i: where each fit starts (none: 0)
    /// Per point, the model's disturbance in ARMA form (a_1.., b_1..): where each fit starts (none: white noise).
    std::vector<std::vector<double>> priorAr, priorMa;
    /// The model's lag (plant delay z + priorLag): kept unless another lag beats it by minDelayEvidence.
    int priorLag = 0;
    double maxGainRelativeStdErr = 0.35;  ///< refused while a gain's standard error is above this share of it
    /// Another delay than the model's replaces it only when its criterion is better by this much (then the next best
    /// must be this much worse too, or the identification is refused: the delay is not clear).
    double minDelayEvidence = 10.0;
    std::size_t minParts = 150;  ///< refused with fewer consecutive measured parts at a point

    /// Throws std::invalid_argument naming the value and its range.
    void validate(std::size_t points) const;
};

/// The model of one control point: y(k) = gain u(k - lag) + mean + ARMA(p, q) noise.
struct PointPlantFit {
    int point = 0;           ///< 0-based
    InputArmaFit fit;        ///< gain, mean, ARMA part, standard errors, residuals
    ArmaOrders orders;       ///< chosen by the criterion
    double criterion = 0.0;  ///< its value (AIC or BIC) for the chosen orders
    /// The disturbance model the loop had was kept (only the gain, the mean and the noise variance re-estimated): the
    /// criterion preferred it to every re-identified ARMA. The gain's standard error is then the one given it.
    bool disturbanceKept = false;
    std::int64_t firstPart = 0, lastPart = 0;  ///< the parts whose measurements were fitted
};

/// The plant identified from a closed-loop record: one delay for the loop, per point the gain and the
/// disturbance, and how the points' one-step prediction errors are correlated.
struct PlantIdentification {
    int loopDelay = 1;
    int lagParts = 0;  ///< the plant's extra delay: a correction sent for part k acts on part k + lag
    int delayParts() const { return loopDelay + lagParts; }  ///< the plant delay the design uses
    InformationCriterion criterion = InformationCriterion::Bic;
    std::vector<PointPlantFit> points;
    std::vector<double> lagScores;  ///< per lag 0 .. maxExtraLag: the criterion summed over the points
    /// The next-best lag's score minus the chosen one's (infinity: one lag tried; negative when the model's lag was
    /// kept although another fitted slightly better).
    double delayEvidence = 0.0;
    Eigen::MatrixXd innovationCorrelation;  ///< correlation of the points' prediction errors at the same part
    std::size_t parts = 0;                  ///< parts in the record
};

/// The data cannot tell the plant yet; `partsNeeded` more parts would likely do (0: more parts alone will
/// not: the corrections do not vary, switch on the dither). The message says why in the user's terms.
class IdentificationRefused : public std::invalid_argument {
public:
    IdentificationRefused(const std::string& why, std::int64_t partsNeeded)
        : std::invalid_argument(why), partsNeeded(partsNeeded) {}
    std::int64_t partsNeeded = 0;
};

/// Identifies the plant from `history` by the prediction-error method at every point, every lag 0 .. maxExtraLag and
/// ARMA orders p, q <= maxArmaOrder on the same parts (the longest stretch of consecutive measured parts at the
/// point): each point's fit by relaxation (the gain by least squares on the series filtered by the noise model's
/// inverse, then the noise for that gain with its orders by the criterion, until both settle: a stationary point of
/// the joint criterion, the standard errors from its J'J) from two starts, the model the loop had (priorGain,
/// priorAr, priorMa) and a Gauss-Newton fit of the joint model (fitInputArma, ARMA(1, 1)); the model the loop had
/// with only its gain re-estimated is a third candidate; the criterion chooses; the lag by the sum of the points'
/// criteria: the model's (priorLag) unless another beats it by minDelayEvidence. Throws IdentificationRefused when a
/// point has too few parts, its corrections did not vary, its gain is not positive or too uncertain, or the delay is
/// not clear; std::invalid_argument for bad options or a record of inconsistent sizes.
PlantIdentification identifyPlant(const LoopHistory& history, const PlantIdentificationOptions& options);

/// The ARMA fit of a point as the presets' disturbance model (ArmaFit::disturbanceModel).
DisturbanceModel identifiedDisturbance(const PointPlantFit& point);

}  // namespace tt::core
