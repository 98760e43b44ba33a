#pragma once

#include <optional>

#include "ui/calibration/calibration_wizard.h"

class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTimer;

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

struct ProbeWizardContext;

/// 3. Capture points: the live ADC code of the chosen plane, the reference typed from the dial
/// indicator, a point captured with one press (the procedure holds still, then averages), read
/// again, typed by hand or removed, the points plotted as they come, a point where the ADC
/// saturated flagged in red. On a stand with a screw jack (the simulator) the bar is bent from here
/// and the indicator reading is filled in. The page only shows the procedure and forwards clicks.
class ProbeCapturePage : public CalibrationWizardPage {
    Q_OBJECT
public:
    ProbeCapturePage(ProbeWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool isComplete() const override;
    void retranslate() override;

    /// Takes the probe's samples (the timer calls it every 100 ms; tests call it directly).
    void pollProbe(double elapsedS = kPollS);
    /// Starts reading a point at the reference entered; false (with the reason shown) when refused.
    bool capturePoint();
    /// Reads the selected point (or the last one) again at the reference entered.
    bool repeatPoint();
    /// Stops a running capture.
    void abortCapture();
    /// Adds a typed point (code and reference from the entry boxes).
    bool addTypedPoint();
    /// Removes the selected point (or the last one).
    void removePoint();
    /// Stand with a screw jack: bends the bar to `um` and fills in what the dial indicator shows.
    void setJack(double um);

    void setReferenceUm(double um);
    void setTypedCode(double code);
    /// Selects a row of the points table (tests; the operator taps it).
    void selectPoint(int row);
    bool capturing() const;
    /// The live mean code, when enough samples arrived.
    std::optional<double> liveCode() const;
    QString message() const;

    static constexpr int kPollMs = 100;
    static constexpr double kPollS = kPollMs / 1000.0;

private:
    /// Object names, ranges and sizes of the entry boxes, the progress bar, the points table and the chart.
    void setUpControls();
    /// The live code, the jack, reference and typed-code rows and the progress above the points and the chart.
    void buildLayout();
    void handleEvents();
    void refreshPoints();
    void refreshState();
    void showMessage(const QString& text, bool problem);

    ProbeWizardContext& m_ctx;
    QTimer* m_timer;
    QLabel* m_live;
    QLabel* m_jackLabel;
    QDoubleSpinBox* m_jack;
    QPushButton* m_setJack;
    QLabel* m_referenceLabel;
    QDoubleSpinBox* m_reference;
    QPushButton* m_capture;
    QPushButton* m_repeat;
    QLabel* m_codeLabel;
    QDoubleSpinBox* m_code;
    QPushButton* m_typed;
    QProgressBar* m_progress;
    QPushButton* m_remove;
    QTableWidget* m_table;
    plot::Chart* m_chart;
    QLabel* m_message;
};

}  // namespace tt::ui
