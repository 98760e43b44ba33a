#include "ui/run/manual_entry_panel.h"

#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QStyle>
#include <QVBoxLayout>

#include "core/loop/measurement_session.h"
#include "ui/run/notice_text.h"

namespace tt::ui {

namespace {

void setInvalid(QLineEdit* field, bool invalid) {
    field->setProperty("invalid", invalid);
    field->style()->unpolish(field);
    field->style()->polish(field);
}

/// A number typed with a point or a comma (the shop floor writes both).
std::optional<double> parseNumber(QString text) {
    text = text.trimmed().replace(QLatin1Char(','), QLatin1Char('.'));
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok) return std::nullopt;
    return v;
}

}  // namespace

ManualEntryPanel::ManualEntryPanel(QWidget* parent)
    : QWidget(parent),
      m_title(new QLabel(this)),
      m_hint(new QLabel(this)),
      m_grid(new QGridLayout),
      m_message(new QLabel(this)) {
    m_title->setObjectName(QStringLiteral("SectionTitle"));
    m_title->setWordWrap(true);
    m_hint->setWordWrap(true);
    m_message->setObjectName(QStringLiteral("diameterMessage"));
    m_message->setStyleSheet(QStringLiteral("color: #c62828; font-weight: bold;"));
    m_message->setWordWrap(true);
    m_message->setVisible(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_title);
    layout->addWidget(m_hint);
    layout->addLayout(m_grid);
    layout->addWidget(m_message);
    m_grid->setHorizontalSpacing(10);
    m_grid->setVerticalSpacing(2);
    retranslate();
}

void ManualEntryPanel::setPoints(const QVector<double>& pointZMm, double nominalDiameterMm, double plausibleRangeMm) {
    m_points = pointZMm;
    m_nominal = nominalDiameterMm;
    m_range = plausibleRangeMm;
    rebuild();
    retranslate();
}

void ManualEntryPanel::rebuild() {
    for (QWidget* w : m_labels)
        delete w;
    for (QWidget* w : m_fields)
        delete w;
    for (QWidget* w : m_units)
        delete w;
    m_labels.clear();
    m_fields.clear();
    m_units.clear();
    showMessage(-1, QString());
    QFont big = font();
    big.setPointSize(20);
    for (int i = 0; i < m_points.size(); ++i) {
        auto* label = new QLabel(this);
        auto* field = new QLineEdit(this);
        auto* unit = new QLabel(QStringLiteral("mm"), this);
        field->setObjectName(QStringLiteral("diameter%1").arg(i));
        field->setFont(big);
        field->setMinimumHeight(52);
        field->setMinimumWidth(110);
        field->setMaxLength(12);
        field->setInputMethodHints(Qt::ImhFormattedNumbersOnly);
        connect(field, &QLineEdit::returnPressed, this, [this, i] { onReturn(i); });
        connect(field, &QLineEdit::textEdited, this, [this, i] {
            setInvalid(m_fields[i], false);
            if (m_messageField == i) showMessage(-1, QString());
        });
        // The fields stand left to right like the points along the shaft (and the plot's x axis).
        unit->setVisible(false);
        m_grid->addWidget(label, 0, i);
        m_grid->addWidget(field, 1, i);
        m_labels.push_back(label);
        m_fields.push_back(field);
        m_units.push_back(unit);
    }
}

void ManualEntryPanel::retranslate() {
    m_title->setText(m_part ? tr("Part %1 by hand: diameters in mm, nominal %2, Enter for the next point")
                                  .arg(*m_part)
                                  .arg(QLocale().toString(m_nominal, 'f', 3))
                            : tr("By hand: no part is waiting for its diameters"));
    m_hint->setVisible(false);
    for (int i = 0; i < m_labels.size(); ++i)
        m_labels[i]->setText(tr("x = %1 mm").arg(QLocale().toString(m_points[i], 'f', 1)));
    for (QLineEdit* f : m_fields)
        f->setPlaceholderText(QLocale().toString(m_nominal, 'f', 3));
}

void ManualEntryPanel::setAwaitingPart(std::optional<qint64> partNumber) {
    if (partNumber == m_part) return;
    m_part = partNumber;
    retranslate();
}

QString ManualEntryPanel::message(int index) const {
    return index == m_messageField ? m_message->text() : QString();
}

void ManualEntryPanel::showMessage(int index, const QString& text) {
    m_messageField = text.isEmpty() ? -1 : index;
    m_message->setText(text);
    m_message->setVisible(!text.isEmpty());
}

std::optional<double> ManualEntryPanel::check(int index) {
    QLineEdit* field = m_fields[index];
    QString reason;
    const std::optional<double> value = parseNumber(field->text());
    if (!value) {
        reason = tr("'%1' is not a diameter in mm.").arg(field->text());
    } else {
        // The measuring session's own rule and wording: nominal ± the plausible range.
        core::MeasurementSession rule({m_points[index]}, m_nominal, m_range);
        const core::SessionAccept verdict = rule.accept({*value, 0.0});
        if (!verdict.accepted) reason = tr("Rejected: %1").arg(noticeText(verdict.refusal));
    }
    setInvalid(field, !reason.isEmpty());
    if (reason.isEmpty() && m_messageField == index) showMessage(-1, QString());
    if (!reason.isEmpty()) {
        const QString text = tr("Point %1: %2").arg(index + 1).arg(reason);
        showMessage(index, text);
        emit valueRefused(text);
        field->selectAll();
        field->setFocus();
        return std::nullopt;
    }
    return value;
}

void ManualEntryPanel::onReturn(int index) {
    if (!check(index)) return;
    if (index + 1 < m_fields.size()) {
        m_fields[index + 1]->setFocus();
        m_fields[index + 1]->selectAll();
        return;
    }
    QVector<double> values;
    for (int i = 0; i < m_fields.size(); ++i) {
        const std::optional<double> v = check(i);
        if (!v) return;
        values.push_back(*v);
    }
    if (!m_part) {
        showMessage(index, tr("No part is waiting for its diameters: nothing was sent."));
        return;
    }
    emit diametersEntered(*m_part, values);
    for (QLineEdit* f : m_fields)
        f->clear();
    if (!m_fields.isEmpty()) m_fields.front()->setFocus();
}

}  // namespace tt::ui
