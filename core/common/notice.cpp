#include "core/common/notice.h"

#include "core/common/text_format.h"

#include <cmath>

namespace tt::core {

namespace {

std::string partText(std::int64_t n) {
    return "part " + std::to_string(n);
}

std::string pointText(const Notice& n) {
    return "point " + std::to_string(n.point) + " (x = " + formatFixed(n.zMm, 3) + " mm)";
}

const char* kHeld = "; the CNC keeps the last correction";

std::string stateText(const Notice& n) {
    switch (n.kind) {
        case NoticeKind::Starting:
            return "starting " + partText(n.part);
        case NoticeKind::ContinuingRun:
            return "continuing run " + std::to_string(n.otherPart) + " with " + partText(n.part);
        case NoticeKind::PausedByOperator:
            return std::string("paused by the operator") + kHeld;
        case NoticeKind::Machining:
            return "machining " + partText(n.part);
        case NoticeKind::Continuing:
            return "continuing";
        case NoticeKind::Stopped:
            return "stopped";
        case NoticeKind::GaugeBack:
            return "the gauge answers again; continuing";
        case NoticeKind::MeasuringLastParts:
            return "measuring the last parts (" + partText(n.part) + " next)";
        case NoticeKind::WaitingForDiameters:
            return "waiting for the diameters of " + partText(n.otherPart);
        case NoticeKind::GaugeNotReady:
            return "the gauge is not ready (" + n.cause + "); " + partText(n.part) + " needs the diameters of " +
                   partText(n.otherPart) + ". Paused, the CNC keeps the last correction";
        case NoticeKind::NoDiameters:
            return "no diameters of " + partText(n.otherPart) + " for " + formatFixed(n.value, 1) +
                   " min. Paused, the CNC keeps the last correction";
        case NoticeKind::RunComplete:
            return "run complete: " + partText(n.part) + " was the last";
        case NoticeKind::PausedOnScrap:
            return "paused: " + partText(n.part) + " is scrap; check the machine, then continue" + kHeld;
        case NoticeKind::HistoryFull:
            return "paused: the history takes no new part (" + n.cause + "); the run goes on by itself when it does" +
                   kHeld;
        case NoticeKind::PartFinished:
            return partText(n.part) + " finished";
        case NoticeKind::PartMeasured:
            return partText(n.part) + " measured";
        default:
            return {};
    }
}

std::string alarmText(const Notice& n) {
    switch (n.kind) {
        case NoticeKind::PartAbandoned:
            return partText(n.part) + " was on the machine when the run was stopped; it is not recorded";
        case NoticeKind::HistoryEndFailed:
            return "the end of the run could not be stored: " + n.cause;
        case NoticeKind::UnexpectedPartFinished:
            return "the machine reported " + partText(n.part) + " finished, which the loop did not start; ignored";
        case NoticeKind::HistoryPartFailed:
            return "the history could not be written, " + partText(n.part) + " is not stored (" + n.cause + ")" + kHeld;
        case NoticeKind::ReadingUnexpected:
            return "a reading of " + formatFixed(n.value, 3) +
                   " mm arrived but no part is waiting to be measured; it was ignored";
        case NoticeKind::HistoryMeasurementFailed:
            return "the diameters of " + partText(n.part) + " could not be stored (" + n.cause + ")" + kHeld;
        case NoticeKind::CorrectionsFailed:
            return "the corrections for " + partText(n.part) + " could not be computed (" + n.cause + ")" + kHeld;
        case NoticeKind::CorrectionHeld:
            return partText(n.part) + ": the controller gave no usable correction at " + pointText(n) + "; holding " +
                   formatFixed(n.reference, 3) + " mm";
        case NoticeKind::CorrectionLimited:
            return partText(n.part) + ": correction at " + pointText(n) + " limited from " + formatFixed(n.value, 3) +
                   " to " + formatFixed(n.reference, 3) + " mm";
        case NoticeKind::CncRefused:
            return "the CNC refused the corrections for " + partText(n.part) + ": " + n.cause +
                   "; it keeps the last correction";
        case NoticeKind::MachineRefused:
            return "the machine did not start " + partText(n.part) + ": " + n.cause;
        case NoticeKind::OutOfToleranceRework:
            return partText(n.part) + ", " + pointText(n) + ": " + formatFixed(n.value, 3) + " mm is " +
                   formatFixed(n.value - n.limit, 3) + " mm above the upper limit " + formatFixed(n.limit, 3) +
                   " mm (deviation " + formatFixed(n.value - n.reference, 3) + " mm from the nominal): rework";
        case NoticeKind::OutOfToleranceScrap:
            return partText(n.part) + ", " + pointText(n) + ": " + formatFixed(n.value, 3) + " mm is " +
                   formatFixed(n.limit - n.value, 3) + " mm below the lower limit " + formatFixed(n.limit, 3) +
                   " mm (deviation " + formatFixed(n.value - n.reference, 3) + " mm from the nominal): scrap";
        case NoticeKind::ModelMismatch:
            return "the plant no longer matches the controller's model (" + partText(n.part) + ", point " +
                   std::to_string(n.point) + "): the " +
                   (n.reference == 1.0   ? "correlation"
                    : n.reference == 2.0 ? "independence"
                                         : "variance") +
                   " test of the innovations over " + std::to_string(n.otherPart) + " parts is " +
                   formatSignificant(n.value, 3) + ", above its limit " + formatSignificant(n.limit, 3) +
                   (n.cause == "hold"      ? "; the CNC keeps the last correction until the run is restarted"
                    : n.cause == "adapt"   ? "; the loop switches to its robust fallback and identifies the plant"
                    : n.cause == "propose" ? "; the loop switches to its robust fallback, identifies the plant and "
                                             "proposes a new design"
                                           : "; the controller goes on");
        case NoticeKind::FallbackEngaged:
            return "from " + partText(n.part) + " the loop corrects with its robust fallback (EWMA, weight " +
                   formatSignificant(n.value, 2) +
                   ": stable for plant gains 0.5 .. 2 times the model's and one more part of delay) while it "
                   "identifies the plant";
        case NoticeKind::IdentificationWaiting:
            return partText(n.part) + ": the plant cannot be identified yet: " + n.cause;
        case NoticeKind::ControllerAdapted:
            return "from " + partText(n.part) +
                   " the loop corrects with an LQG designed for the plant identified from " + n.cause +
                   " (plant delay " + formatSignificant(n.value, 2) + " parts, smallest gain margin " +
                   (std::isfinite(n.reference) ? formatSignificant(n.reference, 3) : std::string("unlimited")) +
                   "); the mismatch monitor restarts on that model";
        case NoticeKind::AdaptationProposed:
            return partText(n.part) + ": an LQG for the plant identified from " + n.cause + " (plant delay " +
                   formatSignificant(n.value, 2) + " parts, smallest gain margin " +
                   (std::isfinite(n.reference) ? formatSignificant(n.reference, 3) : std::string("unlimited")) +
                   ") is proposed; the fallback goes on until an engineer applies it on the Controller page";
        case NoticeKind::AdaptationRefused:
            return partText(n.part) + ": the design for the identified plant is not applied: " + n.cause +
                   "; the fallback goes on";
        case NoticeKind::ProposalAccepted:
            return "from " + partText(n.part) + " the loop corrects with the proposed LQG an engineer applied";
        default:
            return {};
    }
}

std::string rejectionText(const Notice& n) {
    switch (n.kind) {
        case NoticeKind::NotMeasured:
            return "not measured";
        case NoticeKind::SkippedByOperator:
            return "not measured: skipped by the operator";
        case NoticeKind::NotANumber:
            return "the reading is not a number";
        case NoticeKind::NotFinite:
            return "not a finite number";
        case NoticeKind::AllPointsRead:
            return "every control point already has a reading; re-take a point to replace it";
        case NoticeKind::Implausible:
            return "reading " + formatFixed(n.value, 3) + " mm is more than " + formatFixed(n.limit, 3) +
                   " mm from the nominal " + formatFixed(n.reference, 3) +
                   " mm; check the point (x = " + formatFixed(n.zMm, 3) + " mm) and measure again";
        case NoticeKind::AlreadyMeasured:
            return "point already measured for " + partText(n.part);
        case NoticeKind::NotMachinedYet:
            return partText(n.part) + " has not been machined yet";
        case NoticeKind::NotUnderController:
            return partText(n.part) + " was not machined under this controller";
        case NoticeKind::TooLate:
            return partText(n.part) + " is too late: the controller keeps the last " +
                   std::to_string(static_cast<long long>(n.limit)) + " parts";
        case NoticeKind::Outlier:
            return "outlier: " + formatSignificant(n.value, 3) + " sigma from the prediction (gate " +
                   formatSignificant(n.limit, 3) + " sigma)";
        case NoticeKind::AlarmBand:
            return "alarm: |deviation| " + formatSignificant(n.value, 4) + " mm >= alarm band " +
                   formatSignificant(n.limit, 4) + " mm; not used for correction, check the part";
        case NoticeKind::ControllerFailed:
            return "the controller could not use it: " + n.cause;
        case NoticeKind::ControllerRejected:
            return n.cause.empty() ? std::string("no reason given") : n.cause;
        default:
            return {};
    }
}

/// Stored names, in the order of NoticeKind.
constexpr const char* kKindNames[] = {"none",
                                      "starting",
                                      "continuing-run",
                                      "paused-by-operator",
                                      "machining",
                                      "continuing",
                                      "stopped",
                                      "gauge-back",
                                      "measuring-last-parts",
                                      "waiting-for-diameters",
                                      "gauge-not-ready",
                                      "no-diameters",
                                      "run-complete",
                                      "part-finished",
                                      "part-measured",
                                      "part-abandoned",
                                      "history-end-failed",
                                      "unexpected-part-finished",
                                      "history-part-failed",
                                      "reading-unexpected",
                                      "history-measurement-failed",
                                      "corrections-failed",
                                      "correction-held",
                                      "correction-limited",
                                      "cnc-refused",
                                      "machine-refused",
                                      "not-measured",
                                      "skipped-by-operator",
                                      "not-a-number",
                                      "not-finite",
                                      "all-points-read",
                                      "implausible",
                                      "already-measured",
                                      "not-machined-yet",
                                      "not-under-controller",
                                      "too-late",
                                      "outlier",
                                      "alarm-band",
                                      "controller-failed",
                                      "controller-rejected",
                                      "out-of-tolerance-rework",
                                      "out-of-tolerance-scrap",
                                      "paused-on-scrap",
                                      "model-mismatch",
                                      "history-full",
                                      "fallback-engaged",
                                      "identification-waiting",
                                      "controller-adapted",
                                      "adaptation-proposed",
                                      "adaptation-refused",
                                      "proposal-accepted"};
constexpr std::size_t kKinds = sizeof kKindNames / sizeof kKindNames[0];
static_assert(kKinds == static_cast<std::size_t>(NoticeKind::ProposalAccepted) + 1, "one name per kind");

}  // namespace

std::string noticeKindName(NoticeKind kind) {
    const auto i = static_cast<std::size_t>(kind);
    return i < kKinds ? kKindNames[i] : kKindNames[0];
}

NoticeKind noticeKindFromName(const std::string& name) {
    for (std::size_t i = 0; i < kKinds; ++i)
        if (name == kKindNames[i]) return static_cast<NoticeKind>(i);
    return NoticeKind::None;
}

bool isRejection(NoticeKind kind) {
    return kind >= NoticeKind::NotMeasured && kind <= NoticeKind::ControllerRejected;
}

bool isControllerRejection(NoticeKind kind) {
    return kind >= NoticeKind::AlreadyMeasured && kind <= NoticeKind::ControllerRejected;
}

std::string describe(const Notice& notice) {
    if (isRejection(notice.kind)) return rejectionText(notice);
    if (std::string text = stateText(notice); !text.empty()) return text;
    return alarmText(notice);
}

}  // namespace tt::core
