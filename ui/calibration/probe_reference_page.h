#pragma once

#include "ui/calibration/calibration_wizard.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace tt::ui {

struct ProbeWizardContext;

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

}  // namespace tt::ui
