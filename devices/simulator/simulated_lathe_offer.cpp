#include "devices/simulator/simulated_lathe_offer.h"

#include <QCoreApplication>

#include "core/run/simulated_lathe.h"

namespace tt::devices {

ShaftMachineOffer simulatedLatheOffer() {
    ShaftMachineOffer offer;
    offer.key = QStringLiteral("simulated-lathe");
    offer.name = QCoreApplication::translate("Simulator", "Simulated lathe (built in)");
    offer.description = QCoreApplication::translate(
        "Simulator",
        "Parts of the set-up are turned on the simulated lathe, measured at the control points and the next part "
        "is corrected.");
    offer.adjustableSpeed = true;
    offer.make = [](const core::ShaftScenario& scenario, std::uint64_t seed, double speed) {
        return std::make_unique<core::SimulatedLathe>(scenario.shopSpec(seed), core::SimulatedLathe::Time::Paced,
                                                      speed);
    };
    return offer;
}

}  // namespace tt::devices
