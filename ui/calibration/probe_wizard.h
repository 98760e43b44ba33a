#pragma once

#include <optional>
#include <vector>

#include "core/calibration/probe_linearisation.h"
#include "ui/app_context.h"
#include "ui/calibration/calibration_probe.h"
#include "ui/calibration/calibration_wizard.h"
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

/// What the pages of the probe wizard share.
struct ProbeWizardContext {
    AppContext* app = nullptr;
    ProbeCalibrationSession* session = nullptr;
    std::vector<CalibrationProbe*> probes;
    storage::CalibrationStore* store = nullptr;
    std::optional<core::Linearisation> result;  ///< the accepted fit and table (FitPage)

    CalibrationProbe* probe() const;
    QString operatorName() const;
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

/// 5. Accept: the figures of the table, and the operator's acceptance.
class ProbeAcceptPage : public CalibrationWizardPage {
    Q_OBJECT
public:
    ProbeAcceptPage(ProbeWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    void retranslate() override;

private:
    ProbeWizardContext& m_ctx;
    QLabel* m_summary;
    QCheckBox* m_accept;
};

/// 6. Save the table as a new version (who, when) and upload it with read-back of its CRC.
class ProbeSavePage : public CalibrationWizardPage {
    Q_OBJECT
public:
    ProbeSavePage(ProbeWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    void retranslate() override;

    /// Saves the table (refused without an operator name); returns whether it was saved.
    bool save();
    /// Starts the upload of the saved table.
    bool upload();
    /// One step of the upload watch (the timer calls it; tests may too).
    void pollUpload();
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
    std::vector<std::uint8_t> m_image;
    bool m_uploading = false;
};

/// The probe mandrel linearisation wizard (issue 6, item 5): choose the probe and plane → set up
/// the reference → capture points live (or type them) with a live plot → fit with the residual
/// plot and the degree choice explained → accept → save a versioned table and upload it with
/// read-back of its CRC. Works on the session it is given, so Back and Cancel lose nothing.
class ProbeCalibrationWizard : public CalibrationWizard {
    Q_OBJECT
public:
    enum PageId { ChoosePage, ReferencePage, CapturePage, FitPage, AcceptPage, SavePage };

    ProbeCalibrationWizard(AppContext& app, ProbeCalibrationSession& session, std::vector<CalibrationProbe*> probes,
                           storage::CalibrationStore* store, QWidget* parent = nullptr);

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
