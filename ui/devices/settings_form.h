#pragma once

#include <QList>
#include <QVariantMap>
#include <QWidget>

#include "devices/api/settings_schema.h"

class QFormLayout;
class QLabel;

namespace tt::ui {

/// The settings form of a device, drawn from its plugin's schema (devices/api/settings_schema.h):
/// one editor per field with its unit, a message under every invalid field (red frame), fields
/// that do not apply hidden (visibleWhen). Numbers are typed, so a wrong value is shown, not
/// silently clamped; baud rates are offered but can be typed. Large editors for gloved hands.
class SettingsForm : public QWidget {
    Q_OBJECT
public:
    explicit SettingsForm(QWidget* parent = nullptr);

    /// Rebuilds the editors for `schema` and fills them with `values` (defaults where missing).
    void setSchema(const devices::SettingsSchema& schema, const QVariantMap& values);
    /// Takes the texts of `schema` (labels, units, help, choice labels, range hints) for the rows
    /// with the same keys, keeping the editors and what is typed in them: the schema built again
    /// after a language change.
    void setTexts(const devices::SettingsSchema& schema);
    /// Fills the editors again (e.g. revert to the saved settings).
    void setValues(const QVariantMap& values);
    /// The values as typed: numbers converted when they parse, text otherwise (so validation can
    /// say what is wrong).
    QVariantMap values() const;
    /// Shows `issues` under their fields (and clears the others).
    void showIssues(const QList<devices::SettingIssue>& issues);
    /// The editor of a field (for tests and focus), null if none.
    QWidget* editor(const QString& key) const;
    /// The message shown under a field; empty when valid.
    QString issueText(const QString& key) const;

signals:
    /// The user changed a value.
    void edited();

private:
    struct Row {
        devices::SettingField field;
        QLabel* label = nullptr;
        QLabel* unit = nullptr;
        QWidget* editor = nullptr;
        QWidget* line = nullptr;  ///< editor, unit and message: hidden together
        QLabel* issue = nullptr;
    };
    QWidget* makeEditor(const devices::SettingField& field);
    /// Label, unit, tooltip, choice labels and range hint of `row` from its field.
    void applyTexts(const Row& row);
    QVariant readEditor(const Row& row) const;
    void writeEditor(const Row& row, const QVariant& value);
    void updateVisibility();

    QFormLayout* m_layout;
    QList<Row> m_rows;
    bool m_filling = false;
};

}  // namespace tt::ui
