#pragma once

#include "ui/calibration/calibration_wizard.h"

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTimer;

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

struct KpWizardContext;

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

}  // namespace tt::ui
