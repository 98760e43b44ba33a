#pragma once

#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/control/run_to_run_controller.h"
#include "core/loop/adaptive_loop.h"
#include "core/loop/correction_limiter.h"
#include "core/loop/loop_config.h"
#include "core/loop/loop_events.h"
#include "core/loop/loop_state.h"
#include "core/loop/measurement_session.h"
#include "core/loop/mismatch_monitor.h"
#include "core/ports/clock.h"
#include "core/ports/correction_output.h"
#include "core/ports/diameter_gauge.h"
#include "core/ports/history_store.h"
#include "core/ports/machine_cycle.h"

namespace tt::core {

/// The outside world of the loop: every device through its port, the history (may be null: nothing
/// is stored) and the time.
struct LoopPorts {
    MachineCycle& machine;
    CorrectionOutput& output;
    DiameterGauge& gauge;
    const Clock& clock;
    HistoryStore* history = nullptr;
};

/// The corrections for part `partNumber` as the CNC receives them: the applied per-point corrections
/// and the path y_set(x) = y_ff(x) + PCHIP/spline through them (paper 000's approximation unit).
/// Throws std::invalid_argument on a bad correction.
PartCorrection partCorrectionFor(const LoopConfig& config, std::int64_t partNumber,
                                 const std::vector<double>& appliedMm);

/// The corrections a stored part really received (to put it back on the measuring station on resume).
PartCorrection partCorrectionFor(const LoopConfig& config, const StoredPart& part);

/// The closed loop of paper 000 (outer loop, one step per part), written against the ports only:
///   path for part n = feed-forward y_ff(x) + interpolated corrections u_1..u_N  ->  CNC
///   -> part n is machined -> its diameters are measured (gauge, in point order)
///   -> the measurement of part n - z is offered to the controller before part n   -> new path.
/// A step function: step() does everything that is possible at the clock's time and never blocks;
/// a thread (GUI), a plain loop (CLI, runSimulation) or a test drives it.
/// Safe behaviour: when the diameters the next part needs do not come (gauge not ready, or nothing
/// for gaugeTimeoutS) the loop pauses and the CNC keeps the last correction; it continues by itself
/// once they are in. A reading outside nominal ± plausibleRangeMm, or one the controller rejects, is
/// stored with its reason and the point counts as unmeasured. Corrections go through the
/// CorrectionLimiter. A CNC or history failure is a Fault that holds the last correction.
class LoopEngine {
public:
    /// Throws std::invalid_argument on a bad config or a controller with another number of points.
    LoopEngine(LoopConfig config, LoopPorts ports, std::unique_ptr<RunToRunController> controller);

    /// Events go to `listener` (may be null) on the thread that calls the engine.
    void setListener(LoopListener* listener) { m_listener = listener; }

    /// Starts a new run (Idle -> Running) and records it in the history.
    void start(const RunDescription& run);
    /// Continues a stored run (Idle -> Running): the controller state, the next part number, the parts
    /// still waiting to be measured and the measurements stored but not yet used. The caller puts the
    /// pending parts back on the measuring station first (real shop: they are on the rack).
    void resumeFrom(const ResumePoint& point);
    /// The operator pauses: no new part is started (the part on the machine is finished).
    void pause();
    /// The operator continues a paused run.
    void continueRun();
    /// Ends the run (any state -> Idle); a part on the machine is abandoned and not recorded.
    void stop();
    /// The oldest part waiting for its diameters is declared unmeasured (the operator skips it).
    void skipMeasurement();

    /// Does everything possible at the clock's time: finished parts, readings, the next part.
    void step();
    /// The latest time at which step() must run again even if no device reports anything (a timeout),
    /// +infinity when only device events matter.
    double nextWakeS() const;

    /// Idle, Running, Paused or Fault.
    LoopState state() const { return m_state; }
    /// What the loop is doing, in plain words ("machining part 12", "waiting for the diameters of part 9").
    const std::string& detail() const { return m_detail; }
    /// Why the loop is in its state, as a kind with data (the UI words it).
    const Notice& status() const { return m_status; }
    /// The run reached its last part and every part was measured.
    bool complete() const { return m_complete; }
    /// The run's id in the history, when the loop has a history store.
    std::optional<std::int64_t> runId() const { return m_runId; }
    /// The part that will be started next.
    std::int64_t nextPartNumber() const { return m_nextPart; }
    /// Parts finished in this session (after a resume: since the resume).
    std::int64_t partsFinished() const { return m_partsFinished; }
    /// The part waiting longest for its diameters, if any.
    std::optional<std::int64_t> partAwaitingMeasurement() const;
    /// The control point the next reading goes to (of partAwaitingMeasurement()).
    std::optional<std::size_t> nextMeasuredPoint() const;
    /// Corrections last sent to the CNC, radial mm per point.
    const std::vector<double>& lastAppliedMm() const { return m_limiter.lastAppliedMm(); }
    /// The configuration the loop was made with.
    const LoopConfig& config() const { return m_config; }
    /// The run-to-run controller the loop drives.
    const RunToRunController& controller() const { return *m_controller; }
    /// The plant no longer matched the model and the CNC keeps the last correction (MismatchAction::Hold)
    /// until the run is restarted.
    bool holdingOnMismatch() const { return m_holding; }

    /// Replaces the controller from the next part on (the commissioning engineer applied a new tuning),
    /// bumplessly: the first correction after the switch is the one last applied, and the difference
    /// between it and what the new controller asks for fades out linearly over `transferParts` parts, so
    /// no part sees a jump. Throws std::invalid_argument for a null controller, another number of points
    /// or transferParts outside 1 .. 1000. The fading offset is not part of a resume point: a run resumed
    /// during a transfer continues with the new controller alone (the step limit still applies).
    /// With the adaptation (setAdaptation) the replaced controller ends an adaptation in progress: `tuning`, when
    /// given, is the setup it was designed from and becomes the model the loop adapts from next.
    void replaceController(std::unique_ptr<RunToRunController> next, int transferParts = 10,
                           std::optional<RunToRunSetup> tuning = std::nullopt);
    /// Parts of a controller transfer still to fade out (0: none in progress).
    int transferPartsLeft() const { return m_transferLeft; }

    /// The controllers' setup the loop adapts from on a model mismatch (MismatchAction::Adapt or Propose; the run
    /// builder gives the scenario's). Without it those actions hold the last correction like Hold. From then on a
    /// controller that takes over (an adaptation or replaceController) is first primed with the run's recent
    /// parts, so its estimate is consistent with what the parts received. Call before start() or resumeFrom().
    /// Throws std::invalid_argument for a setup that does not fit the loop.
    void setAdaptation(RunToRunSetup setup);
    /// The adaptive loop (null without setAdaptation): its phase, the model in use, the last adaptation.
    const AdaptiveLoop* adaptation() const { return m_adaptive.get(); }
    /// The engineer applies the design the loop proposed (MismatchAction::Propose): it takes over at the next part.
    /// False when no design is proposed.
    bool acceptProposal();
    /// The controller now, in stable English ("LQG on the run's model", "fallback EWMA 0.23, identifying the plant").
    std::string controllerDescription() const;

private:
    /// The controller's correction for `part` plus the fading offset of a controller transfer (and the
    /// switch itself when a new controller waits).
    Eigen::VectorXd correctionWithTransfer(std::int64_t part, const std::vector<double>& previous);
    struct InProgress {
        std::int64_t partNumber = 0;
        double startedS = 0.0;
        std::vector<PointCorrectionRecord> corrections;
        std::optional<PartMeasurementRecord> usedMeasurement;
        ControllerState controllerState;
    };
    /// Why the loop paused: the operator; a gauge that is not ready (continues when it is); diameters
    /// that did not come from a gauge that says it is ready (continues when they come, or when they are
    /// typed by hand); a history store that refuses new parts.
    /// The history that takes no new part (continues when it does again).
    enum class PauseCause { None, Operator, Gauge, GaugeSilent, History };

    void collectFinishedParts();
    void collectReadings();
    void completeMeasurement(PartMeasurementRecord record);
    bool measurementDueReady(std::int64_t partNumber);
    void startNextPart();
    bool historyRefusesPart();  // pauses (PauseCause::History) when the store takes no new part
    void maybeComplete();
    PartMeasurementRecord judge(std::int64_t partNumber, const std::vector<std::optional<double>>& diameters,
                                double timeS) const;
    void offerMeasurement(PartMeasurementRecord& record);
    void judgeTolerances(const PartMeasurementRecord& record);  // out-of-tolerance alarms, pause on scrap
    void watchModel(std::int64_t partNumber);                   // the mismatch monitor after a measurement
    /// `next` takes over at part `part`: primed with the recent parts, the monitor restarts on its model and the
    /// difference to the last applied correction fades out over `transferParts`.
    void takeOver(std::unique_ptr<RunToRunController> next, std::int64_t part, int transferParts);
    /// Carries out what the adaptive loop decided at part `part` (a switch, the record, the operator's notice).
    void applyAdaptation(AdaptationStep step, std::int64_t part);
    /// The corrections of part `n` from the controller, the transfer, the dither and a hold, then the limiter.
    LimiterOutcome correctionsFor(std::int64_t n, const std::vector<double>& previous, Eigen::VectorXd& computed);
    void setState(LoopState state, const Notice& status);
    void alarm(const std::string& kind, const Notice& what, std::optional<std::int64_t> part = std::nullopt);
    void fault(const Notice& what);
    PointMeasurementRecord acceptedPoint(std::size_t i, double measuredMm) const;
    PointMeasurementRecord rejectedPoint(std::size_t i, std::optional<double> measuredMm, const Notice& why) const;
    void notify(LoopEvent event);
    void watchDevices();
    void openSession();
    void resetRun(std::int64_t nextPart);  // forgets the parts of any previous run

    LoopConfig m_config;
    LoopPorts m_ports;
    std::unique_ptr<RunToRunController> m_controller;
    std::unique_ptr<RunToRunController> m_nextController;  ///< takes over at the next part
    int m_transferParts = 0;                               ///< length of the transfer asked for
    int m_transferLeft = 0;                                ///< parts of the fading offset still to come
    Eigen::VectorXd m_transferOffsetMm;                    ///< last applied - new controller's first, mm
    bool m_transferPending = false;                        ///< the controller that took over has not corrected yet
    std::unique_ptr<AdaptiveLoop> m_adaptive;              ///< the self-tuning part (setAdaptation)
    bool m_acceptPending = false;                          ///< acceptProposal() waits for the next part
    std::optional<RunToRunSetup> m_nextTuning;             ///< the setup of m_nextController, when given
    CorrectionLimiter m_limiter;
    MismatchMonitor m_monitor;
    bool m_holding = false;
    LoopListener* m_listener = nullptr;

    LoopState m_state = LoopState::Idle;
    std::string m_detail;
    Notice m_status;
    PauseCause m_pauseCause = PauseCause::None;
    bool m_complete = false;
    std::optional<std::int64_t> m_runId;
    std::int64_t m_nextPart = 1;
    std::int64_t m_partsFinished = 0;
    std::optional<InProgress> m_inProgress;
    std::deque<std::int64_t> m_awaiting;          ///< finished parts waiting for their diameters, oldest first
    std::optional<MeasurementSession> m_session;  ///< readings of m_awaiting.front()
    std::map<std::int64_t, PartMeasurementRecord> m_measured;  ///< complete, not yet offered
    double m_waitingSinceS = std::numeric_limits<double>::quiet_NaN();
    std::map<std::string, DeviceState> m_deviceStates;
};

}  // namespace tt::core
