#pragma once

#include "ui/calibration/calibration_wizard.h"

class QComboBox;
class QLabel;

namespace tt::core {
struct CharacteristicFit;
}

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

struct ProbeWizardContext;

/// 4. Fit: the characteristic with degree 2, 3, 4 or chosen by cross-validation, the reason for
/// the degree in words with each degree's leave-one-out error, the points with the fitted curve,
/// and the residuals. Points where the ADC saturated are left out, and said so; a non-monotonic
/// fit is refused, saying where it turns. Entering the page is the procedure's "next" (the fit is
/// made), going back its "back".
class ProbeFitPage : public CalibrationWizardPage {
    Q_OBJECT
public:
    ProbeFitPage(ProbeWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool isComplete() const override;
    void retranslate() override;

    /// 0 = auto, else 2..4; refits.
    void setDegree(int degree);
    /// The explanation shown (degree choice, scores and problems).
    QString explanation() const;

private:
    void showFit();
    /// The explanation: each degree's leave-one-out and in-sample errors, the points left out, the
    /// refusal or the monotonicity found.
    QString fitExplanation() const;
    /// The captured points with the fitted characteristic, and the residuals about zero.
    void plotFit(const core::CharacteristicFit& fit);

    ProbeWizardContext& m_ctx;
    QLabel* m_degreeLabel;
    QComboBox* m_degree;
    QLabel* m_choice;
    QLabel* m_explanation;
    plot::Chart* m_characteristic;
    plot::Chart* m_residuals;
};

}  // namespace tt::ui
