#pragma once

#include <QStringList>
#include <optional>
#include <vector>

#include "core/calibration/kp_calibration.h"
#include "core/control/dither_force_estimator.h"
#include "ui/app_context.h"
#include "ui/calibration/calibration_wizard.h"
#include "ui/calibration/kp_drive_source.h"

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

namespace tt::ui {

class Chart;

/// One measured known load.
struct KpCapture {
    double loadN = 0.0;
    double currentDifferenceA = 0.0;  ///< (I_fwd − I_rev) / 2, mean over the window
    int estimates = 0;                ///< stroke pairs averaged (0: typed)
};

/// What the k_p wizard has gathered; owned by the Calibration page (Back/Cancel keep it).
struct KpSession {
    int driveIndex = 0;
    QStringList toolIds;  ///< tools that receive the new k_p
    std::vector<KpCapture> points;
    std::optional<core::KpFit> fit;
    bool saved = false;
    void clear() { *this = KpSession{}; }
};

/// What the pages of the k_p wizard share.
struct KpWizardContext {
    AppContext* app = nullptr;
    KpSession* session = nullptr;
    std::vector<KpDriveSource*> drives;
    storage::CalibrationStore* calibrations = nullptr;
    storage::ToolStore* tools = nullptr;
    KpDriveSource* drive() const;
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

/// 2. Known loads: for each load the current difference with dither, measured live over a
/// window (DitherForceEstimator with k_p = 1 gives ΔI) or typed.
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
    /// Starts measuring the current difference at the load entered (non-blocking).
    bool startMeasurement();
    /// Advances a running measurement by `seconds` (the timer calls it; tests too).
    void step(double seconds);
    /// Runs a whole measurement at once (simulator; tests).
    bool measureNow();
    bool measuring() const { return m_measuring; }
    bool addTypedPoint();
    void removePoint();
    QString message() const;

    static constexpr double kSettleS = 1.0;
    static constexpr double kWindowS = 6.0;

private:
    void finishMeasurement();
    void refresh();
    void showMessage(const QString& text, bool problem);

    KpWizardContext& m_ctx;
    QTimer* m_timer;
    std::optional<core::DitherForceEstimator> m_estimator;
    bool m_measuring = false;
    double m_elapsedS = 0.0;
    double m_sum = 0.0;
    int m_count = 0;
    QLabel* m_loadLabel;
    QDoubleSpinBox* m_load;
    QPushButton* m_measure;
    QLabel* m_typedLabel;
    QDoubleSpinBox* m_typed;
    QPushButton* m_addTyped;
    QPushButton* m_remove;
    QProgressBar* m_progress;
    QTableWidget* m_table;
    Chart* m_chart;
    QLabel* m_message;
};

/// 3. The fit P = k_p ΔI + offset with its residuals.
class KpFitPage : public CalibrationWizardPage {
    Q_OBJECT
public:
    KpFitPage(KpWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    void retranslate() override;
    QString explanation() const;

private:
    KpWizardContext& m_ctx;
    QLabel* m_explanation;
    Chart* m_chart;
    Chart* m_residuals;
};

/// 4. Save the calibration and write k_p into the chosen tools (audited with the operator's name).
class KpSavePage : public CalibrationWizardPage {
    Q_OBJECT
public:
    KpSavePage(KpWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
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
/// difference with dither at each, the fit of k_p, saved and written into the tool table.
class KpCalibrationWizard : public CalibrationWizard {
    Q_OBJECT
public:
    enum PageId { SetupPage, LoadsPage, FitPage, SavePage };

    KpCalibrationWizard(AppContext& app, KpSession& session, std::vector<KpDriveSource*> drives,
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
