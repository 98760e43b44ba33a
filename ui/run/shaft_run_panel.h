#pragma once

#include <QVector>
#include <QWidget>
#include <memory>
#include <optional>

#include "core/loop/loop_events.h"
#include "core/storage/plant_forwarder.h"
#include "runtime/run/loop_snapshot.h"
#include "runtime/run/machine_catalog.h"
#include "runtime/run/run_request.h"
#include "runtime/run/stored_runs.h"
#include "ui/app_context.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace tt::runtime {
class RunSession;
}  // namespace tt::runtime

namespace tt::ui {

class LathePanel;
class ManualEntryPanel;
class ProfilePanel;
class VerdictCounter;

/// Run-to-run control of the shaft profile (paper 000), the Run page's first tab: the closed loop with the
/// run history. Start / Pause / Stop, the set-up, the controller, the delay z and the speed; the machine: any
/// the runtime offers (runtime::MachineCatalog: the plugins' complete machines such as the built-in
/// simulator's lathe, and the lathe assembled from the CNC output and gauge of the Devices page). The page
/// asks what the chosen machine can do (its speed, devices to choose, a part cycle the operator confirms with
/// the big Part finished button), never what it is. The live profile of the last part with the tolerance band,
/// the systematic model and the correction path; a history strip of the error at each control point; the loop
/// and its devices in plain words; the alarms; manual entry of diameters. The controls make one run request
/// (runtime::RunRequest); the loop runs in its own thread (runtime::RunSession) and the devices in theirs.
class ShaftRunPanel : public QWidget {
    Q_OBJECT
public:
    /// `context.devices` may be null: then no machine but the lathe from devices is offered, and it refuses.
    explicit ShaftRunPanel(AppContext& context, QWidget* parent = nullptr);
    ~ShaftRunPanel() override;
    /// Sets every visible text (also on a language change).
    void retranslate();

    /// The loop thread's handle.
    runtime::RunSession& session() { return *m_session; }
    /// The plots, the diameters typed by hand, the operator's part cycle, the alarm list.
    ProfilePanel* profilePanel() const { return m_profile; }
    ManualEntryPanel* manualEntry() const { return m_manual; }
    LathePanel* lathePanel() const { return m_lathePanel; }
    QListWidget* alarms() const { return m_alarms; }
    /// The run request the controls make now (a fresh seed each time).
    runtime::RunRequest request() const;
    /// Starts `request` as it is (its machine, seed, end and plant; the controls show its set-up); false with
    /// the reason in the alarm list and a warning when it cannot start.
    bool startRequest(const runtime::RunRequest& request);
    /// Continues an interrupted run (runtime/run/stored_runs.h) on its machine with its stored request; false
    /// (with the reason) when the user may not run the machine, a run is going or the machine is not offered.
    bool resumeRun(const runtime::InterruptedRun& run);

signals:
    /// The out-of-tolerance alert sounded: a rework or scrap part with the setting kSoundOnOutOfTolerance on
    /// (View > Sound on rework or scrap).
    void alertSounded();

private:
    QWidget* buildControls();
    QWidget* buildSetupRow();
    QWidget* buildDevicePicker();
    QWidget* buildSide();
    QWidget* buildLeft();
    void connectControls();
    void connectSession();
    /// Shows the plant database's link on the page and in the status bar.
    void onPlantStatus(const storage::ForwarderStatus& status);
    void connectDevices();
    void onStart();
    /// Readies the offer's machine for `request` and hands the run to the loop thread; `resumeRunId` continues
    /// a stored run. False (with the reason shown) when it cannot.
    bool launch(const runtime::RunRequest& request, std::optional<qint64> resumeRunId);
    void refuseStart(const QString& reason);
    /// The logged-in user may run the machine (Permission::RunMachine); refuses the start otherwise.
    bool mayRunMachine();
    void showRequest(const runtime::RunRequest& request);
    void onPauseContinue();
    void onStop();
    void onPartFinished();
    void onStarted(const runtime::RunLayout& layout);
    void onStartFailed(const QString& reason);
    void onSnapshot(const runtime::LoopSnapshot& snapshot);
    void onLoopEvent(const core::LoopEvent& event);
    void addAlarm(const QString& text, bool severe);
    /// After an adaptation notice, the controller the loop now uses (amber while on the fallback).
    void showControllerInUse(const core::Notice& notice);
    void onOutOfTolerance();
    void fillDeviceChoices();
    void restoreChoices();
    void saveChoices() const;
    /// The machine chosen (while idle) or the one the run is on.
    std::optional<runtime::MachineOffer> shownOffer() const;
    std::optional<runtime::MachineOffer> chosenOffer() const;
    void fillMachineChoices();
    void updateControls();
    void updateTexts();
    void updateLathePanel();
    QString stateText() const;
    QString deviceText() const;
    QString devicesIdleText() const;
    QString deviceChoiceText(const QString& id) const;
    void releaseMachine(const QString& reason);

    AppContext& m_context;
    runtime::RunSession* m_session;
    runtime::MachineCatalog m_catalog;
    runtime::LoopSnapshot m_snapshot;
    bool m_haveRun = false;
    runtime::RunLayout m_layout;
    QList<runtime::MachineOffer> m_offers;             ///< every machine a run can go on
    std::optional<runtime::MachineOffer> m_onMachine;  ///< the machine of the run started last
    runtime::RunRequest m_running;                     ///< the request of the run started last

    QPushButton* m_start;
    QPushButton* m_pause;
    QPushButton* m_stop;
    QLabel* m_presetLabel;
    QComboBox* m_preset;
    QLabel* m_controllerLabel;
    QComboBox* m_controller;
    QLabel* m_delayLabel;
    QSpinBox* m_delay;
    QLabel* m_speedLabel;
    QComboBox* m_speed;
    QLabel* m_machineLabel;
    QComboBox* m_machine;
    QLabel* m_outputLabel;
    QComboBox* m_output;
    QLabel* m_gaugeLabel;
    QComboBox* m_gauge;
    QWidget* m_devicePicker = nullptr;
    QLabel* m_partCounter;
    VerdictCounter* m_verdicts;
    QCheckBox* m_pauseOnScrap;
    ProfilePanel* m_profile;
    LathePanel* m_lathePanel;
    QLabel* m_state;
    QLabel* m_detail;
    QLabel* m_devices;
    QLabel* m_plantLink = nullptr;        ///< the plant database's link (shown with a plant database only)
    QLabel* m_controllerInUse = nullptr;  ///< the controller after an adaptation (shown once the loop adapted)
    QCheckBox* m_manualMode;
    ManualEntryPanel* m_manual;
    QPushButton* m_skip;
    QLabel* m_alarmsTitle;
    QListWidget* m_alarms;
};

}  // namespace tt::ui
