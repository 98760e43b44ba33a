#pragma once

#include <cstdint>
#include <limits>
#include <string>

namespace tt::core {

/// What the engine tells the operator (the loop's state, its alarms, why a measured value is not used),
/// as a kind with its data. The UI words a notice in the user's language (ui/run/notice_text.h); the CLI
/// and the history use the stable English of describe().
enum class NoticeKind {
    None,
    // ---- the loop's state ----
    Starting,             ///< part: the first part of a new run
    ContinuingRun,        ///< otherPart: the run id, part: the next part (resume)
    PausedByOperator,     ///<
    Machining,            ///< part
    Continuing,           ///< (the operator continued, no part on the machine)
    Stopped,              ///<
    GaugeBack,            ///< the gauge answers again
    MeasuringLastParts,   ///< part: the next part to be measured (no new part is started)
    WaitingForDiameters,  ///< otherPart: the part whose diameters the next part needs
    GaugeNotReady,        ///< part: the next part, otherPart: the part due, cause: the gauge's words
    NoDiameters,          ///< otherPart: the part due, value: minutes waited
    RunComplete,          ///< part: the last part of the run
    // ---- events ----
    PartFinished,  ///< part
    PartMeasured,  ///< part
    // ---- alarms and faults ----
    PartAbandoned,             ///< part: on the machine when the run was stopped
    HistoryEndFailed,          ///< cause: the storage's words
    UnexpectedPartFinished,    ///< part: reported by the machine, not started by the loop
    HistoryPartFailed,         ///< part, cause
    ReadingUnexpected,         ///< value: the reading, mm (no part waits to be measured)
    HistoryMeasurementFailed,  ///< part, cause
    CorrectionsFailed,         ///< part, cause
    CorrectionHeld,            ///< part, point, z, reference: the correction held, mm (no usable correction)
    CorrectionLimited,         ///< part, point, z, value: asked, reference: applied, mm
    CncRefused,                ///< part, cause: the CNC output's words
    MachineRefused,            ///< part, cause: the machine's words
    // ---- why a measured value is not used (part, point when known) ----
    NotMeasured,         ///< no reading
    SkippedByOperator,   ///< the operator declared the part not measured
    NotANumber,          ///< the reading is not a number
    NotFinite,           ///< the value is infinite
    AllPointsRead,       ///< every point already has a reading
    Implausible,         ///< value: reading, reference: nominal, limit: window, z: point position (mm)
    AlreadyMeasured,     ///< the point was already measured for the part
    NotMachinedYet,      ///< the part has not been machined yet
    NotUnderController,  ///< the part was machined before this controller took over
    TooLate,             ///< limit: the parts the controller keeps
    Outlier,             ///< value: distance from the prediction, limit: the gate, in sigma
    AlarmBand,           ///< value: |deviation|, limit: the alarm band, mm
    ControllerFailed,    ///< cause: the controller's words
    ControllerRejected,  ///< cause: the controller's own reason (a controller without kinds)
    // ---- tolerances (after the rejections: the stored names and the order above never change) ----
    OutOfToleranceRework,  ///< part, point, z, value: measured, reference: nominal, limit: upper limit (mm)
    OutOfToleranceScrap,   ///< part, point, z, value: measured, reference: nominal, limit: lower limit (mm)
    PausedOnScrap,         ///< part: the scrap part (state: the loop paused itself, the operator continues)
    // ---- the controller's model ----
    /// part, point (the one contributing most), value: test statistic, limit: its limit, otherPart: parts
    /// in the window, reference: 1 = the correlation test, 0 = the variance test, 2 = the independence test of the
    /// points (their innovations move together); cause: "hold" when the
    /// CNC now keeps the last correction; "adapt" / "propose" when the loop switches to its fallback and identifies
    ModelMismatch,
    // ---- the history ----
    /// The history store takes no new part (a terminal's journal at its size limit while the plant database
    /// is unreachable): value: bytes used, limit: the limit in bytes, cause: the store's words. The loop pauses
    /// before the next part and goes on by itself once the store takes parts again.
    HistoryFull,
    // ---- the adaptive loop (after the model mismatch: the stored names and the order above never change) ----
    FallbackEngaged,        ///< part: the fallback takes over here, otherPart: the alarm's part, value: its EWMA weight
    IdentificationWaiting,  ///< part, value: parts more needed (NaN: more parts alone will not do), cause: why
    ControllerAdapted,   ///< part: takes over here, value: plant delay, reference: smallest gain margin, cause: source
    AdaptationProposed,  ///< part, value: plant delay, reference: smallest gain margin, cause: the data's source
    AdaptationRefused,   ///< part, cause: why the new design is not applied (its margins)
    ProposalAccepted,    ///< part: the proposed design takes over here
};

/// One notice with its data (which fields are set depends on the kind, see NoticeKind).
struct Notice {
    Notice() = default;
    /// A notice of `kind` about part `part` (and a second part or the run, `other`).
    explicit Notice(NoticeKind kind_, std::int64_t part_ = 0, std::int64_t other = 0)
        : kind(kind_), part(part_), otherPart(other) {}

    NoticeKind kind = NoticeKind::None;
    std::int64_t part = 0;
    std::int64_t otherPart = 0;
    int point = 0;  ///< control point, 1-based; 0: none
    double value = std::numeric_limits<double>::quiet_NaN();
    double reference = std::numeric_limits<double>::quiet_NaN();
    double limit = std::numeric_limits<double>::quiet_NaN();
    double zMm = std::numeric_limits<double>::quiet_NaN();
    std::string cause;  ///< the words of a device or the storage (device texts are in the user's language)

    explicit operator bool() const { return kind != NoticeKind::None; }
};

/// Whether the kind says why a measured value is not used (NotMeasured .. ControllerRejected).
bool isRejection(NoticeKind kind);
/// Whether the rejection comes from the controller (not from the measurement's plausibility check).
bool isControllerRejection(NoticeKind kind);

/// Stable, untranslated name of a kind ("implausible"), stored in the history.
std::string noticeKindName(NoticeKind kind);
/// The kind of a stored name; NoticeKind::None for an unknown name.
NoticeKind noticeKindFromName(const std::string& name);

/// The stable English words of a notice ("part 7 finished"), for the command line and the history.
std::string describe(const Notice& notice);

}  // namespace tt::core
