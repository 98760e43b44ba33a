#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <vector>

#include "core/model/deformation_model.h"
#include "core/sim/shaft/lathe_setup.h"

namespace tt::core {

/// The experiments behind the force-deformation model (paper 004): one test bar per (a, f) of the grid,
/// each turned along its whole length at constant depth and feed, its finished diameter gauged at the
/// positions z with the micrometer of the set-up.
struct DeformationExperimentPlan {
    std::vector<double> depthsMm;       ///< levels of a, mm (1..50 levels, each in (0, finished radius))
    std::vector<double> feedsMmPerRev;  ///< levels of f, mm/rev (1..50 levels, each in (0, 5])
    std::vector<double> zMm;            ///< gauged positions along the bar, mm (1..2000, on the shaft)
    std::uint64_t seed = 1;             ///< seed of the micrometer's noise
};

/// Called after each bar with (bars done, bars in all); returning false stops the experiment.
using DeformationExperimentProgress = std::function<bool(std::size_t barsDone, std::size_t bars)>;

/// Thrown when the progress callback stopped the experiment.
class DeformationExperimentStopped : public std::runtime_error {
public:
    DeformationExperimentStopped() : std::runtime_error("the experiment was stopped") {}
};

/// Runs the experiment on the shaft-turning simulator: for every bar the deformation along z from
/// LathePass (Kienzle force, shaft on elastic centres, cutter deflection), the finished diameter
/// d = d_nominal + 2 Y read by the set-up's micrometer (Gaussian error, rounded to its display step;
/// LatheMicrometerModel, a separate stream per bar and position), and the measured deformation
/// Y = (d_read - d_nominal) / 2 in µm. Rows ordered by a, then f, then z. Throws
/// std::invalid_argument naming the first value outside its limits; DeformationExperimentStopped when
/// `progress` returns false.
DeformationSamples runDeformationExperiment(const LatheSetup& setup, const DeformationExperimentPlan& plan,
                                            const DeformationExperimentProgress& progress = {});

}  // namespace tt::core
