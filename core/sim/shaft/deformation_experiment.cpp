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

}  // namespace tt::core
