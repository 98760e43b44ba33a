#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <QVariantMap>
#include <memory>
#include <optional>

#include "devices/api/device.h"
#include "devices/api/device_kind.h"
#include "ui/page.h"

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QStackedWidget;

namespace tt::runtime {
class DeviceHub;
struct DeviceView;
}  // namespace tt::runtime

namespace tt::ui {

class DeviceStatusBridge;
class EmptyState;
class SettingsForm;

/// The Devices page: the configured device instances (gauge micrometers, probe mandrels,
/// drive-current readouts, correction outputs; the built-in simulator is always among the
/// types), adding and removing them, each one's settings as a form drawn from its plugin's
/// schema with the problems shown under the fields, Test connection, and the live value, state,
/// last error and counters. Settings persist (QSettings) when applied; Revert undoes unapplied
/// edits. Uses the application's devices (AppContext::devices, a runtime::DeviceHub: the instances live in
/// the device thread, the page sees their snapshots; required: std::invalid_argument without one; app/gui.cpp
/// makes it before the window). Keeps the device badge and status bar up to date.
class DevicesPage : public Page {
    Q_OBJECT
public:
    explicit DevicesPage(AppContext& context, QWidget* parent = nullptr);
    ~DevicesPage() override;
    QString title() const override;
    void retranslate() override;
    QString unappliedEdits() const override;

    runtime::DeviceHub& hub() { return *m_hub; }
    /// The form of the device shown (for tests).
    SettingsForm& form() { return *m_form; }

private:
    struct Selection {
        QString deviceId;  ///< empty for a device being added
        QString pluginId;
        devices::DeviceKind kind = devices::DeviceKind::Gauge;
    };

    void buildUi();
    /// The hub's news, the list, the buttons, the form and the timers, connected.
    void connectControls();
    /// The simulator's fault switches of the selected device, each to its flag.
    void connectFaultSwitches();
    void fillTypes();
    void reloadList();
    void selectDevice(const QString& id);
    void startDraft();
    void showSelection();
    void validateForm();
    void apply();
    void revert();
    void removeSelected();
    void testConnection();
    /// Why a connection test must wait while a run is going (empty: it may go ahead).
    QString testRefusedByTheLoop(bool testsTheRunningDevice) const;
    void pollTest();
    void finishTest(bool ok, const QString& text);
    /// Ends a connection test: the trial instance goes, the instance it closed opens again.
    void endTest();
    void refreshStatus();
    void updateListTones();
    void saveSettings();
    const runtime::DeviceView* selectedDevice() const;
    QString typeName(const QString& pluginId, devices::DeviceKind kind) const;

    runtime::DeviceHub* m_hub = nullptr;
    DeviceStatusBridge* m_bridge = nullptr;
    std::optional<Selection> m_selection;
    QVariantMap m_savedValues;
    QString m_savedName;

    // Test connection.
    QString m_testTarget;      ///< the id of the instance tested (the trial one for typed settings); empty: none
    QString m_testStartValue;  ///< the live value before the test: a new one proves the device answers
    QTimer m_testTimer;
    QElapsedTimer m_testClock;
    QTimer m_refresh;

    // Left column.
    QLabel* m_listTitle;
    QListWidget* m_list;
    QLabel* m_newTypeLabel;
    QComboBox* m_newType;
    QPushButton* m_add;
    QPushButton* m_remove;
    // Right column.
    QStackedWidget* m_detailStack;
    EmptyState* m_empty;
    QLabel* m_detailTitle;
    QLabel* m_typeText;
    QLabel* m_stateLabel;
    QLabel* m_stateBadge;
    QLabel* m_stateMessage;
    QLabel* m_liveLabel;
    QLabel* m_live;
    QLabel* m_lastErrorLabel;
    QLabel* m_lastError;
    QLabel* m_nameLabel;
    QLineEdit* m_name;
    QLabel* m_settingsTitle;
    SettingsForm* m_form;
    QLabel* m_problems;
    QPushButton* m_test;
    QPushButton* m_apply;
    QPushButton* m_revert;
    QLabel* m_testResult;
    QGroupBox* m_faults;
    QCheckBox* m_faultSilent;
    QCheckBox* m_faultNoisy;
    QCheckBox* m_faultStuck;
    QCheckBox* m_faultMalformed;
    QCheckBox* m_faultUnplugged;
    QLabel* m_statsTitle;
    QLabel* m_stats;
};

}  // namespace tt::ui
