#include "core/control/run_to_run_setup.h"

#include <stdexcept>

#include "core/control/lagged_controller.h"

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

void ControllerModel::validate(std::size_t points, int delay) const {
    if (gain.size() != points || disturbance.size() != points)
        throw std::invalid_argument("the controller's model has " + std::to_string(gain.size()) + " gains and " +
                                    std::to_string(disturbance.size()) + " disturbances for " + std::to_string(points) +
                                    " control points");
    for (std::size_t i = 0; i < points; ++i)
        if (!(gain[i] > 0.0 && gain[i] <= 100.0))
            throw std::invalid_argument("the controller's model: the gain of point " + std::to_string(i + 1) +
                                        " must be in (0, 100], got " + std::to_string(gain[i]));
    if (lagParts < 0 || delay + lagParts > kMaxDelay)
        throw std::invalid_argument(
            "the controller's model: the plant delay z + lag = " + std::to_string(delay + lagParts) + " must be " +
            std::to_string(delay) + " .. " + std::to_string(kMaxDelay) + " parts");
    const auto m = static_cast<Eigen::Index>(points);
    if (innovationCorrelation.size() != 0 &&
        (innovationCorrelation.rows() != m || innovationCorrelation.cols() != m || !innovationCorrelation.allFinite()))
        throw std::invalid_argument("the controller's model: the innovation correlation must be " +
                                    std::to_string(points) + " x " + std::to_string(points));
}

RunToRunPlantSpec designPlantSpec(const RunToRunSetup& setup) {
    RunToRunPlantSpec spec = setup.plant;
    if (!setup.model) return spec;
    setup.model->validate(spec.points.size(), spec.delay);
    for (std::size_t i = 0; i < spec.points.size(); ++i) {
        spec.points[i].gain = setup.model->gain[i];
        spec.points[i].disturbance = setup.model->disturbance[i];
    }
    spec.delay += setup.model->lagParts;
    return spec;
}

int actuationLag(const RunToRunSetup& setup) {
    return setup.model ? setup.model->lagParts : 0;
}

namespace {

std::unique_ptr<RunToRunController> makeController(const RunToRunSetup& setup, const RunToRunPlant& plant,
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

}  // namespace

std::unique_ptr<RunToRunController> makeRunToRunController(const RunToRunSetup& setup, const RunToRunPlant& plant,
                                                           ControllerKind kind, double ewmaWeight) {
    std::unique_ptr<RunToRunController> controller = makeController(setup, plant, kind, ewmaWeight);
    if (!setup.model || kind == ControllerKind::Open) return controller;
    return std::make_unique<LaggedController>(std::move(controller), setup.model->lagParts,
                                              setup.model->innovationCorrelation);
}

}  // namespace tt::core
