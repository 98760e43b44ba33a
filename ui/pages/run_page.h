#pragma once

#include <QVector>

#include "core/loop/loop_events.h"
#include "ui/page.h"
#include "ui/run/run_settings.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace tt::ui {

class ManualEntryPanel;
class ProfilePanel;
class RunSession;

/// The operator's main page: the closed loop on the built-in lathe simulator with the run history
/// (paper 000). Start / Pause / Stop, the controller, the delay z and the speed; the live profile of the
/// last part with the tolerance band, the systematic model and the correction path; a history strip
/// of the error at each control point; the loop and the devices in plain words; the alarms; manual
/// entry of diameters. The loop runs in its own thread (RunSession), so the window never waits.
class RunPage : public Page {
    Q_OBJECT
public:
    explicit RunPage(AppContext& context, QWidget* parent = nullptr);
    ~RunPage() override;
    QString title() const override;
    void retranslate() override;

    RunSession& session() { return *m_session; }
    ProfilePanel* profilePanel() const { return m_profile; }
    ManualEntryPanel* manualEntry() const { return m_manual; }
    QListWidget* alarms() const { return m_alarms; }
    /// The settings the controls hold now.
    RunSettings settings() const;

private:
    QWidget* buildControls();
    QWidget* buildSide();
    void onStart();
    void onPauseContinue();
    void onStop();
    void onStarted(const RunLayout& layout);
    void onStartFailed(const QString& reason);
    void onSnapshot(const LoopSnapshot& snapshot);
    void onLoopEvent(const core::LoopEvent& event);
    void addAlarm(const QString& text, bool severe);
    void updateControls();
    void updateTexts();
    QString stateText() const;
    QString deviceText() const;

    RunSession* m_session;
    LoopSnapshot m_snapshot;
    bool m_haveRun = false;
    RunLayout m_layout;

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
    QLabel* m_partCounter;
    ProfilePanel* m_profile;
    QLabel* m_stateTitle;
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
