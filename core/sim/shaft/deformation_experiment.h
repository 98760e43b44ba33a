#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <vector>

#include "core/control/feed_refinement_design.h"
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

/// Turns the bars of a targeted experiment (FeedRefinementRound) at depth `depthMm`, each at its feed
/// along its whole length, and gauges each at its own positions with the set-up's micrometer, as
/// runDeformationExperiment does. The bars are numbered from `firstBar` for the micrometer's noise
/// streams (each bar and gauge point its own stream), so bars of different rounds share no noise with
/// each other or with the grid experiment (bars 1 .. 2500). Rows in the order of the bars and their
/// points; `progress` is called after each bar. Throws std::invalid_argument on a depth or feed outside
/// the pass's limits, a position off the shaft, no bars or more than 1000; DeformationExperimentStopped
/// when `progress` returns false.
DeformationSamples runTargetedBars(const LatheSetup& setup, double depthMm, const std::vector<RefinementBar>& bars,
                                   std::uint64_t seed, std::int64_t firstBar,
                                   const DeformationExperimentProgress& progress = {});

}  // namespace tt::core
