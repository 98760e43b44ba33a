#pragma once

#include <QStringList>
#include <optional>
#include <vector>

#include "core/calibration/kp_procedure.h"
#include "core/control/dither_current_difference.h"
#include "ui/app_context.h"
#include "ui/calibration/calibration_wizard.h"
#include "ui/calibration/device_kp_drive.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTimer;

namespace tt::storage {
class CalibrationStore;
class ToolStore;
}  // namespace tt::storage

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

/// What the k_p wizard has gathered: the procedure (loads, fit, checks) and what the wizard keeps
/// besides; owned by the Calibration page (Back/Cancel keep it).
struct KpSession {
    int driveIndex = 0;
    QStringList toolIds;  ///< tools that receive the new k_p
    core::KpCalibrationProcedure procedure{std::make_unique<core::DitherCurrentDifference>()};
    bool saved = false;
    void clear() { *this = KpSession{}; }
};

/// What the pages of the k_p wizard share.
struct KpWizardContext {
    AppContext* app = nullptr;
    KpSession* session = nullptr;
    std::vector<DeviceKpDrive*> drives;
    storage::CalibrationStore* calibrations = nullptr;
    storage::ToolStore* tools = nullptr;
    DeviceKpDrive* drive() const;
    core::KpCalibrationProcedure& procedure() const { return session->procedure; }
    QString operatorName() const;
};

/// 1. The drive and the tools that get the new k_p.
class KpSetupPage : public CalibrationWizardPage {
    Q_OBJECT
public:
    KpSetupPage(KpWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    bool validatePage() override;
    void retranslate() override;
    /// Ticks or unticks a tool by id.
    void setToolChecked(const QString& id, bool checked);

private:
    KpWizardContext& m_ctx;
    QLabel* m_driveLabel;
    QComboBox* m_drive;
    QLabel* m_toolsLabel;
    QListWidget* m_tools;
    QLabel* m_instructions;
};

/// 2. Known loads: for each load the current difference with dither, measured live (the
/// procedure holds still, then averages the stroke pairs) or typed; a load measured again,
/// stopped or removed. On a stand with a hydraulic jack (the simulator) the jack applies the load.
/// The page only shows the procedure and forwards clicks.
class KpLoadsPage : public CalibrationWizardPage {
    Q_OBJECT
public:
    KpLoadsPage(KpWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool isComplete() const override;
    void retranslate() override;

    void setLoadN(double loadN);
    void setTypedCurrentDifference(double a);
    /// Starts measuring at the load entered (the stand's jack applies it; non-blocking).
    bool startMeasurement();
    /// Measures the selected load (or the last) again.
    bool repeatMeasurement();
    /// Stops a running measurement.
    void abortMeasurement();
    /// Takes the drive's samples (the timer calls it every 100 ms; tests too).
    void step(double elapsedS = 0.1);
    bool measuring() const;
    bool addTypedPoint();
    void removePoint();
    /// Selects a row of the loads table (tests; the operator taps it).
    void selectPoint(int row);
    QString message() const;

private:
    void handleEvents();
    void refresh();
    void refreshState();
    void applyLoad(double loadN);
    void showMessage(const QString& text, bool problem);

    KpWizardContext& m_ctx;
    QTimer* m_timer;
    QLabel* m_live;
    QLabel* m_loadLabel;
    QDoubleSpinBox* m_load;
    QPushButton* m_measure;
    QPushButton* m_repeat;
    QLabel* m_typedLabel;
    QDoubleSpinBox* m_typed;
    QPushButton* m_addTyped;
    QPushButton* m_remove;
    QProgressBar* m_progress;
    QTableWidget* m_table;
    plot::Chart* m_chart;
    QLabel* m_message;
};

/// 3. The fit P = k_p ΔI + offset with its residuals, and verification loads compared with it.
/// Entering the page is the procedure's "next" (the fit is made), Next its "accept" (refused while
/// a verification load failed), Back its "back".
class KpFitPage : public CalibrationWizardPage {
    Q_OBJECT
public:
    KpFitPage(KpWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool validatePage() override;
    bool isComplete() const override;
    void retranslate() override;
    QString explanation() const;

    void setCheckLoadN(double loadN);
    /// Measures a verification load (the stand's jack applies it); stops a running one.
    bool checkLoad();
    /// Takes the drive's samples (the timer calls it; tests too).
    void step(double elapsedS = 0.1);
    bool checking() const;
    QString checkResult() const;

private:
    void showFit();
    KpWizardContext& m_ctx;
    QLabel* m_explanation;
    QLabel* m_checkLabel;
    QDoubleSpinBox* m_checkLoad;
    QPushButton* m_check;
    QLabel* m_checkResult;
    QTimer* m_timer;
    plot::Chart* m_chart;
    plot::Chart* m_residuals;
};

/// 4. Save the calibration and write k_p into the chosen tools (audited with the operator's name).
class KpSavePage : public CalibrationWizardPage {
    Q_OBJECT
public:
    KpSavePage(KpWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool isComplete() const override;
    void retranslate() override;
    bool save();

private:
    KpWizardContext& m_ctx;
    QLabel* m_summary;
    QPushButton* m_save;
    QLabel* m_result;
};

/// The k_p calibration wizard (issue 6, item 5): known loads on the cross slide, the current
/// difference with dither at each, the fit of k_p verified at a further load, saved and written
/// into the tool table. The steps are core::KpCalibrationProcedure's.
class KpCalibrationWizard : public CalibrationWizard {
    Q_OBJECT
public:
    enum PageId { SetupPage, LoadsPage, FitPage, SavePage };

    KpCalibrationWizard(AppContext& app, KpSession& session, std::vector<DeviceKpDrive*> drives,
                        storage::CalibrationStore* calibrations, storage::ToolStore* tools, QWidget* parent = nullptr);

    KpSetupPage* setupPage() const { return m_setup; }
    KpLoadsPage* loadsPage() const { return m_loads; }
    KpFitPage* fitPage() const { return m_fit; }
    KpSavePage* savePage() const { return m_save; }

protected:
    QString titleText() const override;

private:
    KpWizardContext m_ctx;
    KpSetupPage* m_setup;
    KpLoadsPage* m_loads;
    KpFitPage* m_fit;
    KpSavePage* m_save;
};

}  // namespace tt::ui
