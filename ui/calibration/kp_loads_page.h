#pragma once

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

struct KpWizardContext;

/// 2. Known loads: for each load the current difference with dither, measured live (the
/// procedure holds still, then averages the stroke pairs) or typed; a load measured again,
/// stopped or removed. On a stand with a hydraulic jack (the simulator) the jack applies the load.
/// The page only shows the procedure and forwards clicks.
class KpLoadsPage : public CalibrationWizardPage {
    Q_OBJECT
public:
    KpLoadsPage(KpWizardContext& context, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool isComplete() const override;
    void retranslate() override;

    void setLoadN(double loadN);
    void setTypedCurrentDifference(double a);
    /// Starts measuring at the load entered (the stand's jack applies it; non-blocking).
    bool startMeasurement();
    /// Measures the selected load (or the last) again.
    bool repeatMeasurement();
    /// Stops a running measurement.
    void abortMeasurement();
    /// Takes the drive's samples (the timer calls it every 100 ms; tests too).
    void step(double elapsedS = 0.1);
    bool measuring() const;
    bool addTypedPoint();
    void removePoint();
    /// Selects a row of the loads table (tests; the operator taps it).
    void selectPoint(int row);
    QString message() const;

private:
    /// Object names, ranges and sizes of the entry boxes, the points table and the chart.
    void setUpControls();
    /// The live ΔI, the load and typed entry rows and the progress above the points and the chart.
    void buildLayout();
    void handleEvents();
    void refresh();
    void refreshState();
    void applyLoad(double loadN);
    void showMessage(const QString& text, bool problem);

    KpWizardContext& m_ctx;
    QTimer* m_timer;
    QLabel* m_live;
    QLabel* m_loadLabel;
    QDoubleSpinBox* m_load;
    QPushButton* m_measure;
    QPushButton* m_repeat;
    QLabel* m_typedLabel;
    QDoubleSpinBox* m_typed;
    QPushButton* m_addTyped;
    QPushButton* m_remove;
    QProgressBar* m_progress;
    QTableWidget* m_table;
    plot::Chart* m_chart;
    QLabel* m_message;
};

}  // namespace tt::ui
