#include "ui/run/verdict_counter.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>

namespace tt::ui {

namespace {

QLabel* bigLabel(QWidget* parent, const char* name, const char* colour) {
    auto* label = new QLabel(parent);
    label->setObjectName(QString::fromLatin1(name));
    QFont f = label->font();
    f.setPointSize(16);
    f.setBold(true);
    label->setFont(f);
    if (colour) label->setStyleSheet(QStringLiteral("color: %1;").arg(QString::fromLatin1(colour)));
    return label;
}

}  // namespace

VerdictCounter::VerdictCounter(QWidget* parent)
    : QWidget(parent),
      m_good(bigLabel(this, "verdictGood", "#2e7d32")),
      m_rework(bigLabel(this, "verdictRework", "#b26a00")),
      m_scrap(bigLabel(this, "verdictScrap", "#c62828")),
      m_yield(bigLabel(this, "verdictYield", nullptr)) {
    setObjectName(QStringLiteral("verdictCounter"));
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 4, 0, 4);
    grid->setHorizontalSpacing(16);
    grid->addWidget(m_good, 0, 0);
    grid->addWidget(m_rework, 0, 1);
    grid->addWidget(m_scrap, 0, 2);
    grid->addWidget(m_yield, 1, 0, 1, 3);
    retranslate();
}

void VerdictCounter::onLoopEvent(const core::LoopEvent& event) {
    if (event.kind != core::LoopEvent::Kind::PartMeasured || !event.measurement) return;
    const std::optional<core::ToleranceVerdict> verdict = event.measurement->verdict();
    if (!verdict) return;
    m_counts.add(*verdict);
    updateTexts();
}

void VerdictCounter::reset() {
    m_counts = {};
    updateTexts();
}

void VerdictCounter::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void VerdictCounter::retranslate() {
    updateTexts();
}

void VerdictCounter::updateTexts() {
    m_good->setText(tr("Good: %1").arg(m_counts.good));
    m_rework->setText(tr("Rework: %1").arg(m_counts.rework));
    m_scrap->setText(tr("Scrap: %1").arg(m_counts.scrap));
    const std::optional<double> yield = m_counts.yield();
    m_yield->setText(yield ? tr("Yield: %1 % of %n part(s)", nullptr, static_cast<int>(m_counts.total()))
                                 .arg(*yield * 100.0, 0, 'f', 1)
                           : tr("Yield: no part yet"));
}

}  // namespace tt::ui
