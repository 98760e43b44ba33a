#pragma once

#include "ui/calibration/calibration_wizard.h"

class QComboBox;
class QLabel;
class QListWidget;

namespace tt::ui {

struct KpWizardContext;

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

}  // namespace tt::ui
