#include "ui/boring/hold_reason.h"

#include <QCoreApplication>
#include <cmath>

namespace tt::ui {

namespace {

QString mm(double v) {
    return QString::number(v, 'f', 3);
}

QString problemText(const core::DeflectionReading& reading, core::BoringMethod method) {
    switch (reading.problem) {
        case core::ReadingProblem::SourceNotReady:
            return method == core::BoringMethod::Current
                       ? QCoreApplication::translate("BoringPanel",
                                                     "The drive current read-out is silent or disconnected.")
                       : QCoreApplication::translate("BoringPanel", "The probe mandrel is silent or disconnected.");
        case core::ReadingProblem::NoRecentSample:
            return QCoreApplication::translate("BoringPanel", "No data from the probe mandrel for more than %1 ms.")
                .arg(std::lround(reading.silenceLimitS * 1000.0));
        case core::ReadingProblem::NoTable:
            return QCoreApplication::translate(
                "BoringPanel",
                "The probe mandrel sends raw codes without a linearisation table: load one on the "
                "Calibration page.");
        case core::ReadingProblem::NotCylindrical:
            return QCoreApplication::translate(
                "BoringPanel", "Taper or contour (or a feed move): the force cannot be read from the current here.");
        case core::ReadingProblem::SlideNotMoving:
            return QCoreApplication::translate(
                "BoringPanel", "The cross slide does not move with the dither: it sticks, or the dither is off.");
        case core::ReadingProblem::WindowTooShort:
            return QCoreApplication::translate(
                "BoringPanel",
                "The dither stroke is too short for this PLC cycle: too few readings at constant speed. "
                "Use a longer dither period or a shorter PLC cycle.");
        case core::ReadingProblem::WaitingForStrokes:
            return QCoreApplication::translate("BoringPanel", "Waiting for a forward and a reverse dither stroke.");
        case core::ReadingProblem::None:
            break;
    }
    return QCoreApplication::translate("BoringPanel", "No valid deflection this cycle.");
}

/// What a device says about itself: its own message, or its state.
QString deviceDetail(const core::DeviceHealth& health) {
    const QString message = QString::fromStdString(health.message);
    return QCoreApplication::translate("BoringPanel", "The device reports: %1")
        .arg(message.isEmpty() ? deviceStateWords(health.state) : message);
}

}  // namespace

QString deviceStateWords(core::DeviceState state) {
    switch (state) {
        case core::DeviceState::Ready:
            return QCoreApplication::translate("BoringPanel", "ready");
        case core::DeviceState::Connecting:
            return QCoreApplication::translate("BoringPanel", "not answering yet");
        case core::DeviceState::Disconnected:
            return QCoreApplication::translate("BoringPanel", "disconnected");
        case core::DeviceState::Error:
            return QCoreApplication::translate("BoringPanel", "in error");
    }
    return {};
}

CycleWords describeCycle(const core::CompensationCycle& cycle, core::BoringMethod method) {
    CycleWords words;
    const core::CompensationStep& step = cycle.step;
    const QString held =
        QCoreApplication::translate("BoringPanel", "Holding the offset at %1 mm").arg(mm(step.offsetMm));
    switch (cycle.outputProblem) {
        case core::OutputProblem::NotReady:
            words.holding = true;
            words.headline = held;
            words.reason = QCoreApplication::translate("BoringPanel", "The CNC output is %1.")
                               .arg(deviceStateWords(cycle.outputHealth.state));
            if (!cycle.outputHealth.message.empty()) words.detail = deviceDetail(cycle.outputHealth);
            return words;
        case core::OutputProblem::Refused:
            words.holding = true;
            words.headline = held;
            words.reason = cycle.outputMessage.empty()
                               ? QCoreApplication::translate("BoringPanel", "The CNC does not take the offset.")
                               : QCoreApplication::translate("BoringPanel", "The CNC does not take the offset: %1")
                                     .arg(QString::fromStdString(cycle.outputMessage));
            return words;
        case core::OutputProblem::None:
            break;
    }
    if (step.holding) {
        words.holding = true;
        words.headline = held;
        words.reason = problemText(cycle.reading, method);
        if (cycle.reading.problem == core::ReadingProblem::SourceNotReady)
            words.detail = deviceDetail(cycle.reading.sourceHealth);
        return words;
    }
    words.headline = QCoreApplication::translate("BoringPanel", "Compensating");
    if (step.rangeLimited)
        words.reason = QCoreApplication::translate(
            "BoringPanel", "The offset is at its range limit: the deflection is larger than the limit allows.");
    else if (step.rateLimited)
        words.reason = QCoreApplication::translate("BoringPanel", "The offset moves at its rate limit.");
    else
        words.reason = QCoreApplication::translate("BoringPanel", "The offset follows the measured deflection.");
    return words;
}

QString describeRefusal(const core::BoringRunRefused& refusal) {
    using R = core::BoringRunRefusal;
    switch (refusal.kind()) {
        case R::NoStiffness:
            return QCoreApplication::translate(
                "BoringPanel", "The tool has no stiffness: enter its section and overhang on the Tools page.");
        case R::NoCurrentGain:
            return QCoreApplication::translate(
                "BoringPanel", "The tool has no current-to-force gain k_p: calibrate it on the Calibration page.");
        case R::NoDriveReadout:
            return QCoreApplication::translate("BoringPanel", "The chosen source has no drive current read-out.");
        case R::NoProbe:
            return QCoreApplication::translate("BoringPanel", "The chosen source has no probe mandrel.");
        case R::BadPlane:
            return QCoreApplication::translate("BoringPanel", "Choose the mandrel's plane that lies along X.");
        case R::OffsetLimitOutOfRange:
            return QCoreApplication::translate("BoringPanel", "The offset limit of %1 mm is outside %2 to %3 mm.")
                .arg(mm(refusal.value()), mm(refusal.min()), mm(refusal.max()));
        case R::RateLimitOutOfRange:
            return QCoreApplication::translate("BoringPanel", "The rate limit of %1 mm/s is outside %2 to %3 mm/s.")
                .arg(QString::number(refusal.value(), 'f', 4), QString::number(refusal.min(), 'f', 4),
                     QString::number(refusal.max(), 'f', 1));
        case R::PlcCycleOutOfRange:
            return QCoreApplication::translate("BoringPanel", "The PLC cycle of %1 ms is outside %2 to %3 ms.")
                .arg(std::lround(refusal.value() * 1000.0))
                .arg(std::lround(refusal.min() * 1000.0))
                .arg(std::lround(refusal.max() * 1000.0));
        case R::PlcCycleNotTheStations:
            return QCoreApplication::translate("BoringPanel",
                                               "The simulated station runs at a PLC cycle of %1 ms, not %2 ms.")
                .arg(std::lround(refusal.max() * 1000.0))
                .arg(std::lround(refusal.value() * 1000.0));
        case R::EstimatorSettings:
            return QCoreApplication::translate("BoringPanel", "The force estimator's settings are refused.");
        case R::HeldOffsetBeyondLimit:
            return QCoreApplication::translate(
                       "BoringPanel",
                       "The CNC holds an offset of %1 mm, more than the limit of %2 mm: zero the offset first (tool "
                       "out of the bore).")
                .arg(mm(refusal.value()), mm(refusal.max()));
    }
    return QCoreApplication::translate("BoringPanel", "The run is refused.");
}

}  // namespace tt::ui
