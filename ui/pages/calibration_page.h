#pragma once

#include <QPointer>
#include <QString>
#include <memory>
#include <vector>

#include "ui/calibration/kp_wizard.h"
#include "ui/calibration/probe_calibration_session.h"
#include "ui/page.h"

class QLabel;
class QPushButton;
class QStackedWidget;
class QTableWidget;

namespace tt::devices {
class DeviceManager;
}

namespace tt::storage {
class CalibrationStore;
class Database;
class ToolStore;
}  // namespace tt::storage

namespace tt::ui {

class CalibrationProbe;
class EmptyState;
class KpCalibrationWizard;
class KpDriveSource;
class ProbeCalibrationWizard;

/// The Calibration page (issue 6, item 5): the probe mandrel linearisation wizard and the k_p
/// wizard, embedded in the page (never modal), with the saved table versions and k_p
/// calibrations listed. The page owns what the wizards gather, so Back, Cancel and switching
/// pages never lose captured points; "Start over" asks first. The probes offered are the built-in
/// simulated mandrel and every probe-mandrel device of `context().devices` (the simulator's too,
/// through DeviceCalibrationProbe); the drives, the built-in simulated cross feed and every
/// drive-current device (DeviceKpDrive). When those devices change, the lists follow; a wizard
/// that is open is closed (its points are kept) so it never talks to a removed device.
class CalibrationPage : public Page {
    Q_OBJECT
public:
    explicit CalibrationPage(AppContext& context, QWidget* parent = nullptr);
    ~CalibrationPage() override;
    QString title() const override;
    void retranslate() override;

    /// Replaces the probes offered (they must outlive the page); the built-in simulator stays first.
    void setProbes(std::vector<CalibrationProbe*> probes);
    /// Replaces the drives offered (they must outlive the page); the built-in simulator stays first.
    void setDrives(std::vector<KpDriveSource*> drives);
    /// The probes and drives the wizards offer now, the built-in simulators first.
    std::vector<CalibrationProbe*> offeredProbes() const { return probes(); }
    std::vector<KpDriveSource*> offeredDrives() const { return drives(); }
    /// Why a wizard was closed (the devices changed), shown above the lists; empty otherwise.
    QString deviceNotice() const;

    /// Opens the probe wizard (continuing the kept session, if any).
    void startProbeCalibration();
    /// Opens the k_p wizard.
    void startKpCalibration();
    /// Forgets the kept probe points after asking.
    void startOver();

    ProbeCalibrationWizard* probeWizard() const { return m_probeWizard; }
    KpCalibrationWizard* kpWizard() const { return m_kpWizard; }
    ProbeCalibrationSession& probeSession() { return m_probeSession; }
    KpSession& kpSession() { return m_kpSession; }
    CalibrationProbe* simulatedProbe() const;
    bool overviewShown() const;
    QTableWidget* tablesView() const { return m_tables; }
    QTableWidget* kpView() const { return m_kpList; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    void watchDevices();
    void adoptDevices();
    void openStores();
    void refreshLists();
    void showOverview();
    std::vector<CalibrationProbe*> probes() const;
    std::vector<KpDriveSource*> drives() const;

    std::unique_ptr<storage::Database> m_db;
    std::unique_ptr<storage::CalibrationStore> m_calibrations;
    std::unique_ptr<storage::ToolStore> m_tools;
    QString m_storeError;
    std::unique_ptr<CalibrationProbe> m_simProbe;
    std::unique_ptr<KpDriveSource> m_simDrive;
    std::vector<CalibrationProbe*> m_extraProbes;
    std::vector<KpDriveSource*> m_extraDrives;
    QPointer<devices::DeviceManager> m_devices;
    std::vector<std::unique_ptr<CalibrationProbe>> m_deviceProbes;  ///< adapters of the devices' probes
    std::vector<std::unique_ptr<KpDriveSource>> m_deviceDrives;     ///< adapters of the devices' drives
    QList<QPair<QString, const void*>> m_adopted;                   ///< the devices adapted (id, instance)
    ProbeCalibrationSession m_probeSession;
    KpSession m_kpSession;

    QStackedWidget* m_stack;
    QWidget* m_overview;
    ProbeCalibrationWizard* m_probeWizard = nullptr;
    KpCalibrationWizard* m_kpWizard = nullptr;
    QLabel* m_probeTitle;
    QLabel* m_probeText;
    QPushButton* m_probeStart;
    QPushButton* m_probeStartOver;
    QTableWidget* m_tables;
    QLabel* m_kpTitle;
    QLabel* m_kpText;
    QPushButton* m_kpStart;
    QTableWidget* m_kpList;
    QLabel* m_storeProblem;
    QLabel* m_deviceNotice;
};

}  // namespace tt::ui
