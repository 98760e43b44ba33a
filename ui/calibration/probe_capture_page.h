#pragma once

#include <deque>

#include "ui/calibration/calibration_wizard.h"

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTableWidget;
class QTimer;

namespace tt::ui {

class Chart;
struct ProbeWizardContext;

/// 3. Capture points: the live ADC code of the chosen plane (averaged), the reference typed from
/// the dial indicator, a point captured with one press (or typed by hand), the points plotted as
/// they come. On the simulator a screw jack bends the bar and the indicator reading is filled in.
class ProbeCapturePage : public CalibrationWizardPage {
    Q_OBJECT
public:
    ProbeCapturePage(ProbeWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool isComplete() const override;
    void retranslate() override;

    /// Reads the probe for `seconds` (the timer calls it with its period; tests call it directly).
    void pollProbe(double seconds);
    /// Adds a point from the live mean code and the reference entered; false (with the reason
    /// shown) when there are too few live samples or the probe is not ready.
    bool capturePoint();
    /// Adds a typed point (code and reference from the entry boxes).
    bool addTypedPoint();
    /// Removes the selected point (or the last one).
    void removePoint();
    /// Simulator: bends the bar to `um` and fills in what the dial indicator shows.
    void setJack(double um);

    void setReferenceUm(double um);
    void setTypedCode(double code);
    /// Mean of the recent live codes; nullopt with fewer than the minimum samples.
    std::optional<double> liveCode() const;
    QString message() const;

    static constexpr int kMinPoints = 5;

private:
    void refreshPoints();
    void showMessage(const QString& text, bool problem);

    ProbeWizardContext& m_ctx;
    QTimer* m_timer;
    std::deque<double> m_codes;
    QLabel* m_live;
    QLabel* m_jackLabel;
    QDoubleSpinBox* m_jack;
    QPushButton* m_setJack;
    QLabel* m_referenceLabel;
    QDoubleSpinBox* m_reference;
    QLabel* m_codeLabel;
    QDoubleSpinBox* m_code;
    QPushButton* m_capture;
    QPushButton* m_typed;
    QPushButton* m_remove;
    QTableWidget* m_table;
    Chart* m_chart;
    QLabel* m_message;
    bool m_messageIsProblem = false;
};

}  // namespace tt::ui
