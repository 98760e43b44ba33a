#include "ui/run/verdict_counter.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QStyle>

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
      m_rework(bigLabel(this, "verdictRework", "#9a5b00")),
      m_scrap(bigLabel(this, "verdictScrap", "#c62828")),
      m_yield(bigLabel(this, "verdictYield", nullptr)),
      m_last(new QLabel(this)) {
    setObjectName(QStringLiteral("verdictCounter"));
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 2, 0, 2);
    grid->setVerticalSpacing(4);
    grid->setHorizontalSpacing(16);
    m_last->setObjectName(QStringLiteral("lastPartVerdict"));  // colours and size: resources/style/trueturn.qss
    m_last->setAlignment(Qt::AlignCenter);
    m_last->setMinimumHeight(44);
    m_last->setWordWrap(true);
    grid->addWidget(m_last, 0, 0, 1, 3);
    grid->addWidget(m_good, 1, 0);
    grid->addWidget(m_rework, 1, 1);
    grid->addWidget(m_scrap, 1, 2);
    grid->addWidget(m_yield, 2, 0, 1, 3);
    retranslate();
}

void VerdictCounter::onLoopEvent(const core::LoopEvent& event) {
    if (event.kind == core::LoopEvent::Kind::StateChanged) followScrapPause(event);
    if (event.kind != core::LoopEvent::Kind::PartMeasured || !event.measurement) return;
    const std::optional<core::ToleranceVerdict> verdict = event.measurement->verdict();
    if (!verdict) return;
    m_counts.add(*verdict);
    m_lastVerdict = verdict;
    m_lastPart = event.partNumber;
    if (!m_holdingScrap) {
        m_shownVerdict = verdict;
        m_shownPart = event.partNumber;
    }
    updateTexts();
    if (*verdict != core::ToleranceVerdict::Good) emit outOfTolerance(*verdict);
}

void VerdictCounter::followScrapPause(const core::LoopEvent& stateChange) {
    if (stateChange.state == core::LoopState::Paused && stateChange.notice.kind == core::NoticeKind::PausedOnScrap) {
        m_holdingScrap = true;
        m_shownVerdict = core::ToleranceVerdict::Scrap;
        m_shownPart = stateChange.notice.part;
    } else if (stateChange.state != core::LoopState::Paused && m_holdingScrap) {
        m_holdingScrap = false;
        m_shownVerdict = m_lastVerdict;
        m_shownPart = m_lastPart;
    } else {
        return;
    }
    updateTexts();
}

void VerdictCounter::reset() {
    m_counts = {};
    m_lastVerdict.reset();
    m_lastPart = 0;
    m_shownVerdict.reset();
    m_shownPart = 0;
    m_holdingScrap = false;
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
    QString key = QStringLiteral("none");
    QString text = tr("No part measured yet");
    if (m_shownVerdict) {
        switch (*m_shownVerdict) {
            case core::ToleranceVerdict::Good:
                key = QStringLiteral("good");
                text = tr("Part %1: GOOD").arg(m_shownPart);
                break;
            case core::ToleranceVerdict::Rework:
                key = QStringLiteral("rework");
                text = tr("Part %1: REWORK").arg(m_shownPart);
                break;
            case core::ToleranceVerdict::Scrap:
                key = QStringLiteral("scrap");
                text = tr("Part %1: SCRAP").arg(m_shownPart);
                break;
        }
    }
    m_last->setText(text);
    m_last->setProperty("verdict", key);
    m_last->style()->unpolish(m_last);
    m_last->style()->polish(m_last);
    m_good->setText(tr("Good: %1").arg(m_counts.good));
    m_rework->setText(tr("Rework: %1").arg(m_counts.rework));
    m_scrap->setText(tr("Scrap: %1").arg(m_counts.scrap));
    const std::optional<double> yield = m_counts.yield();
    m_yield->setText(yield ? tr("Yield: %1 % of %n part(s)", nullptr, static_cast<int>(m_counts.total()))
                                 .arg(*yield * 100.0, 0, 'f', 1)
                           : tr("Yield: no part yet"));
}

}  // namespace tt::ui
