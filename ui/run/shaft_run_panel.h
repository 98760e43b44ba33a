#pragma once

#include <QVector>
#include <QWidget>
#include <memory>
#include <optional>

#include "core/loop/loop_events.h"
#include "devices/api/shaft_machine_offer.h"
#include "ui/app_context.h"
#include "ui/run/run_settings.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace tt::ui {

class LatheLink;
class LathePanel;
class ManualEntryPanel;
class ProfilePanel;
struct InterruptedRun;
class RunSession;
class VerdictCounter;

/// Run-to-run control of the shaft profile (paper 000), the Run page's first tab: the closed loop with the
/// run history. Start / Pause / Stop, the set-up, the controller, the delay z and the speed (machines whose
/// time can run faster); the machine: one a device plugin offers whole (devices::ShaftMachineOffer, e.g.
/// the built-in simulator's lathe), or the lathe assembled from the CNC output and the gauge chosen from the
/// Devices page (AppContext::devices) with the part cycle confirmed with the big Part finished button; the live profile
/// of the last part with the tolerance band, the systematic model and the correction path; a history strip of the error
/// at each control point; the loop and the devices it uses in plain words; the alarms; manual entry of diameters. The
/// loop runs in its own thread (RunSession), so the window never waits; the devices stay in this thread (LatheLink).
class ShaftRunPanel : public QWidget {
    Q_OBJECT
public:
    /// `context.devices` may be null: then no machine is offered and a run is refused with the reason.
    explicit ShaftRunPanel(AppContext& context, QWidget* parent = nullptr);
    ~ShaftRunPanel() override;
    /// Sets every visible text (also on a language change).
    void retranslate();

    /// The loop thread's handle.
    RunSession& session() { return *m_session; }
    /// The real lathe's devices as connected to the loop.
    LatheLink& lathe() { return *m_link; }
    /// The plots, the diameters typed by hand, the real lathe's part cycle, the alarm list.
    ProfilePanel* profilePanel() const { return m_profile; }
    ManualEntryPanel* manualEntry() const { return m_manual; }
    LathePanel* lathePanel() const { return m_lathePanel; }
    QListWidget* alarms() const { return m_alarms; }
    /// The settings the controls hold now.
    RunSettings settings() const;
    /// Continues an interrupted run (ui/run/interrupted_run.h) on its machine with its stored settings; false
    /// (with the reason in the alarm list and a warning) when the user may not run the machine, a run is
    /// going or the machine is not offered.
    bool resumeRun(const InterruptedRun& run);

signals:
    /// The out-of-tolerance alert sounded: a rework or scrap part with the setting kSoundOnOutOfTolerance on
    /// (View > Sound on rework or scrap).
    void alertSounded();

private:
    QWidget* buildControls();
    QWidget* buildSetupRow();
    QWidget* buildDevicePicker();
    QWidget* buildSide();
    void onStart();
    void refuseStart(const QString& reason);
    /// The logged-in user may run the machine (Permission::RunMachine); refuses the start otherwise.
    bool mayRunMachine();
    void onPauseContinue();
    void onStop();
    void onPartFinished();
    void onStarted(const RunLayout& layout);
    void onStartFailed(const QString& reason);
    void onSnapshot(const LoopSnapshot& snapshot);
    void onLoopEvent(const core::LoopEvent& event);
    void addAlarm(const QString& text, bool severe);
    void onOutOfTolerance();
    void fillDeviceChoices();
    void restoreChoices();
    void saveChoices() const;
    bool realLatheChosen() const;
    /// The machine offer chosen, or none (the lathe assembled from the devices).
    std::optional<devices::ShaftMachineOffer> chosenOffer() const;
    void fillMachineChoices();
    void updateControls();
    void updateTexts();
    void updateLathePanel();
    QString stateText() const;
    QString deviceText() const;
    QString deviceChoiceText(const QString& id) const;

    AppContext& m_context;
    RunSession* m_session;
    LatheLink* m_link;
    LoopSnapshot m_snapshot;
    bool m_haveRun = false;
    RunLayout m_layout;
    QList<devices::ShaftMachineOffer> m_offers;  ///< complete machines the plugins offer

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
    QCheckBox* m_manualMode;
    ManualEntryPanel* m_manual;
    QPushButton* m_skip;
    QLabel* m_alarmsTitle;
    QListWidget* m_alarms;
};

}  // namespace tt::ui
