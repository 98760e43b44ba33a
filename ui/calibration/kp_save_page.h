#pragma once

#include "ui/calibration/calibration_wizard.h"

class QLabel;
class QPushButton;

namespace tt::ui {

struct KpWizardContext;

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

}  // namespace tt::ui
