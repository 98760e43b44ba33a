#include "ui/devices/settings_form.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QStyle>
#include <QVBoxLayout>

#include "devices/api/serial_settings.h"

namespace tt::ui {

using devices::SettingField;

namespace {

void setInvalid(QWidget* w, bool invalid) {
    w->setProperty("invalid", invalid);
    w->style()->unpolish(w);
    w->style()->polish(w);
}

}  // namespace

SettingsForm::SettingsForm(QWidget* parent) : QWidget(parent), m_layout(new QFormLayout(this)) {
    m_layout->setContentsMargins(0, 0, 0, 0);
    m_layout->setVerticalSpacing(6);
    m_layout->setHorizontalSpacing(16);
    m_layout->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_layout->setRowWrapPolicy(QFormLayout::DontWrapRows);
    // The global style frames invalid line edits; combo boxes get the same here.
    setStyleSheet(
        QStringLiteral("QComboBox[invalid=\"true\"] { border: 2px solid #c62828; background: #fdecea; }"
                       "QLabel#FieldIssue { color: #c62828; font-weight: bold; }"
                       "QLabel#FieldUnit { color: #38434f; min-width: 70px; }"));
}

QWidget* SettingsForm::makeEditor(const SettingField& field) {
    switch (field.type) {
        case SettingField::Type::Bool: {
            auto* box = new QCheckBox(this);
            connect(box, &QCheckBox::toggled, this, [this] {
                updateVisibility();
                if (!m_filling) emit edited();
            });
            return box;
        }
        case SettingField::Type::Choice: {
            auto* combo = new QComboBox(this);
            for (const devices::SettingChoice& c : field.choices)
                combo->addItem(c.label, c.value);  // labels again in applyTexts()
            connect(combo, &QComboBox::currentIndexChanged, this, [this] {
                updateVisibility();
                if (!m_filling) emit edited();
            });
            return combo;
        }
        case SettingField::Type::SerialPort: {
            auto* combo = new QComboBox(this);
            combo->setEditable(true);
            combo->setInsertPolicy(QComboBox::NoInsert);
            combo->addItems(devices::availableSerialPorts());
            connect(combo, &QComboBox::editTextChanged, this, [this] {
                if (!m_filling) emit edited();
            });
            return combo;
        }
        case SettingField::Type::Integer:
            if (!field.allowedValues.isEmpty()) {
                auto* combo = new QComboBox(this);
                combo->setEditable(true);
                combo->setInsertPolicy(QComboBox::NoInsert);
                for (qint64 v : field.allowedValues)
                    combo->addItem(QString::number(v));
                connect(combo, &QComboBox::editTextChanged, this, [this] {
                    if (!m_filling) emit edited();
                });
                return combo;
            }
            [[fallthrough]];
        case SettingField::Type::Number:
        case SettingField::Type::Text:
        case SettingField::Type::Folder: {
            auto* edit = new QLineEdit(this);
            connect(edit, &QLineEdit::textEdited, this, [this] {
                if (!m_filling) emit edited();
            });
            return edit;
        }
    }
    return new QLineEdit(this);
}

void SettingsForm::setSchema(const devices::SettingsSchema& schema, const QVariantMap& values) {
    while (m_layout->rowCount() > 0)
        m_layout->removeRow(0);
    m_rows.clear();
    for (const SettingField& field : schema) {
        Row row;
        row.field = field;
        row.label = new QLabel(this);
        row.editor = makeEditor(field);
        row.editor->setObjectName(QStringLiteral("field_") + field.key);
        row.editor->setMinimumWidth(220);
        auto* editorLine = new QWidget(this);
        auto* line = new QHBoxLayout(editorLine);
        line->setContentsMargins(0, 0, 0, 0);
        line->addWidget(row.editor, 1);
        row.unit = new QLabel(editorLine);
        row.unit->setObjectName(QStringLiteral("FieldUnit"));
        line->addWidget(row.unit);
        row.issue = new QLabel(this);
        row.issue->setObjectName(QStringLiteral("FieldIssue"));
        row.issue->setWordWrap(true);
        row.issue->hide();
        auto* column = new QWidget(this);
        auto* stack = new QVBoxLayout(column);
        stack->setContentsMargins(0, 0, 0, 0);
        stack->setSpacing(2);
        stack->addWidget(editorLine);
        stack->addWidget(row.issue);
        row.line = column;
        m_layout->addRow(row.label, column);
        applyTexts(row);
        m_rows.append(row);
    }
    setValues(devices::withDefaults(schema, values));
}

void SettingsForm::applyTexts(const Row& row) {
    const SettingField& field = row.field;
    row.label->setText(field.label);
    row.unit->setText(field.unit);
    row.editor->setToolTip(field.help);
    if (auto* combo = qobject_cast<QComboBox*>(row.editor); combo && field.type == SettingField::Type::Choice) {
        for (const devices::SettingChoice& c : field.choices)
            if (const int index = combo->findData(c.value); index >= 0) combo->setItemText(index, c.label);
    } else if (auto* edit = qobject_cast<QLineEdit*>(row.editor);
               edit && (field.type == SettingField::Type::Integer || field.type == SettingField::Type::Number) &&
               field.minimum < field.maximum) {
        edit->setPlaceholderText(tr("%1 to %2").arg(field.minimum).arg(field.maximum));
    }
}

void SettingsForm::setTexts(const devices::SettingsSchema& schema) {
    for (Row& row : m_rows) {
        for (const SettingField& field : schema) {
            if (field.key != row.field.key) continue;
            row.field = field;
            applyTexts(row);
        }
    }
}

void SettingsForm::writeEditor(const Row& row, const QVariant& value) {
    if (auto* box = qobject_cast<QCheckBox*>(row.editor)) {
        box->setChecked(value.toBool());
    } else if (auto* combo = qobject_cast<QComboBox*>(row.editor)) {
        if (combo->isEditable()) {
            combo->setEditText(value.toString());
        } else {
            const int index = combo->findData(value.toString());
            combo->setCurrentIndex(index >= 0 ? index : 0);
        }
    } else if (auto* edit = qobject_cast<QLineEdit*>(row.editor)) {
        edit->setText(value.toString());
    }
}

void SettingsForm::setValues(const QVariantMap& values) {
    m_filling = true;
    for (const Row& row : m_rows)
        writeEditor(row, values.value(row.field.key, row.field.defaultValue));
    m_filling = false;
    updateVisibility();
    showIssues({});
}

QVariant SettingsForm::readEditor(const Row& row) const {
    if (auto* box = qobject_cast<QCheckBox*>(row.editor)) return box->isChecked();
    QString text;
    if (auto* combo = qobject_cast<QComboBox*>(row.editor))
        text = combo->isEditable() ? combo->currentText().trimmed() : combo->currentData().toString();
    else if (auto* edit = qobject_cast<QLineEdit*>(row.editor))
        text = row.field.type == SettingField::Type::Text ? edit->text() : edit->text().trimmed();
    bool ok = false;
    if (row.field.type == SettingField::Type::Integer) {
        const qlonglong v = text.toLongLong(&ok);
        if (ok) return v;
    } else if (row.field.type == SettingField::Type::Number) {
        const double v = QString(text).replace(QLatin1Char(','), QLatin1Char('.')).toDouble(&ok);
        if (ok) return v;
    }
    return text;
}

QVariantMap SettingsForm::values() const {
    QVariantMap map;
    for (const Row& row : m_rows)
        map.insert(row.field.key, readEditor(row));
    return map;
}

void SettingsForm::updateVisibility() {
    const QVariantMap current = values();
    for (const Row& row : m_rows) {
        const bool visible = devices::isFieldVisible(row.field, current);
        row.label->setVisible(visible);
        row.line->setVisible(visible);
    }
}

void SettingsForm::showIssues(const QList<devices::SettingIssue>& issues) {
    for (const Row& row : m_rows) {
        QString message;
        for (const devices::SettingIssue& issue : issues)
            if (issue.key == row.field.key) message = issue.message;
        row.issue->setText(message);
        row.issue->setVisible(!message.isEmpty());
        setInvalid(row.editor, !message.isEmpty());
    }
}

QWidget* SettingsForm::editor(const QString& key) const {
    for (const Row& row : m_rows)
        if (row.field.key == key) return row.editor;
    return nullptr;
}

QString SettingsForm::issueText(const QString& key) const {
    for (const Row& row : m_rows)
        if (row.field.key == key) return row.issue->text();
    return {};
}

}  // namespace tt::ui
