#pragma once

#include "ui/calibration/calibration_wizard.h"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTimer;

namespace tt::ui {

struct ProbeWizardContext;

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

}  // namespace tt::ui
