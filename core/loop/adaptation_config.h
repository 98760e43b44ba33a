#pragma once

#include "core/control/adaptive_design.h"
#include "core/control/plant_identification.h"
#include "core/control/run_to_run_plant.h"

namespace tt::core {

/// How the loop adapts when the mismatch monitor fires with the action adapt or propose ("loop":
/// {"adaptation": {...}} in a preset): the record it identifies from, how often it tries, how long a switch
/// fades, the optional dither and the identification's choices and refusals (core/control/plant_identification.h).
struct AdaptationConfig {
    int windowParts = 2000;  ///< identify from the last this many parts (parts since the start when fewer)
    int retryParts = 25;     ///< a refused identification is tried again after at least this many parts
    int transferParts = 10;  ///< each switch fades the difference of the corrections out over this many parts
    /// A dither on the correction while the loop identifies (on the fallback): the diameter moves by +- this share
    /// of each point's tolerance zone width, a pseudo-random binary sequence of the part number. 0: off.
    double ditherShare = 0.0;
    int maxExtraLag = 2;   ///< plant delays z .. z + maxExtraLag are tried
    int maxArmaOrder = 2;  ///< the disturbance's ARMA(p, q) orders, p, q <= this
    InformationCriterion criterion = InformationCriterion::Bic;
    double maxGainRelativeStdErr = 0.35;  ///< a gain more uncertain than this share of it is not used
    /// After an adaptation whose gains are less certain than this share, the loop identifies again every refineParts
    /// parts and takes a design whose gains are clearly more certain (adapt only; 0: never refine).
    double refineBelow = 0.05;
    int refineParts = 200;
    double minDelayEvidence = 10.0;  ///< criterion difference the chosen delay needs over the next
    /// The gain change (up, and its inverse down) a new design's margins must cover at least, beyond what the
    /// identified gains' uncertainty asks (1.05 .. kMaxMinGainMargin): a commissioning engineer's demand.
    double minGainMargin = kDefaultMinGainMargin;
    int minParts = 150;  ///< consecutive measured parts the identification needs at least

    /// The identification options for a loop of delay `loopDelay` starting from the model `model` (its gains and, in
    /// ARMA form, its disturbances).
    PlantIdentificationOptions identification(int loopDelay, const RunToRunPlantSpec& model) const;
    /// Throws std::invalid_argument naming the value and its range.
    void validate() const;
};

/// Largest gain margin a preset may demand of a new design.
inline constexpr double kMaxMinGainMargin = 100.0;

/// Largest dither share of the tolerance zone.
inline constexpr double kMaxDitherShare = 0.5;

}  // namespace tt::core
