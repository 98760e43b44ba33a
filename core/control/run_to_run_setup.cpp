#include "core/control/run_to_run_setup.h"

#include <stdexcept>

namespace tt::core {

std::string controllerKindName(ControllerKind kind) {
    switch (kind) {
        case ControllerKind::Lqg:
            return "lqg";
        case ControllerKind::Ewma:
            return "ewma";
        case ControllerKind::Open:
            return "open";
        case ControllerKind::Dewma:
            return "dewma";
    }
    return "open";
}

ControllerKind controllerKindFromName(const std::string& name) {
    if (name == "lqg") return ControllerKind::Lqg;
    if (name == "ewma") return ControllerKind::Ewma;
    if (name == "open") return ControllerKind::Open;
    if (name == "dewma") return ControllerKind::Dewma;
    throw std::invalid_argument("unknown controller '" + name + "' (lqg, ewma, open, dewma)");
}

std::unique_ptr<RunToRunController> makeRunToRunController(const RunToRunSetup& setup, const RunToRunPlant& plant,
                                                           ControllerKind kind, double ewmaWeight) {
    switch (kind) {
        case ControllerKind::Lqg:
            return std::make_unique<LqgController>(plant, designLqg(plant, setup.weights), setup.limits, setup.lqg);
        case ControllerKind::Ewma: {
            EwmaOptions options = setup.ewma;
            options.weight = ewmaWeight;
            options.driftWeight = 0.0;
            return std::make_unique<EwmaController>(plant.gain, setup.limits, options);
        }
        case ControllerKind::Dewma: {
            EwmaOptions options = setup.ewma;
            options.weight = ewmaWeight;
            if (options.driftWeight <= 0.0) options.driftWeight = kDefaultDriftWeight;
            options.driftHorizonParts = plant.delay;
            return std::make_unique<EwmaController>(plant.gain, setup.limits, options);
        }
        case ControllerKind::Open:
            return std::make_unique<OpenLoopController>(plant.pointCount());
    }
    throw std::invalid_argument("unknown controller kind");
}

}  // namespace tt::core
