#pragma once

#include <vector>

#include "ui/app_context.h"
#include "ui/calibration/calibration_wizard.h"
#include "ui/calibration/device_calibration_probe.h"
#include "ui/calibration/probe_calibration_session.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTimer;

namespace tt::storage {
class CalibrationStore;
}

namespace tt::ui {

class ProbeCapturePage;
class ProbeFitPage;

/// What the pages of the probe wizard share: the session (its procedure holds the steps), the
/// probes offered and the store.
struct ProbeWizardContext {
    AppContext* app = nullptr;
    ProbeCalibrationSession* session = nullptr;
    std::vector<DeviceCalibrationProbe*> probes;
    storage::CalibrationStore* store = nullptr;

    DeviceCalibrationProbe* probe() const;
    core::ProbeLinearisationProcedure& procedure() const { return session->procedure; }
    QString operatorName() const;
    /// Forwards the probe's samples to the procedure (`elapsedS` of wall time since the last call).
    void pumpProbe(double elapsedS) const;
    /// Plane, ADC resolution and the instrument's division into the procedure (back to its capture step).
    void setUp(int plane, int adcBits, double divisionUm) const;
};

/// 1. Choose the probe, the bending plane and the ADC resolution.
class ProbeChoosePage : public CalibrationWizardPage {
    Q_OBJECT
public:
    ProbeChoosePage(ProbeWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    bool validatePage() override;
    void retranslate() override;

private:
    void store();
    ProbeWizardContext& m_ctx;
    QLabel* m_probeLabel;
    QComboBox* m_probe;
    QLabel* m_planeLabel;
    QComboBox* m_plane;
    QLabel* m_bitsLabel;
    QSpinBox* m_bits;
    QLabel* m_health;
};

/// 2. Set up the reference: dial indicator or micrometer at the tool tip, its resolution.
class ProbeReferencePage : public CalibrationWizardPage {
    Q_OBJECT
public:
    ProbeReferencePage(ProbeWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    bool validatePage() override;
    void retranslate() override;

private:
    ProbeWizardContext& m_ctx;
    QLabel* m_kindLabel;
    QComboBox* m_kind;
    QLabel* m_resolutionLabel;
    QDoubleSpinBox* m_resolution;
    QLabel* m_instructions;
};

/// 5. Verify and accept: the figures of the table, verification points read through the table
/// (captured like the points, not used by the fit), and the operator's acceptance, which the
/// procedure refuses while a verification point failed.
class ProbeAcceptPage : public CalibrationWizardPage {
    Q_OBJECT
public:
    ProbeAcceptPage(ProbeWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool validatePage() override;
    bool isComplete() const override;
    void retranslate() override;

    /// Stand with a screw jack: bends the bar to `um` and fills in what the dial indicator shows.
    void setJack(double um);
    void setReferenceUm(double um);
    /// Starts a verification point at the reference entered (stops a running one).
    bool checkPoint();
    /// Takes the probe's samples (the timer calls it; tests too).
    void pollProbe(double elapsedS = 0.1);
    /// Ticks or unticks the acceptance (the procedure may refuse it).
    void setAccepted(bool accepted);
    QString checkResult() const;

private:
    void refresh();
    ProbeWizardContext& m_ctx;
    QLabel* m_summary;
    QLabel* m_checkTitle;
    QLabel* m_jackLabel;
    QDoubleSpinBox* m_jack;
    QPushButton* m_setJack;
    QLabel* m_referenceLabel;
    QDoubleSpinBox* m_reference;
    QPushButton* m_check;
    QLabel* m_result;
    QCheckBox* m_accept;
    QTimer* m_timer;
};

/// 6. Save the table as a new version (who, when) and upload it with read-back of its CRC.
class ProbeSavePage : public CalibrationWizardPage {
    Q_OBJECT
public:
    ProbeSavePage(ProbeWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool isComplete() const override;
    void retranslate() override;

    /// Saves the table (refused without an operator name); returns whether it was saved.
    bool save();
    /// Starts the upload of the saved table.
    bool upload();
    /// One step of the upload watch (the timer calls it; tests may too).
    void pollUpload(double elapsedS = 0.1);
    /// Writes the table as C header, binary image or CSV (by the file's extension).
    bool exportTable(const QString& path);

private:
    void showResult(const QString& text, bool problem);
    ProbeWizardContext& m_ctx;
    QLabel* m_intro;
    QPushButton* m_save;
    QPushButton* m_upload;
    QPushButton* m_export;
    QProgressBar* m_progress;
    QLabel* m_saved;
    QLabel* m_result;
    QTimer* m_timer;
};

/// The probe mandrel linearisation wizard (issue 6, item 5): choose the probe and plane → set up
/// the reference → capture points live (or type them) with a live plot → fit with the residual
/// plot and the degree choice explained → verify and accept → save a versioned table and upload
/// it with read-back of its CRC. The steps are core::ProbeLinearisationProcedure's; the pages show
/// its state and forward the clicks. Works on the session it is given, so Back and Cancel lose
/// nothing.
class ProbeCalibrationWizard : public CalibrationWizard {
    Q_OBJECT
public:
    enum PageId { ChoosePage, ReferencePage, CapturePage, FitPage, AcceptPage, SavePage };

    ProbeCalibrationWizard(AppContext& app, ProbeCalibrationSession& session,
                           std::vector<DeviceCalibrationProbe*> probes, storage::CalibrationStore* store,
                           QWidget* parent = nullptr);

    ProbeChoosePage* choosePage() const { return m_choose; }
    ProbeReferencePage* referencePage() const { return m_reference; }
    ProbeCapturePage* capturePage() const { return m_capture; }
    ProbeFitPage* fitPage() const { return m_fit; }
    ProbeAcceptPage* acceptPage() const { return m_accept; }
    ProbeSavePage* savePage() const { return m_save; }

protected:
    QString titleText() const override;

private:
    ProbeWizardContext m_ctx;
    ProbeChoosePage* m_choose;
    ProbeReferencePage* m_reference;
    ProbeCapturePage* m_capture;
    ProbeFitPage* m_fit;
    ProbeAcceptPage* m_accept;
    ProbeSavePage* m_save;
};

}  // namespace tt::ui
