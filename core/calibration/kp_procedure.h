#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/calibration/current_difference_meter.h"
#include "core/calibration/kp_calibration.h"
#include "core/calibration/settled_average.h"

namespace tt::core {

/// One known load and the current difference measured (or typed) at it.
struct KpLoadPoint {
    double loadN = 0.0;               ///< known radial load, N (towards the axis: positive)
    double currentDifferenceA = 0.0;  ///< ΔI = (I_fwd − I_rev) / 2, mean over the stroke pairs, A
    int pairs = 0;                    ///< stroke pairs averaged; 0 when typed
};

/// Why a measurement at a load ended without a point.
enum class KpMeasureProblem {
    None,
    NotReady,     ///< the read-out reports a problem (its message comes with it)
    NoSamples,    ///< no sample arrived for the timeout
    TooFewPairs,  ///< fewer stroke pairs than needed in the window (the meter's last problem comes with it)
    Aborted,      ///< the operator stopped it
};

/// A verification load: measured after the fit, not used by it, and compared with the force the
/// fit gives for its current difference.
struct KpCheck {
    KpLoadPoint point;
    double forceN = 0.0;      ///< k_p ΔI + offset, N
    double deviationN = 0.0;  ///< force − load, N
    double toleranceN = 0.0;  ///< allowed |deviation|, N
    bool passed = false;
};

/// Why the loads give no k_p (the fit's kind, or a measurement still running).
struct KpFitOutcome {
    std::optional<KpFit> fit;
    std::optional<KpFitProblem> refusal;
    int count = 0;            ///< TooFewLoads / TooFewDifferentLoads / NotANumber: see KpFitRefused
    double slopeNPerA = 0.0;  ///< FallsWithLoad
};

/// What the k_p procedure reports, as kinds with data (the wizard words them).
struct KpEvent {
    enum class Kind {
        LoadMeasured,  ///< point (number), value
        LoadRepeated,  ///< point measured again
        LoadTyped,
        LoadRemoved,
        MeasureFailed,  ///< problem, strokeProblem, pairs, device message
        CheckDone,      ///< check
        Fitted,
        FitRefused,  ///< outcome refusal
        Accepted,
        AcceptRefused,
    };
    Kind kind = Kind::LoadMeasured;
    int point = 0;  ///< numbered from 1
    KpLoadPoint value;
    KpMeasureProblem problem = KpMeasureProblem::None;
    StrokeProblem strokeProblem = StrokeProblem::None;
    std::string deviceMessage;
    std::optional<KpCheck> check;
};

/// Timing of the measurement at one load.
struct KpProcedureConfig {
    double settleS = 1.0;           ///< hold still: stroke pairs within this time after the start are not used, s
    int pairsPerLoad = 12;          ///< stroke pairs averaged per load
    double windowS = 6.0;           ///< at most this long averaging after the settling, s (sample time)
    int minPairs = 3;               ///< fewer pairs in the window: no point
    double noSampleTimeoutS = 3.0;  ///< a measurement without a sample for this long fails, s (wall time)
};

/// The current-to-force gain k_p from known loads (paper 001: "found experimentally") as a state
/// machine, with no widget: Capture (apply a load, the cross feed dithers, hold still, average the
/// current difference of the stroke pairs, next load; repeat, type or remove loads) → Fit (P =
/// k_p ΔI + offset, refused with a kind; verification loads compared with the fit) → Accepted.
/// The drive's samples arrive through the engine's port (core::DriveCurrentReadout); the stroke
/// pairs are told apart by a CurrentDifferenceMeter.
class KpCalibrationProcedure {
public:
    enum class Step { Capture, Fit, Accepted };
    using Phase = HoldPhase;

    /// Takes the meter (not null); throws std::invalid_argument for timing out of range.
    explicit KpCalibrationProcedure(std::unique_ptr<CurrentDifferenceMeter> meter,
                                    const KpProcedureConfig& config = {});

    // --- the operator's actions ---
    /// Capture: measures at the load applied now, N. The samples the read-out holds from before
    /// the load was applied belong to the old one: take them first (pump).
    void measure(double loadN);
    /// Capture: measures point `index` (from 0) again at its load; the new value replaces it.
    void repeatPoint(int index);
    void typePoint(double loadN, double currentDifferenceA);
    void removePoint(int index);
    /// Stops a running measurement or check (no point).
    void abort();
    /// Capture → Fit (at least kMinKpLoads loads, none being measured; the fit is made). False when refused.
    bool next();
    /// Fit → Capture, Accepted → Fit. The loads stay.
    void back();
    /// Fit: measures a verification load, N.
    void check(double loadN);
    /// Fit → Accepted when k_p is fitted and no check failed or runs.
    bool accept();
    void withdrawAcceptance();

    // --- timed input ---
    /// The drive's samples; `elapsedS` of wall time since the last call (for the timeout).
    void pump(DriveCurrentReadout& readout, double elapsedS);

    // --- outputs ---
    std::vector<KpEvent> takeEvents();
    Step step() const { return m_step; }
    Phase phase() const { return m_average.holdPhase(); }
    bool measuring() const { return phase() != Phase::Idle; }
    /// 0..1 of the running measurement.
    double progress() const { return m_average.progress(); }
    /// The load being measured, N.
    double loadN() const { return m_loadN; }
    std::optional<int> repeating() const { return m_repeat; }
    bool checking() const { return m_checking; }
    /// Stroke pairs averaged so far in the running measurement.
    int pairs() const { return m_average.count(); }
    /// The latest stroke pair's current difference (live, also between measurements), A.
    std::optional<double> liveDifferenceA() const { return m_live; }
    const std::vector<KpLoadPoint>& points() const { return m_points; }
    const KpFitOutcome& fitOutcome() const { return m_fit; }
    const std::vector<KpCheck>& checks() const { return m_checks; }
    bool canFit() const;
    bool accepted() const { return m_step == Step::Accepted; }
    const KpProcedureConfig& config() const { return m_config; }

private:
    void requireStep(Step step, const char* action) const;
    void start(double loadN, std::optional<int> repeat, bool check);
    void finish(KpMeasureProblem problem, std::string deviceMessage = {});
    void finishCheck(const KpLoadPoint& point);
    void refit();
    void report(KpEvent event) { m_events.push_back(std::move(event)); }

    std::unique_ptr<CurrentDifferenceMeter> m_meter;
    KpProcedureConfig m_config;
    Step m_step = Step::Capture;
    SettledAverage m_average;
    double m_loadN = 0.0;
    std::optional<int> m_repeat;
    bool m_checking = false;
    double m_quietS = 0.0;
    StrokeProblem m_lastProblem = StrokeProblem::None;
    std::optional<double> m_live;
    std::vector<KpLoadPoint> m_points;
    KpFitOutcome m_fit;
    std::vector<KpCheck> m_checks;
    std::vector<KpEvent> m_events;
};

}  // namespace tt::core
