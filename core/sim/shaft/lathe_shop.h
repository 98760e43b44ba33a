#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/control/run_to_run_plant.h"
#include "core/ports/clock.h"
#include "core/sim/shaft/lathe_setup.h"
#include "core/sim/shaft/lathe_simulator.h"
#include "core/sim/shaft/lathe_station.h"
#include "core/sim/shaft/plant_mismatch.h"

namespace tt::core {

/// What the built-in simulated shop is made of.
struct LatheShopSpec {
    /// The physical lathe (paper-2012-group* presets); none: the controller's statistical design model
    /// is the machine (paper-2012).
    std::optional<LatheSetup> lathe;
    /// Control points, gains, per-point disturbance models and gauge noise (the controller's plant).
    /// The physical lathe takes the points and the disturbances; the statistical plant all of it.
    RunToRunPlantSpec plant;
    double nominalDiameterMm = 27.0;  ///< statistical plant only (the lathe has its own workpiece)
    double partLengthMm = 325.0;      ///< statistical plant only
    LatheStationTiming timing;
    std::uint64_t seed = 1;  ///< every random source of the shop
    /// How the simulated plant differs from the controller's model (plant.delay is the model's z). A gain
    /// factor and a step at one control point need the statistical plant.
    PlantMismatch mismatch;
};

/// The built-in simulated shop: a part process (physical lathe or statistical plant) and the measuring
/// station behind the loop's ports, on a shared clock. Same seed, same parts.
class LatheShop {
public:
    /// Throws std::invalid_argument on a bad spec.
    LatheShop(const LatheShopSpec& spec, const Clock& clock);

    /// The process that machines the parts (physical lathe or statistical plant).
    LathePartProcess& process() { return *m_process; }
    /// The station with the shop's ports.
    LatheStation& station() { return *m_station; }
    /// The control points along the part, mm.
    const std::vector<double>& pointZMm() const { return m_points; }
    /// The physical lathe, or null for the statistical plant.
    LatheSimulator* lathe() { return m_lathe; }

private:
    void applyMismatch(const LatheShopSpec& spec);

    std::vector<double> m_points;
    std::unique_ptr<LathePartProcess> m_process;
    LatheSimulator* m_lathe = nullptr;
    std::unique_ptr<LatheStation> m_station;
};

}  // namespace tt::core
