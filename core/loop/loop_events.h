#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/loop/loop_state.h"
#include "core/ports/correction_output.h"
#include "core/ports/device_health.h"
#include "core/ports/history_store.h"

namespace tt::core {

/// Something the operator should see, as the loop engine reports it.
struct LoopEvent {
    /// What happened.
    enum class Kind {
        StateChanged,  ///< state / detail changed (message = the detail in plain words)
        PartStarted,   ///< corrections sent, the part is on the machine (corrections, path)
        PartFinished,  ///< the part came off the machine and is stored
        PartMeasured,  ///< all diameters of a part are in (measurement, with the loop's verdicts)
        Alarm,         ///< alarmKind + message, also stored with the run ("adaptation": with `adaptation`)
        DeviceChanged  ///< device = which one ("gauge", "cnc", "machine"), health
    };
    Kind kind = Kind::StateChanged;
    LoopState state = LoopState::Idle;
    std::int64_t partNumber = 0;
    double timeS = 0.0;
    std::string message;  ///< the stable English words (CLI, history); `notice` holds the kind and data
    Notice notice;
    std::string alarmKind;
    std::string device;
    DeviceHealth health;
    std::vector<PointCorrectionRecord> corrections;
    CorrectionPath path;
    std::optional<PartMeasurementRecord> measurement;
    /// What the adaptive loop did (an Alarm of kind "adaptation" that changed or proposed the controller).
    std::optional<AdaptationRecord> adaptation;
};

/// Receives the loop engine's events, on the thread that drives the engine.
class LoopListener {
public:
    virtual ~LoopListener() = default;
    /// Called for every event, in the order they happen.
    virtual void onLoopEvent(const LoopEvent& event) = 0;
};

}  // namespace tt::core
