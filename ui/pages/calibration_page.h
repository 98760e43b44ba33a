#pragma once

#include <QPointer>
#include <QString>
#include <memory>
#include <vector>

#include "ui/calibration/kp_session.h"
#include "ui/calibration/probe_calibration_session.h"
#include "ui/page.h"

class QLabel;
class QPushButton;
class QStackedWidget;
class QTableWidget;

namespace tt::runtime {
class DeviceHub;
}

namespace tt::storage {
class CalibrationStore;
class Database;
class ToolStore;
}  // namespace tt::storage

namespace tt::ui {

class DeviceCalibrationProbe;
class DeviceKpDrive;
class KpCalibrationWizard;
class ProbeCalibrationWizard;

/// The Calibration page (issue 6, item 5): the probe mandrel linearisation wizard and the k_p
/// wizard, embedded in the page (never modal), with the saved table versions and k_p
/// calibrations listed. The page owns what the wizards gather, so Back, Cancel and switching
/// pages never lose captured points; "Start over" asks first. The probes offered are the
/// probe-mandrel devices of `context().devices` (DeviceCalibrationProbe), the drives its
/// drive-current devices (DeviceKpDrive), the built-in simulator's among them like any other;
/// a device on a calibration stand brings its jack. When those devices change, the lists follow;
/// a wizard that is open is closed (its points are kept) so it never talks to a removed device.
class CalibrationPage : public Page {
    Q_OBJECT
public:
    explicit CalibrationPage(AppContext& context, QWidget* parent = nullptr);
    ~CalibrationPage() override;
    QString title() const override;
    void retranslate() override;

    /// The probes and drives the wizards offer now (the devices' adapters, in the devices' order).
    std::vector<DeviceCalibrationProbe*> offeredProbes() const;
    std::vector<DeviceKpDrive*> offeredDrives() const;
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
    bool overviewShown() const;
    QTableWidget* tablesView() const { return m_tables; }
    QTableWidget* kpView() const { return m_kpList; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    /// The overview: the store and device notices, the probe tables and the k_p calibrations with
    /// the buttons that start the wizards.
    void buildOverview();
    void watchDevices();
    void adoptDevices();
    void closeWizards();
    void releaseJacks();
    void openStores();
    void refreshLists();
    void showOverview();

    storage::CalibrationStore* m_calibrations = nullptr;  ///< from the application's data access object
    storage::ToolStore* m_tools = nullptr;
    QString m_storeError;
    QPointer<runtime::DeviceHub> m_devices;
    std::vector<std::unique_ptr<DeviceCalibrationProbe>> m_deviceProbes;  ///< adapters of the devices' probes
    std::vector<std::unique_ptr<DeviceKpDrive>> m_deviceDrives;           ///< adapters of the devices' drives
    QList<QPair<QString, quintptr>> m_adopted;                            ///< the devices adapted (id, instance)
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
