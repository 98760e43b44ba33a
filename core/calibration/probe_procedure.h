#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/calibration/probe_capture.h"
#include "core/calibration/probe_linearisation.h"
#include "core/calibration/table_upload.h"

namespace tt::core {

/// Why the captured points give no table.
enum class ProbeFitRefusal {
    None,
    TooFewPoints,      ///< fewer usable (unclipped) points than the degree needs
    TooFewReferences,  ///< fewer different reference deflections than the degree needs
    ConstantCode,      ///< the code is the same at every point: it does not follow the deflection
    NonMonotonic,      ///< the fitted curve turns (where: fit->monotonicity)
    OutOfRange,        ///< a code outside the ADC's range, or a table beyond what 16 bits hold
    BadInput,          ///< a point that is not a number, or a degree or resolution out of range
};

/// The fit of the captured points: the saturated points left out (numbered from 1), the fit, and
/// the table when the fit is usable, or the reason it is not.
struct ProbeFitOutcome {
    std::vector<int> leftOut;                    ///< saturated points not used, numbered from 1
    std::optional<CharacteristicFit> fit;        ///< when the points could be fitted at all
    std::optional<Linearisation> linearisation;  ///< when the fit is usable (monotonic, table built)
    ProbeFitRefusal refusal = ProbeFitRefusal::None;
    int needed = 0;  ///< TooFewPoints / TooFewReferences: how many the degree needs
    int got = 0;     ///< and how many there are
    double constantCode = 0.0;

    bool usable() const { return linearisation.has_value(); }
};

/// Fits the points that did not clip the ADC (degree 2..4 or kAutoDegree) and builds the table.
ProbeFitOutcome fitProbePoints(const std::vector<ProbePoint>& points, int adcBits, int degree);

/// A verification point: captured after the fit, not used by it, read through the table.
struct ProbeCheck {
    ProbePoint point;
    double readingUm = 0.0;    ///< what the table reads at the mean code, µm
    double deviationUm = 0.0;  ///< reading − reference, µm
    double toleranceUm = 0.0;  ///< allowed |deviation|, µm
    bool passed = false;       ///< within the tolerance and the ADC did not clip
};

/// What the procedure reports, as kinds with data (the wizard words them).
struct ProbeEvent {
    enum class Kind {
        PointCaptured,  ///< point (number), value
        PointRepeated,  ///< point replaced by a new capture
        PointTyped,
        PointRemoved,
        CaptureFailed,  ///< problem (and the device's message)
        CheckDone,      ///< check
        Fitted,         ///< outcome usable
        FitRefused,     ///< outcome refusal
        Accepted,
        AcceptRefused,  ///< a check failed, a check runs, or no usable fit
        UploadVerified,
        UploadFailed,  ///< upload problem
    };
    Kind kind = Kind::PointCaptured;
    int point = 0;  ///< the point concerned, numbered from 1
    ProbePoint value;
    CaptureProblem problem = CaptureProblem::None;
    std::string deviceMessage;
    std::optional<ProbeCheck> check;
    TableUploadProcedure::Problem uploadProblem = TableUploadProcedure::Problem::None;
};

/// Set-up of a probe linearisation.
struct ProbeProcedureConfig {
    int plane = 0;                     ///< 0 = X (radial), 1 = Y
    int adcBits = 12;                  ///< 10..16
    double referenceDivisionUm = 1.0;  ///< division of the reference instrument, µm (0.1 .. 10)
    int minPoints = 5;                 ///< points before the fit is offered
    ProbeCaptureConfig capture;
    double readbackTimeoutS = 3.0;
};

/// The probe-mandrel linearisation (paper 001, way 2; issue 6, item 5) as a state machine, with
/// no widget: Capture (apply a reference deflection, hold still, average the samples, next
/// point; repeat, type or remove points) → Fit (the characteristic and its table; saturated points
/// refused; verification points read through the table) → Accepted → Upload (send, read back,
/// compare). The operator's actions are the inputs (capture, repeatPoint, next, back, abort,
/// accept), the probe's samples and the upload's progress arrive through pumpProbe/pumpUpload,
/// and what happened comes out as events (takeEvents). The steps' data stays when going back.
class ProbeLinearisationProcedure {
public:
    enum class Step { Capture, Fit, Accepted, Upload };

    /// Throws std::invalid_argument for a configuration out of range.
    explicit ProbeLinearisationProcedure(const ProbeProcedureConfig& config = {});

    // --- set-up (Capture step, no capture running) ---
    /// Plane, ADC resolution and the reference instrument's division; keeps the points.
    void configure(int plane, int adcBits, double referenceDivisionUm);

    // --- the operator's actions ---
    /// Capture: reads a new point at `referenceUm` (hold still, then average). The samples the
    /// port holds from before the command were read under the old load: take them first
    /// (pumpProbe), so the settling starts at the command.
    void capture(double referenceUm);
    /// Capture: reads point `index` (from 0) again at `referenceUm`; the new reading replaces it.
    void repeatPoint(int index, double referenceUm);
    /// Capture: a point typed by hand.
    void typePoint(double referenceUm, double adcCode);
    /// Capture: removes point `index` (from 0).
    void removePoint(int index);
    /// Stops what runs: a capture or check (no point), or the wait for an upload.
    void abort();
    /// The load on the bar changed (a jack moved): the live mean restarts, a running capture ends.
    void loadChanged();
    /// Capture → Fit (enough points, none being read; the fit is made), Accepted → Upload. False when refused.
    bool next();
    /// Fit → Capture, Accepted → Fit, Upload → Accepted (not while an upload runs). The data stays.
    void back();
    /// Back to Capture from any step (an upload running is stopped).
    void returnToCapture();
    /// Fit: another degree (2..4 or kAutoDegree); refits. In Accepted: back to Fit first.
    void setDegree(int degree);
    /// Fit: reads a verification point at `referenceUm` through the table.
    void check(double referenceUm);
    /// Fit → Accepted when the fit is usable and no check failed or runs; emits Accepted or AcceptRefused.
    bool accept();
    /// Accepted → Fit.
    void withdrawAcceptance();
    /// Upload: sends the image of the accepted table as `version` through `port`.
    void startUpload(TableUploadPort& port, std::vector<std::uint8_t> image, std::uint16_t version);

    // --- timed inputs ---
    /// The probe's samples (live mean, a running capture or check); `elapsedS` of wall time.
    void pumpProbe(DeflectionProbe& probe, double elapsedS);
    /// The upload's progress and read-back; `elapsedS` of wall time.
    void pumpUpload(TableUploadPort& port, double elapsedS);

    // --- outputs ---
    /// The events since the last call, oldest first.
    std::vector<ProbeEvent> takeEvents();
    Step step() const { return m_step; }
    const ProbeProcedureConfig& config() const { return m_config; }
    const std::vector<ProbePoint>& points() const { return m_points; }
    /// The points as the linearisation takes them (all, saturated too).
    std::vector<CalibrationPoint> calibrationPoints() const;
    /// The sampling machine (live mean, phase and progress of a running capture).
    const ProbeCapture& sampling() const { return m_capture; }
    /// A capture or check is being read.
    bool capturing() const { return m_capture.running(); }
    /// A running capture reads point index (from 0) again; nullopt for a new point or a check.
    std::optional<int> repeating() const { return m_repeat; }
    bool checking() const { return m_checking; }
    /// Enough points to fit and none being read.
    bool canFit() const;
    int degree() const { return m_degree; }
    /// The fit (after next() from Capture).
    const ProbeFitOutcome& fitOutcome() const { return m_fit; }
    const std::vector<ProbeCheck>& checks() const { return m_checks; }
    bool accepted() const { return m_step == Step::Accepted || m_step == Step::Upload; }
    const TableUploadProcedure& upload() const { return m_upload; }

private:
    void requireStep(Step step, const char* action) const;
    void startCapture(double referenceUm, std::optional<int> repeat, bool check);
    void finishCapture(const ProbeCaptureResult& result);
    void finishCheck(const ProbeCaptureResult& result);
    void refit();
    void reportUpload();
    void report(ProbeEvent event) { m_events.push_back(std::move(event)); }
    static void checkConfig(const ProbeProcedureConfig& config);

    ProbeProcedureConfig m_config;
    Step m_step = Step::Capture;
    ProbeCapture m_capture;
    std::optional<int> m_repeat;
    bool m_checking = false;
    std::vector<ProbePoint> m_points;
    int m_degree = kAutoDegree;
    ProbeFitOutcome m_fit;
    std::vector<ProbeCheck> m_checks;
    TableUploadProcedure m_upload;
    TableUploadProcedure::Phase m_reportedUpload = TableUploadProcedure::Phase::Idle;
    std::vector<ProbeEvent> m_events;
};

}  // namespace tt::core
