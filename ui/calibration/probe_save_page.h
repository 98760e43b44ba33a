#pragma once

#include "ui/calibration/calibration_wizard.h"

class QLabel;
class QProgressBar;
class QPushButton;
class QTimer;

namespace tt::storage {
struct ProbeTableRecord;
}

namespace tt::ui {

struct ProbeWizardContext;

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
    /// The table's record by `who`: the probe, plane, fit and the points it was fitted to (no image yet).
    storage::ProbeTableRecord tableRecord(const QString& who) const;
    /// Adds the table image of the next version (in the probe's format) and its CRCs to `r`.
    void attachImage(storage::ProbeTableRecord& r) const;
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

}  // namespace tt::ui
