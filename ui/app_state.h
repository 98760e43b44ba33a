#pragma once

#include <QObject>
#include <QString>

namespace tt::ui {

/// What the status bar and the page header show about the machine: the closed loop and the
/// devices, in plain words. The loop engine and device manager write it; widgets observe it.
class AppState : public QObject {
    Q_OBJECT
public:
    /// Loop states of the closed loop (core/loop): Idle, Running, Paused, Fault.
    enum class Loop { Idle, Running, Paused, Fault };
    /// Summary tone of the devices: none configured, all ready, some warning, some in error.
    enum class Tone { Idle, Ok, Warning, Fault };

    explicit AppState(QObject* parent = nullptr);

    Loop loop() const { return m_loop; }
    QString loopDetail() const { return m_loopDetail; }
    Tone deviceTone() const { return m_deviceTone; }
    QString deviceSummary() const { return m_deviceSummary; }
    QString databaseDescription() const { return m_databaseDescription; }
    /// The plant database's link as the operator reads it (empty with a local history).
    QString plantLink() const { return m_plantLink; }
    /// Whether the plant link needs the operator's eye (offline, the journal nearly full).
    bool plantLinkWarns() const { return m_plantLinkWarns; }
    /// Where the application's log is written (ui/log_file.h); empty when it is not written.
    QString logFilePath() const { return m_logFilePath; }
    void setLogFilePath(const QString& path) { m_logFilePath = path; }
    QString operatorName() const { return m_operatorName; }

    void setLoop(Loop loop, const QString& detail);
    void setDevices(Tone tone, const QString& summary);
    void setDatabaseDescription(const QString& description);
    void setPlantLink(const QString& text, bool warns);
    void setOperatorName(const QString& name);

    /// Translated name of a loop state ("Running").
    static QString loopName(Loop loop);

signals:
    void loopChanged();
    void devicesChanged();
    void databaseChanged();
    void operatorChanged();

private:
    Loop m_loop = Loop::Idle;
    QString m_loopDetail;
    Tone m_deviceTone = Tone::Idle;
    QString m_deviceSummary;
    QString m_databaseDescription;
    QString m_plantLink;
    bool m_plantLinkWarns = false;
    QString m_logFilePath;
    QString m_operatorName;
};

}  // namespace tt::ui
