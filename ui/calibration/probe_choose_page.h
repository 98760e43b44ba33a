#pragma once

#include "ui/calibration/calibration_wizard.h"

class QComboBox;
class QLabel;
class QSpinBox;

namespace tt::ui {

struct ProbeWizardContext;

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

}  // namespace tt::ui
