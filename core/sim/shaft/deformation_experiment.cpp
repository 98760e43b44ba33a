#include "core/sim/shaft/deformation_experiment.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/sim/shaft/lathe_micrometer.h"
#include "core/sim/shaft/lathe_pass.h"

namespace tt::core {

namespace {

void checkLevels(const std::vector<double>& levels, std::size_t maxCount, const char* what) {
    if (levels.empty() || levels.size() > maxCount)
        throw std::invalid_argument(std::string("the experiment needs 1 .. ") + std::to_string(maxCount) + " " + what +
                                    " (got " + std::to_string(levels.size()) + ")");
    for (double v : levels)
        if (!std::isfinite(v)) throw std::invalid_argument(std::string("one of the ") + what + " is not a number");
}

}  // namespace

DeformationSamples runDeformationExperiment(const LatheSetup& setup, const DeformationExperimentPlan& plan,
                                            const DeformationExperimentProgress& progress) {
    checkLevels(plan.depthsMm, 50, "depths of cut");
    checkLevels(plan.feedsMmPerRev, 50, "feeds");
    checkLevels(plan.zMm, 2000, "gauged positions");
    const LatheMicrometerModel micrometer(setup.micrometer, plan.seed);
    const double nominal = setup.workpiece.finishDiameterMm;
    const auto rows = static_cast<Eigen::Index>(plan.depthsMm.size() * plan.feedsMmPerRev.size() * plan.zMm.size());
    DeformationSamples s;
    s.depthMm.resize(rows);
    s.feedMmPerRev.resize(rows);
    s.zMm.resize(rows);
    s.deformationUm.resize(rows);
    Eigen::Index row = 0;
    std::int64_t bar = 0;
    const std::size_t bars = plan.depthsMm.size() * plan.feedsMmPerRev.size();
    for (double a : plan.depthsMm) {
        const LathePass pass(setup, a);
        for (double f : plan.feedsMmPerRev) {
            ++bar;
            for (std::size_t i = 0; i < plan.zMm.size(); ++i) {
                const double z = plan.zMm[i];
                const double trueDiameter = nominal + 2.0 * pass.deformationMm(z, f);
                const double read = micrometer.readMm(trueDiameter, bar, static_cast<int>(i));
                s.depthMm(row) = a;
                s.feedMmPerRev(row) = f;
                s.zMm(row) = z;
                s.deformationUm(row) = 1000.0 * 0.5 * (read - nominal);
                ++row;
            }
            if (progress && !progress(static_cast<std::size_t>(bar), bars)) throw DeformationExperimentStopped();
        }
    }
    return s;
}

DeformationSamples runTargetedBars(const LatheSetup& setup, double depthMm, const std::vector<RefinementBar>& bars,
                                   std::uint64_t seed, std::int64_t firstBar,
                                   const DeformationExperimentProgress& progress) {
    if (bars.empty() || bars.size() > 1000)
        throw std::invalid_argument("a targeted experiment needs 1 .. 1000 bars (got " + std::to_string(bars.size()) +
                                    ")");
    const LathePass pass(setup, depthMm);
    const LatheMicrometerModel micrometer(setup.micrometer, seed);
    const double nominal = setup.workpiece.finishDiameterMm;
    Eigen::Index rows = 0;
    for (const RefinementBar& b : bars)
        rows += static_cast<Eigen::Index>(b.zMm.size());
    DeformationSamples s;
    s.depthMm = Eigen::VectorXd::Constant(rows, depthMm);
    s.feedMmPerRev.resize(rows);
    s.zMm.resize(rows);
    s.deformationUm.resize(rows);
    Eigen::Index row = 0;
    for (std::size_t k = 0; k < bars.size(); ++k) {
        const RefinementBar& bar = bars[k];
        const std::int64_t number = firstBar + static_cast<std::int64_t>(k);
        for (std::size_t i = 0; i < bar.zMm.size(); ++i) {
            const double trueDiameter = nominal + 2.0 * pass.deformationMm(bar.zMm[i], bar.feedMmPerRev);
            const double read = micrometer.readMm(trueDiameter, number, static_cast<int>(i));
            s.feedMmPerRev(row) = bar.feedMmPerRev;
            s.zMm(row) = bar.zMm[i];
            s.deformationUm(row) = 1000.0 * 0.5 * (read - nominal);
            ++row;
        }
        if (progress && !progress(k + 1, bars.size())) throw DeformationExperimentStopped();
    }
    return s;
}

}  // namespace tt::core
