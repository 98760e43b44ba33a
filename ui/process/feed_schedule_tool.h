#pragma once

#include <optional>

#include "config/deformation_model_config.h"
#include "config/feed_schedule_config.h"
#include "core/control/feed_scheduler.h"
#include "core/sim/shaft/feed_refinement.h"
#include "core/sim/shaft/feed_schedule_check.h"
#include "ui/app_context.h"
#include "ui/process/process_tool.h"

class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSlider;
class QTabWidget;

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

class DeformationModelPanel;
class FeedModelTask;
class GCodeView;
struct FeedTaskResult;

/// The Feed schedule tab of the Process page (paper 004): the force-deformation model Y(a, f, z)
/// (simulated experiments and fit, a measured CSV fitted, or a model file loaded) with its statistics;
/// the pass (depth, feed range and step, z from and to, L_min); the family of curves Y(z) for several
/// feeds with the level Yc and the resulting staircase of feeds; Yc on a slider between Y1 (quality)
/// and Y2 (productivity), the schedule and the time saved following it; the check on the simulator;
/// the CNC program with line numbers, saved to a file. When the check misses the ±10 % band, Refine
/// closes the loop on the model (targeted bars on the simulator, the model refitted at the depth, the
/// pass rescheduled and checked, round by round); the refined model is used while the pass stays at its
/// depth, feed range and z. Long work runs in FeedModelTask's thread.
class FeedScheduleTool : public ProcessTool {
    Q_OBJECT
public:
    /// Builds the tab and starts the built-in set-up's experiments and fit in the worker.
    explicit FeedScheduleTool(AppContext& context, QWidget* parent = nullptr);
    ~FeedScheduleTool() override;

    QString key() const override { return QStringLiteral("feed-schedule"); }
    QString title() const override;
    void retranslate() override;

    /// Runs the experiments of the feed-scheduling preset on the simulator and fits the model (worker).
    void simulateExperiments();
    /// Asks for an experiment CSV and fits it (worker).
    void fitCsvFile();
    /// Asks for a model file (fit-deformation --json) and loads it.
    void loadModelFile();
    /// Machines the current schedule on the simulator of the model's set-up (worker).
    void checkOnSimulator();
    /// Refines the model for the current pass where its check missed (worker; see FeedModelTask::refine).
    void refineModel();
    /// Asks for a file name and writes the program; false when nothing was written.
    bool saveProgram();
    /// Sets Yc as a fraction of [Y1, Y2] (what dragging the slider does).
    void setLevelFraction(double fraction);

    /// Whether a task runs in the worker.
    bool busy() const;
    /// The model fitted or loaded (with its statistics, set-up and job), if any.
    const std::optional<config::DeformationModelFile>& model() const { return m_model; }
    /// The model the schedule rests on: the refined one when the pass is the one it was refined for,
    /// else model(); nullptr when there is none.
    const config::DeformationModelFile* activeModel() const;
    /// The last refinement, if any (kept until another model is fitted or loaded).
    const std::optional<core::FeedRefinement>& refinement() const { return m_refinement; }
    /// The schedule of the current inputs, or nothing when they cannot be scheduled (see problem()).
    const std::optional<core::FeedSchedule>& schedule() const { return m_schedule; }
    /// Machining times of the schedule and of constant fmin and fmax (when the model has a job), s.
    const std::optional<core::MachiningTimes>& times() const { return m_times; }
    /// The check on the simulator of the current schedule, if made since it last changed.
    const std::optional<core::FeedScheduleCheck>& check() const { return m_check; }
    /// The CNC program of the schedule in the chosen dialect (empty when there is none).
    QString programText() const { return m_program; }
    /// Why the current inputs cannot be scheduled (the engine's message), empty otherwise.
    QString problem() const { return m_problem; }

    /// Widgets, for tests and screenshots.
    plot::Chart* curvesChart() const { return m_curves; }
    plot::Chart* feedChart() const { return m_feeds; }
    GCodeView* programView() const { return m_programView; }
    QTabWidget* views() const { return m_views; }
    QSlider* levelSlider() const { return m_level; }
    QDoubleSpinBox* depthBox() const { return m_depth; }
    QDoubleSpinBox* feedStepBox() const { return m_feedStep; }
    QDoubleSpinBox* minLengthBox() const { return m_minLength; }
    QComboBox* dialectBox() const { return m_dialect; }
    QComboBox* switchBox() const { return m_switch; }
    QPushButton* refineButton() const { return m_refine; }
    QLabel* resultLabel() const { return m_result; }
    DeformationModelPanel* modelPanel() const { return m_modelPanel; }

signals:
    /// A task (experiments and fit, CSV fit, check) has ended.
    void taskFinished();

private:
    void buildLayout();
    void configureBoxes();
    /// The buttons, the model task, the level slider and the pass boxes to what they do.
    void connectControls();
    void useModel(config::DeformationModelFile file);
    void taskDone(const FeedTaskResult& result, bool cancelled);
    void setBusy(bool busy, const QString& what);
    core::FeedScheduleRequest request() const;
    void reschedule();
    void showSchedule();
    void plotCurves();
    void plotFeeds();
    void updateProgram();
    void showResult();
    void showModelSummary();
    void showRefineProgress(int round, int barsDone, int bars);
    bool checkMisses() const;
    QString refinementLine() const;

    AppContext& m_context;
    FeedModelTask* m_task;
    std::optional<config::FeedSchedulingSetup> m_preset;  ///< the built-in feed-scheduling set-up
    QString m_presetProblem;
    std::optional<config::DeformationModelFile> m_model;
    std::optional<core::DeformationSamples> m_samples;           ///< the measurements m_model was fitted on
    std::optional<config::DeformationModelFile> m_refinedModel;  ///< the local model of the last refinement
    std::optional<core::FeedScheduleRequest> m_refinedFor;       ///< the pass it was refined for
    std::optional<core::FeedRefinement> m_refinement;
    std::optional<config::FeedSchedulingSetup> m_modelSetup;  ///< the simulator the model came from, if known
    std::optional<core::FeedSchedule> m_schedule;
    std::optional<core::MachiningTimes> m_times;
    std::optional<core::FeedScheduleCheck> m_check;
    QString m_program;
    QString m_problem;
    QString m_taskWhat;
    QString m_taskError;

    QGroupBox* m_modelBox;
    QLabel* m_modelSummary;
    QPushButton* m_simulate;
    QPushButton* m_fitCsv;
    QPushButton* m_load;
    QProgressBar* m_progress;
    QPushButton* m_cancel;
    QGroupBox* m_passBox;
    QLabel* m_depthLabel;
    QDoubleSpinBox* m_depth;
    QLabel* m_feedsLabel;
    QDoubleSpinBox* m_feedMin;
    QDoubleSpinBox* m_feedMax;
    QLabel* m_feedStepLabel;
    QDoubleSpinBox* m_feedStep;
    QLabel* m_zLabel;
    QDoubleSpinBox* m_zStart;
    QDoubleSpinBox* m_zEnd;
    QLabel* m_minLengthLabel;
    QDoubleSpinBox* m_minLength;
    QLabel* m_dialectLabel;
    QComboBox* m_dialect;
    QComboBox* m_switch;
    QPushButton* m_checkButton;
    QPushButton* m_refine;
    QPushButton* m_save;
    QLabel* m_levelTitle;
    QLabel* m_levelValue;
    QSlider* m_level;
    QLabel* m_levelLow;
    QLabel* m_levelHigh;
    QLabel* m_result;
    QTabWidget* m_views;
    plot::Chart* m_curves;
    plot::Chart* m_feeds;
    GCodeView* m_programView;
    DeformationModelPanel* m_modelPanel;
};

}  // namespace tt::ui
