#include "ui/boring/hold_reason.h"

#include <QCoreApplication>

namespace tt::ui {

namespace {

QString problemText(core::ReadingProblem problem, BoringSource source) {
    switch (problem) {
        case core::ReadingProblem::SourceNotReady:
            return source == BoringSource::Current
                       ? QCoreApplication::translate("BoringPanel",
                                                     "The drive current read-out is silent or disconnected.")
                       : QCoreApplication::translate("BoringPanel", "The probe mandrel is silent or disconnected.");
        case core::ReadingProblem::NoRecentSample:
            return QCoreApplication::translate("BoringPanel",
                                               "No data from the probe mandrel for more than half a second.");
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
    return {};
}

}  // namespace

CycleWords describeCycle(const core::CompensationCycle& cycle, BoringSource source) {
    CycleWords words;
    const core::CompensationStep& step = cycle.step;
    const QString offset = QString::number(step.offsetMm, 'f', 3);
    words.detail = QString::fromStdString(step.holding ? step.reason : cycle.reading.reason);
    if (!cycle.outputError.empty()) {
        words.holding = true;
        words.headline = QCoreApplication::translate("BoringPanel", "Holding the offset at %1 mm").arg(offset);
        words.reason = QCoreApplication::translate("BoringPanel", "The CNC does not take the offset: %1")
                           .arg(QString::fromStdString(cycle.outputError));
        return words;
    }
    if (step.holding) {
        words.holding = true;
        words.headline = QCoreApplication::translate("BoringPanel", "Holding the offset at %1 mm").arg(offset);
        words.reason = problemText(cycle.reading.problem, source);
        if (words.reason.isEmpty()) words.reason = words.detail;
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

}  // namespace tt::ui
