#include "ui/run/lathe_panel.h"

#include <QGridLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

namespace tt::ui {

LathePanel::LathePanel(QWidget* parent)
    : QWidget(parent),
      m_machine(new QLabel(this)),
      m_machineDetail(new QLabel(this)),
      m_measure(new QLabel(this)),
      m_measureDetail(new QLabel(this)),
      m_reading(new QPushButton(this)),
      m_finished(new QPushButton(this)) {
    setObjectName(QStringLiteral("lathePanel"));
    setAttribute(Qt::WA_StyledBackground, true);
    setStyleSheet(QStringLiteral(
        "QWidget#lathePanel { background: #ffffff; border: 1px solid #c9ced6; border-radius: 6px; }"
        "QLabel#latheMachineText, QLabel#latheMeasureText { font-size: 16pt; font-weight: bold; color: #1f2a36; }"
        "QLabel#latheMachineDetail, QLabel#latheMeasureDetail { font-size: 13pt; color: #38434f; }"
        "QPushButton#partFinishedButton { font-size: 20pt; min-height: 64px; }"
        "QPushButton#gaugeReadingButton { font-size: 14pt; min-height: 48px; }"));
    m_machine->setObjectName(QStringLiteral("latheMachineText"));
    m_machineDetail->setObjectName(QStringLiteral("latheMachineDetail"));
    m_measure->setObjectName(QStringLiteral("latheMeasureText"));
    m_measureDetail->setObjectName(QStringLiteral("latheMeasureDetail"));
    for (QLabel* l : {m_machine, m_machineDetail, m_measure, m_measureDetail})
        l->setWordWrap(true);
    m_reading->setObjectName(QStringLiteral("gaugeReadingButton"));
    m_finished->setObjectName(QStringLiteral("partFinishedButton"));
    m_finished->setProperty("role", QStringLiteral("primary"));
    for (QPushButton* b : {m_finished, m_reading})
        b->setMinimumWidth(250);
    // What to machine next to the big button; where to measure next to the gauge's.
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(12, 8, 8, 8);
    grid->setHorizontalSpacing(12);
    grid->setVerticalSpacing(6);
    auto* machineTexts = new QVBoxLayout;
    machineTexts->setSpacing(0);
    machineTexts->addWidget(m_machine);
    machineTexts->addWidget(m_machineDetail);
    auto* measureTexts = new QVBoxLayout;
    measureTexts->setSpacing(0);
    measureTexts->addWidget(m_measure);
    measureTexts->addWidget(m_measureDetail);
    grid->addLayout(machineTexts, 0, 0);
    grid->addWidget(m_finished, 0, 1);
    grid->addLayout(measureTexts, 1, 0);
    grid->addWidget(m_reading, 1, 1);
    grid->setColumnStretch(0, 1);
    connect(m_finished, &QPushButton::clicked, this, [this] {
        // One press per part: the part leaves the machine in the loop's thread, so the button waits for
        // the next part the loop reports.
        m_pressedPart = m_view.partOnMachine;
        m_finished->setEnabled(false);
        emit partFinished();
    });
    connect(m_reading, &QPushButton::clicked, this, &LathePanel::readingRequested);
    retranslate();
}

void LathePanel::setView(const View& view) {
    m_view = view;
    retranslate();
}

QString LathePanel::machineText() const {
    if (!m_view.runGoing) return tr("No run on the lathe");
    if (!m_view.partOnMachine) return tr("No part on the machine");
    return tr("Machine part %1").arg(*m_view.partOnMachine);
}

QString LathePanel::machineDetail() const {
    if (!m_view.runGoing) return tr("Press Start: the corrections of part 1 go to the CNC.");
    if (!m_view.partOnMachine) return tr("The next part starts when its corrections are on the CNC.");
    return m_view.cncValue.isEmpty() ? tr("Its corrections are on the CNC.")
                                     : tr("Its corrections are on the CNC (%1).").arg(m_view.cncValue);
}

QString LathePanel::measureText() const {
    const View& v = m_view;
    if (!v.runGoing) return {};
    if (!v.awaitingPart) return tr("Nothing to measure");
    if (v.byHand) return tr("Part %1: type its diameters below").arg(*v.awaitingPart);
    return tr("Measure part %1 at x = %2 mm").arg(*v.awaitingPart).arg(QLocale().toString(v.nextPointXMm, 'f', 1));
}

QString LathePanel::measureDetail() const {
    const View& v = m_view;
    if (!v.runGoing || !v.awaitingPart || v.byHand) return {};
    const QString point = tr("Point %1 of %2").arg(v.nextPoint + 1).arg(v.pointCount);
    return v.gaugeValue.isEmpty() ? point : tr("%1 · last reading %2").arg(point, v.gaugeValue);
}

void LathePanel::retranslate() {
    m_machine->setText(machineText());
    m_machineDetail->setText(machineDetail());
    m_measure->setText(measureText());
    m_measure->setVisible(m_view.runGoing);
    m_measureDetail->setText(measureDetail());
    m_measureDetail->setVisible(!m_measureDetail->text().isEmpty());
    m_reading->setText(tr("Take gauge reading"));
    m_reading->setVisible(m_view.runGoing && m_view.haveGauge && !m_view.byHand);
    m_reading->setEnabled(m_view.awaitingPart.has_value() && m_view.gaugeReady);
    m_finished->setText(m_view.partOnMachine ? tr("Part %1 finished").arg(*m_view.partOnMachine) : tr("Part finished"));
    m_finished->setEnabled(m_view.runGoing && m_view.partOnMachine.has_value() &&
                           m_view.partOnMachine != m_pressedPart);
}

}  // namespace tt::ui
