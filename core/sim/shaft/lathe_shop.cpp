#include "core/sim/shaft/lathe_shop.h"

#include <cmath>
#include <stdexcept>

#include "core/sim/shaft/lathe_statistical_process.h"

namespace tt::core {

LatheShop::LatheShop(const LatheShopSpec& spec, const Clock& clock) {
    if (spec.plant.points.empty()) throw std::invalid_argument("the simulated shop needs at least one control point");
    spec.mismatch.validate(spec.plant.delay, spec.plant.points.size());
    if (spec.lathe && (spec.mismatch.gainFactor != 1.0 || (spec.mismatch.step && spec.mismatch.step->point)))
        throw std::invalid_argument(
            "a plant gain factor and a step at one control point are simulated on the statistical plant only (a "
            "preset without a lathe section)");
    std::vector<DisturbanceModel> disturbances;
    for (const ControlPointSpec& p : spec.plant.points) {
        m_points.push_back(p.xMm);
        disturbances.push_back(p.disturbance);
    }
    if (spec.lathe) {
        LatheDisturbanceModel disturbance =
            LatheDisturbanceModel::fromPointModels(disturbances, spec.lathe->randomCommonShare)
                .scaled(spec.lathe->randomScale);
        LatheSetup setup = *spec.lathe;
        setup.seed = spec.seed;
        auto lathe = std::make_unique<LatheSimulator>(setup, m_points, std::move(disturbance));
        m_lathe = lathe.get();
        m_process = std::move(lathe);
        applyMismatch(spec);
        m_station =
            std::make_unique<LatheStation>(*m_process, setup.micrometer, spec.seed, clock, m_points, spec.timing);
        return;
    }
    LatheDisturbanceModel disturbance = LatheDisturbanceModel::fromPointModels(disturbances);
    Eigen::VectorXd gains(static_cast<Eigen::Index>(m_points.size()));
    std::vector<double> sigma;
    for (std::size_t i = 0; i < spec.plant.points.size(); ++i) {
        gains(static_cast<Eigen::Index>(i)) = spec.plant.points[i].gain * spec.mismatch.gainFactor;
        const double v = spec.plant.points[i].measurementNoiseVarianceMm2;
        if (!std::isfinite(v) || v < 0.0) throw std::invalid_argument("a gauge noise variance is negative");
        sigma.push_back(std::sqrt(v));
    }
    m_process = std::make_unique<LatheStatisticalProcess>(m_points, gains, std::move(disturbance),
                                                          spec.nominalDiameterMm, spec.partLengthMm, spec.seed);
    applyMismatch(spec);
    m_station = std::make_unique<LatheStation>(*m_process, LatheMicrometerModel(sigma, 0.0, spec.seed), clock, m_points,
                                               spec.timing);
}

void LatheShop::applyMismatch(const LatheShopSpec& spec) {
    const int lag = spec.mismatch.delayParts ? *spec.mismatch.delayParts - spec.plant.delay : 0;
    if (lag == 0 && !spec.mismatch.step) return;
    m_process = std::make_unique<MismatchedProcess>(std::move(m_process), lag, spec.mismatch.step, m_points);
}

}  // namespace tt::core
