#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/control/margins.h"
#include "core/control/plant_identification.h"
#include "core/control/run_to_run_setup.h"
#include "core/ports/adaptation_record.h"

namespace tt::core {

/// The plant changes the fallback controller must survive: the plant's gain from kFallbackMinGainFactor to
/// kFallbackMaxGainFactor times the model's, and one extra part of delay (issue: "gain 0.5 .. 2 and one extra
/// part"), checked on a grid of gain factors every kFallbackGainStep.
inline constexpr double kFallbackMinGainFactor = 0.5;
inline constexpr double kFallbackMaxGainFactor = 2.0;
inline constexpr double kFallbackGainStep = 0.05;
inline constexpr int kFallbackExtraParts = 1;

/// The fallback the loop switches to when the plant no longer matches the model: an EWMA (the measuring cycles'
/// mean value, no model of the disturbance) with the largest weight on 0.01 .. 1 whose loop stays stable for
/// every plant gain factor in [0.5, 2] at the model's delay and one part more (closed-loop eigenvalues).
struct FallbackDesign {
    double weight = 0.0;     ///< lambda
    int delayParts = 1;      ///< the model's plant delay it was designed for
    ChannelMargins margins;  ///< at the model's gain and delay (every point alike: the loop depends on g / k_i)
};

/// Designs the fallback for a plant delay `delayParts` (1 .. kMaxDelay). Throws std::invalid_argument when no
/// weight on the grid covers the range (does not happen for delays 1 .. 8; tested).
FallbackDesign designFallback(int delayParts);

/// The fallback controller of `setup` (its EWMA options, the design plant's gains, wrapped for the model's lag).
std::unique_ptr<RunToRunController> makeFallbackController(const RunToRunSetup& setup, const FallbackDesign& fallback);

/// What a design adapted to an identified plant must show before it is applied: a stable loop whose gain margins
/// cover the identified gains' uncertainty, a factor 1 + max(kMinGainUncertainty, kGainSigmas x the largest relative
/// standard error) up and its inverse down (kGainSigmas = 2: about 95 % of the gains the data allow). The LQG is
/// synthesised with the setup's weights and, while it fails, with R2 multiplied by each of kDetuneFactors in turn (a
/// slower, more robust design).
inline constexpr double kMinGainUncertainty = 0.25;
inline constexpr double kGainSigmas = 2.0;
inline constexpr double kDetuneFactors[] = {1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0};

/// The largest relative standard error of the identified gains (0 when none is known): as identified, or with
/// `joint` the one with the disturbance free too (gainStdErrJoint: what the data alone tell; infinite when they
/// cannot tell a gain at all).
double worstGainShare(const PlantModelRecord& model, bool joint = false);

/// The gain change a new design's margins must cover by default: 1 + kMinGainUncertainty.
inline constexpr double kDefaultMinGainMargin = 1.0 + kMinGainUncertainty;

/// An LQG design for an identified plant with its margins checked.
struct AdaptedDesign {
    RunToRunSetup setup;              ///< the setup with the identified model (and the R2 finally used)
    LoopMargins margins;              ///< of that design on the identified plant
    MarginsRecord worst;              ///< its worst channel
    double requiredGainFactor = 1.0;  ///< the gain change the margins had to cover
    double r2Factor = 1.0;            ///< R2 multiplied by this (1: the setup's weights)
    bool passes = false;              ///< the margins hold: the design may be applied
    std::string why;                  ///< when it does not pass, in the user's terms
};

/// The identified model as the controller's model (gains, disturbances from the ARMA fits, lag, correlation).
ControllerModel controllerModelFrom(const PlantIdentification& id, std::string source);

/// Re-synthesises the LQG of `current` (its weights, limits, integral action) for the identified plant and checks
/// its margins: they cover a gain change of requiredGainFactor(..., minGainMargin). Throws std::invalid_argument
/// when the plant cannot be built.
AdaptedDesign designAdapted(const RunToRunSetup& current, const PlantIdentification& id, const std::string& source,
                            double minGainMargin = kDefaultMinGainMargin);

/// The same for a setup that already carries its model (setup.model), with the margins covering a gain change
/// `requiredGainFactor` (>= 1) up and down (a resumed run designs again what it recorded).
AdaptedDesign designForModel(const RunToRunSetup& withModel, double requiredGainFactor);

/// max(minGainMargin, 1 + kGainSigmas x the largest relative standard error of the gains).
double requiredGainFactor(const std::vector<double>& gain, const std::vector<double>& gainStdErr,
                          double minGainMargin = kDefaultMinGainMargin);

/// The adapted LQG controller of a design (makeRunToRunController on its setup).
std::unique_ptr<RunToRunController> makeAdaptedController(const RunToRunSetup& adapted);

/// The worst channel of `margins`: the smallest upper gain, phase and delay margins, the largest lower gain margin
/// and the fewest extra parts tolerated.
MarginsRecord worstMargins(const LoopMargins& margins);
/// One channel's margins as recorded.
MarginsRecord marginsRecord(const ChannelMargins& channel);

/// The controller's model of `setup` as recorded (the identified one, or the plant's own); the ARMA form of a
/// preset's disturbance when it has one (one shaping filter, an AR(1) or white noise; empty lists otherwise).
PlantModelRecord modelRecord(const RunToRunSetup& setup);
/// An identified model as recorded, with its standard errors.
PlantModelRecord modelRecord(const PlantIdentification& id, const std::string& source);
/// The controller's model a record describes (for a resumed run); throws std::invalid_argument for a record
/// without the ARMA form of every point or with another number of points than `setup`.
ControllerModel controllerModelFrom(const PlantModelRecord& record, const RunToRunSetup& setup);

/// The ARMA form of a disturbance model: a_1.., b_1.. and the innovation variance (see PointModelRecord).
struct ArmaForm {
    std::vector<double> ar, ma;
    double noiseVarianceMm2 = 0.0;
};
/// One shaping filter (its ARMA in the innovations n_0 e), one AR(1) or white noise; none for a sum of components
/// or a random walk.
std::optional<ArmaForm> armaForm(const DisturbanceModel& model);

}  // namespace tt::core
