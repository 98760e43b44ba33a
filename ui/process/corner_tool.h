#pragma once

#include <QString>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "core/sim/feed_drives/corner_work_run.h"
#include "ui/app_context.h"
#include "ui/process/process_tool.h"
#include "ui/status_text.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTabWidget;

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

class CornerJob;
class CornerMoveEditor;

/// The network the tool works with and what belongs to it.
struct CornerNetState {
    core::CorrectiveNet net;
    core::PulseSettings pulse;             ///< the pulse it was trained for
    std::vector<core::NetSample> samples;  ///< its training set (for retraining)
    core::FeedDrivesFactors model;         ///< the controller's model of the drives (factors identified)
    double bestReductionPct = 0.0;         ///< what the best pulses of its training moves achieved
};

/// The corrective pulse of the feed drives at a corner (paper 002, issue 15), a tab of the Process page:
/// the corner between two moves (speeds entered or picked), the programmed path and the simulated paths
/// without and with the pulse (zoomed on the corner), the contour error and the pulse on a time axis;
/// training the network on the simulator with its training curve, progress and cancel; a run of corners
/// on a machine whose friction, velocity gain or inertia of one drive drifts, with the drift monitor and
/// the guarded retraining, and retraining on demand. Long work runs in a worker thread (CornerJob); the engine is
/// core/sim/feed_drives.
class CornerTool : public ProcessTool {
    Q_OBJECT
public:
    explicit CornerTool(AppContext& context, QWidget* parent = nullptr);
    ~CornerTool() override;

    QString key() const override { return QStringLiteral("corner"); }
    QString title() const override;
    void retranslate() override;

    /// Simulates the corner shown without and with the pulse (the network's when it was trained for
    /// this pulse, else the best one found on the simulator) and draws it.
    void simulate();
    /// Starts training a network on the number of moves chosen; false when busy.
    bool train();
    /// Starts a run of corners with the current network; false when busy or without a network.
    bool runCorners();
    /// Starts retraining the network on the last run's recent corners; false when busy or there are none.
    bool retrainNow();
    /// Cancels the running job (the network of before is kept).
    void cancel();
    /// Switches to the corner preset `name` (1v340-feed-drives, the paper's drives, or 1v340-soft-drives);
    /// the network, the run and the samples belong to the machine and start afresh. False when busy or when
    /// the preset cannot be read (the machine of before stays, the summary says why).
    bool setMachine(const QString& name);
    /// Whether a job runs.
    bool busy() const;

    const std::optional<CornerNetState>& network() const { return m_net; }
    const std::optional<core::CornerWorkResult>& lastRun() const { return m_lastRun; }
    CornerMoveEditor* editor() const { return m_editor; }
    QPushButton* simulateButton() const { return m_simulate; }
    QPushButton* trainButton() const { return m_train; }
    QPushButton* cancelButton() const { return m_cancel; }
    QPushButton* runButton() const { return m_run; }
    QPushButton* retrainButton() const { return m_retrain; }
    QSpinBox* trainingMovesBox() const { return m_trainingMoves; }
    QSpinBox* cornersBox() const { return m_corners; }
    QComboBox* machineBox() const { return m_machine; }
    QComboBox* driftKindBox() const { return m_driftKind; }
    QComboBox* driftAxisBox() const { return m_driftAxis; }
    QDoubleSpinBox* driftFactorBox() const { return m_driftFactor; }
    QCheckBox* zoomBox() const { return m_zoom; }
    QTabWidget* views() const { return m_views; }
    QLabel* summaryLabel() const { return m_summary; }
    QLabel* statusLabel() const { return m_status; }
    QLabel* networkLabel() const { return m_networkText; }
    QLabel* driftLabel() const { return m_driftText; }
    plot::Chart* pathChart() const { return m_pathChart; }
    plot::Chart* errorChart() const { return m_errorChart; }
    plot::Chart* pulseChart() const { return m_pulseChart; }
    plot::Chart* trainingChart() const { return m_trainingChart; }
    plot::Chart* driftChart() const { return m_driftChart; }

signals:
    /// A job ended (trained, ran, retrained, cancelled or failed); for tests and the status line.
    void jobFinished();

private:
    struct LiveCurve {
        std::mutex mutex;
        std::vector<double> training;
        std::vector<double> validation;
        double outputScaleV = 1.0;
    };

    QWidget* buildCornerView();
    QWidget* buildNetworkView();
    QWidget* buildDriftView();
    void buildLayout();
    void updateEnabled();
    void showProgress(const QString& stage, int done, int total);
    void finishJob(bool cancelled, const QString& error);
    void showTrainingChart();  ///< the network's own training curve (a retraining's after one)
    void showDriftChart();     ///< the last run's monitor
    void showNetworkText();
    void showDriftText();
    QString retrainText(const core::CornerRetrainEvent& event) const;
    QString factorsText(const core::FeedDrivesFactors& factors) const;
    bool netFitsPulse(const core::PulseSettings& pulse) const;

    core::CornerScenario m_scenario;
    QString m_scenarioProblem;
    std::optional<CornerNetState> m_net;
    std::optional<core::CornerWorkResult> m_lastRun;
    std::shared_ptr<LiveCurve> m_curve;
    std::function<void()> m_apply;  ///< takes the finished job's result (GUI thread)
    CornerJob* m_job;

    QLabel* m_machineLabel;
    QComboBox* m_machine;
    CornerMoveEditor* m_editor;
    QPushButton* m_simulate;
    QLabel* m_summary;
    QLabel* m_status;
    StatusText m_statusText;  ///< the last job's outcome on m_status, made again when the language changes
    QProgressBar* m_progress;
    QPushButton* m_cancel;
    QTabWidget* m_views;
    QCheckBox* m_zoom;
    plot::Chart* m_pathChart;
    plot::Chart* m_errorChart;
    plot::Chart* m_pulseChart;
    QLabel* m_trainingMovesLabel;
    QSpinBox* m_trainingMoves;
    QPushButton* m_train;
    QLabel* m_networkText;
    plot::Chart* m_trainingChart;
    QLabel* m_driftLabel;
    QComboBox* m_driftKind;
    QLabel* m_driftAxisLabel;
    QComboBox* m_driftAxis;
    QDoubleSpinBox* m_driftFactor;
    QLabel* m_cornersLabel;
    QSpinBox* m_corners;
    QPushButton* m_run;
    QPushButton* m_retrain;
    QLabel* m_driftText;
    plot::Chart* m_driftChart;
    std::optional<core::CornerRun> m_shownWithout;
    std::optional<core::CornerRun> m_shownWith;
};

}  // namespace tt::ui
