#include "ui/run/notice_text.h"

#include <QCoreApplication>

namespace tt::ui {

namespace {

QString mm(double value, int decimals = 3) {
    return QString::number(value, 'f', decimals);
}

QString cause(const core::Notice& n) {
    return QString::fromStdString(n.cause);
}

QString stateText(const core::Notice& n) {
    using K = core::NoticeKind;
    switch (n.kind) {
        case K::Starting:
            return QCoreApplication::translate("Notice", "Starting part %1").arg(n.part);
        case K::ContinuingRun:
            return QCoreApplication::translate("Notice", "Continuing run %1 with part %2").arg(n.otherPart).arg(n.part);
        case K::PausedByOperator:
            return QCoreApplication::translate("Notice", "Paused by the operator; the CNC keeps the last correction");
        case K::Machining:
            return QCoreApplication::translate("Notice", "Machining part %1").arg(n.part);
        case K::Continuing:
            return QCoreApplication::translate("Notice", "Continuing");
        case K::Stopped:
            return QCoreApplication::translate("Notice", "Stopped");
        case K::GaugeBack:
            return QCoreApplication::translate("Notice", "The gauge answers again; continuing");
        case K::MeasuringLastParts:
            return QCoreApplication::translate("Notice", "Measuring the last parts (part %1 next)").arg(n.part);
        case K::WaitingForDiameters:
            return QCoreApplication::translate("Notice", "Waiting for the diameters of part %1").arg(n.otherPart);
        case K::GaugeNotReady:
            return QCoreApplication::translate(
                       "Notice",
                       "The gauge is not ready (%1); part %2 needs the diameters of part %3. Paused, the CNC keeps "
                       "the last correction")
                .arg(cause(n))
                .arg(n.part)
                .arg(n.otherPart);
        case K::NoDiameters:
            return QCoreApplication::translate(
                       "Notice", "No diameters of part %1 for %2 min. Paused, the CNC keeps the last correction")
                .arg(n.otherPart)
                .arg(n.value, 0, 'f', 1);
        case K::RunComplete:
            return QCoreApplication::translate("Notice", "Run complete: part %1 was the last").arg(n.part);
        case K::PausedOnScrap:
            return QCoreApplication::translate(
                       "Notice",
                       "Paused: part %1 is scrap; check the machine, then continue. The CNC keeps the last correction")
                .arg(n.part);
        case K::HistoryFull:
            return QCoreApplication::translate("Notice",
                                               "Paused before part %1: the history takes no new part (%2). The run "
                                               "goes on by itself when it does; the CNC keeps the last correction")
                .arg(n.part)
                .arg(cause(n));
        case K::PartFinished:
            return QCoreApplication::translate("Notice", "Part %1 finished").arg(n.part);
        case K::PartMeasured:
            return QCoreApplication::translate("Notice", "Part %1 measured").arg(n.part);
        default:
            return {};
    }
}

/// The mismatch monitor's alarm: which test, over how many parts, and what the loop does about it.
QString mismatchText(const core::Notice& n) {
    const QString test = n.reference == 1.0   ? QCoreApplication::translate("Notice", "correlation")
                         : n.reference == 2.0 ? QCoreApplication::translate("Notice", "independence")
                                              : QCoreApplication::translate("Notice", "variance");
    const QString then =
        n.cause == "hold"
            ? QCoreApplication::translate("Notice", "The CNC keeps the last correction until the run is restarted")
        : n.cause == "adapt" || n.cause == "propose"
            ? QCoreApplication::translate("Notice", "The loop switches to its robust fallback and identifies the plant")
            : QCoreApplication::translate("Notice", "The controller goes on");
    return QCoreApplication::translate("Notice",
                                       "The plant no longer matches the controller's model (part %1, point "
                                       "%2): the %3 test of the innovations over %4 parts is %5, above its "
                                       "limit %6. %7")
        .arg(n.part)
        .arg(n.point)
        .arg(test)
        .arg(n.otherPart)
        .arg(n.value, 0, 'g', 3)
        .arg(n.limit, 0, 'g', 3)
        .arg(then);
}

/// What the loop says about a part's corrections, its tolerance or the controller's model.
/// What the adaptive loop did after a model mismatch (core/loop/adaptive_loop.h).
QString adaptationText(const core::Notice& n) {
    using K = core::NoticeKind;
    switch (n.kind) {
        case K::FallbackEngaged:
            return QCoreApplication::translate(
                       "Notice",
                       "From part %1 the loop corrects with its robust fallback (EWMA, weight %2: stable for plant "
                       "gains 0.5 to 2 times the model's and one more part of delay) while it identifies the plant")
                .arg(n.part)
                .arg(n.value, 0, 'f', 2);
        case K::IdentificationWaiting:
            return QCoreApplication::translate("Notice", "Part %1: the plant cannot be identified yet: %2")
                .arg(n.part)
                .arg(cause(n));
        case K::ControllerAdapted:
            return QCoreApplication::translate(
                       "Notice",
                       "From part %1 the loop corrects with an LQG designed for the plant identified from %2 (plant "
                       "delay %3 parts, smallest gain margin %4); the mismatch monitor restarts on that model")
                .arg(n.part)
                .arg(cause(n))
                .arg(n.value, 0, 'f', 0)
                .arg(n.reference, 0, 'g', 3);
        case K::AdaptationProposed:
            return QCoreApplication::translate(
                       "Notice",
                       "Part %1: an LQG for the plant identified from %2 (plant delay %3 parts) is proposed; the "
                       "fallback goes on until an engineer applies it on the Controller page")
                .arg(n.part)
                .arg(cause(n))
                .arg(n.value, 0, 'f', 0);
        case K::AdaptationRefused:
            return QCoreApplication::translate(
                       "Notice",
                       "Part %1: the design for the identified plant is not applied: %2; the fallback goes on")
                .arg(n.part)
                .arg(cause(n));
        case K::ProposalAccepted:
            return QCoreApplication::translate(
                       "Notice", "From part %1 the loop corrects with the proposed LQG an engineer applied")
                .arg(n.part);
        default:
            return {};
    }
}

}  // namespace

QString controllerInUseText(const core::Notice& n) {
    using K = core::NoticeKind;
    switch (n.kind) {
        case K::FallbackEngaged:
            return QCoreApplication::translate(
                       "Notice",
                       "Controller: robust EWMA fallback (weight %1) from part %2, while the plant is identified")
                .arg(n.value, 0, 'f', 2)
                .arg(n.part);
        case K::ControllerAdapted:
            return QCoreApplication::translate(
                       "Notice", "Controller: LQG adapted at part %1 (plant delay %2 parts, smallest gain margin %3)")
                .arg(n.part)
                .arg(n.value, 0, 'f', 0)
                .arg(n.reference, 0, 'g', 3);
        case K::AdaptationProposed:
            return QCoreApplication::translate(
                "Notice",
                "Controller: robust EWMA fallback; a new design waits for an engineer's Apply (Controller page)");
        case K::AdaptationRefused:
            return QCoreApplication::translate("Notice",
                                               "Controller: robust EWMA fallback; the new design was not applied: %1")
                .arg(cause(n));
        case K::ProposalAccepted:
            return QCoreApplication::translate("Notice", "Controller: LQG applied by an engineer at part %1")
                .arg(n.part);
        default:
            return {};
    }
}

bool controllerInUseIsFallback(const core::Notice& n) {
    using K = core::NoticeKind;
    return n.kind == K::FallbackEngaged || n.kind == K::AdaptationProposed || n.kind == K::AdaptationRefused;
}

namespace {

QString correctionText(const core::Notice& n) {
    using K = core::NoticeKind;
    switch (n.kind) {
        case K::CorrectionsFailed:
            return QCoreApplication::translate(
                       "Notice",
                       "The corrections for part %1 could not be computed (%2); the CNC keeps the last correction")
                .arg(n.part)
                .arg(cause(n));
        case K::CorrectionHeld:
            return QCoreApplication::translate(
                       "Notice",
                       "Part %1: the controller gave no usable correction at point %2 (x = %3 mm); holding %4 mm")
                .arg(n.part)
                .arg(n.point)
                .arg(mm(n.zMm, 1), mm(n.reference));
        case K::CorrectionLimited:
            return QCoreApplication::translate("Notice",
                                               "Part %1: correction at point %2 (x = %3 mm) limited from %4 to %5 mm")
                .arg(n.part)
                .arg(n.point)
                .arg(mm(n.zMm, 1), mm(n.value), mm(n.reference));
        case K::CncRefused:
            return QCoreApplication::translate(
                       "Notice", "The CNC refused the corrections for part %1: %2; it keeps the last correction")
                .arg(n.part)
                .arg(cause(n));
        case K::MachineRefused:
            return QCoreApplication::translate("Notice", "The machine did not start part %1: %2")
                .arg(n.part)
                .arg(cause(n));
        case K::OutOfToleranceRework:
            return QCoreApplication::translate(
                       "Notice", "Part %1, point %2 (x = %3 mm): %4 mm is %5 mm above the upper limit %6 mm: rework")
                .arg(n.part)
                .arg(n.point)
                .arg(mm(n.zMm, 1), mm(n.value), mm(n.value - n.limit), mm(n.limit));
        case K::OutOfToleranceScrap:
            return QCoreApplication::translate(
                       "Notice", "Part %1, point %2 (x = %3 mm): %4 mm is %5 mm below the lower limit %6 mm: scrap")
                .arg(n.part)
                .arg(n.point)
                .arg(mm(n.zMm, 1), mm(n.value), mm(n.limit - n.value), mm(n.limit));
        case K::ModelMismatch:
            return mismatchText(n);
        case K::FallbackEngaged:
        case K::IdentificationWaiting:
        case K::ControllerAdapted:
        case K::AdaptationProposed:
        case K::AdaptationRefused:
        case K::ProposalAccepted:
            return adaptationText(n);
        default:
            return {};
    }
}

QString faultText(const core::Notice& n) {
    using K = core::NoticeKind;
    switch (n.kind) {
        case K::PartAbandoned:
            return QCoreApplication::translate(
                       "Notice", "Part %1 was on the machine when the run was stopped; it is not recorded")
                .arg(n.part);
        case K::HistoryEndFailed:
            return QCoreApplication::translate("Notice", "The end of the run could not be stored: %1").arg(cause(n));
        case K::UnexpectedPartFinished:
            return QCoreApplication::translate(
                       "Notice", "The machine reported part %1 finished, which the loop did not start; ignored")
                .arg(n.part);
        case K::HistoryPartFailed:
            return QCoreApplication::translate(
                       "Notice",
                       "The history could not be written, part %1 is not stored (%2); the CNC keeps the last "
                       "correction")
                .arg(n.part)
                .arg(cause(n));
        case K::ReadingUnexpected:
            return QCoreApplication::translate(
                       "Notice", "A reading of %1 mm arrived but no part is waiting to be measured; it was ignored")
                .arg(mm(n.value));
        case K::HistoryMeasurementFailed:
            return QCoreApplication::translate(
                       "Notice", "The diameters of part %1 could not be stored (%2); the CNC keeps the last correction")
                .arg(n.part)
                .arg(cause(n));
        default:
            return correctionText(n);
    }
}

QString rejectionText(const core::Notice& n) {
    using K = core::NoticeKind;
    switch (n.kind) {
        case K::NotMeasured:
            return QCoreApplication::translate("Notice", "not measured");
        case K::SkippedByOperator:
            return QCoreApplication::translate("Notice", "not measured: skipped by the operator");
        case K::NotANumber:
            return QCoreApplication::translate("Notice", "the reading is not a number");
        case K::NotFinite:
            return QCoreApplication::translate("Notice", "not a finite number");
        case K::AllPointsRead:
            return QCoreApplication::translate(
                "Notice", "every control point already has a reading; re-take a point to replace it");
        case K::Implausible:
            return QCoreApplication::translate(
                       "Notice",
                       "reading %1 mm is more than %2 mm from the nominal %3 mm; check the point (x = %4 mm) and "
                       "measure again")
                .arg(mm(n.value), mm(n.limit), mm(n.reference), mm(n.zMm, 1));
        case K::AlreadyMeasured:
            return QCoreApplication::translate("Notice", "the point was already measured for part %1").arg(n.part);
        case K::NotMachinedYet:
            return QCoreApplication::translate("Notice", "part %1 has not been machined yet").arg(n.part);
        case K::NotUnderController:
            return QCoreApplication::translate("Notice", "part %1 was not machined under this controller").arg(n.part);
        case K::TooLate:
            return QCoreApplication::translate("Notice", "part %1 is too late: the controller keeps the last %2 parts")
                .arg(n.part)
                .arg(static_cast<long long>(n.limit));
        case K::Outlier:
            return QCoreApplication::translate("Notice",
                                               "rejected by the controller: %1 σ from the prediction (gate %2 σ)")
                .arg(n.value, 0, 'g', 3)
                .arg(n.limit, 0, 'g', 3);
        case K::AlarmBand:
            return QCoreApplication::translate(
                       "Notice",
                       "rejected by the controller: the deviation %1 mm reaches the alarm band %2 mm; check the part")
                .arg(n.value, 0, 'g', 4)
                .arg(n.limit, 0, 'g', 4);
        case K::ControllerFailed:
            return QCoreApplication::translate("Notice", "the controller could not use it: %1").arg(cause(n));
        case K::ControllerRejected:
            return QCoreApplication::translate("Notice", "rejected by the controller: %1").arg(cause(n));
        default:
            return {};
    }
}

}  // namespace

QString noticeText(const core::Notice& notice) {
    if (core::isRejection(notice.kind)) return rejectionText(notice);
    if (QString text = stateText(notice); !text.isEmpty()) return text;
    return faultText(notice);
}

QString alarmText(const core::Notice& notice) {
    if (!core::isRejection(notice.kind)) return noticeText(notice);
    return QCoreApplication::translate("Notice", "Part %1, point %2: %3")
        .arg(notice.part)
        .arg(notice.point)
        .arg(noticeText(notice));
}

}  // namespace tt::ui
