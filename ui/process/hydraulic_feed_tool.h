#pragma once

#include <memory>

#include "core/sim/hydraulic/feed_study.h"
#include "ui/app_context.h"
#include "ui/process/feed_study_worker.h"
#include "ui/process/process_tool.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

class FeedBlockDiagram;
class FeedChartTabs;
class FeedParameterForm;

/// Hydraulic feed stabilisation (paper 003) as a tab of the Process page, for the machine's designer
/// choosing the regulator and the commissioning engineer checking a retrofit: the block diagram of the
/// chain with every parameter editable, the regulator (feedback of the measured feed, or the paper's
/// feed-forward of the measured force), the feed, the slot's opening and the magnet current after a load
/// step with and without the regulator, the feedback's gain and phase margins, the warnings of the run
/// (stall, saturated slot, feed off the set feed), sweeps of xi and of the gain as families of curves with
/// their settling times and overshoots, the feed-forward's stability boundary, and export (PNG, CSV).
/// The simulations run in a worker thread with progress and cancel.
class HydraulicFeedTool : public ProcessTool {
    Q_OBJECT
public:
    explicit HydraulicFeedTool(AppContext& context, QWidget* parent = nullptr);
    ~HydraulicFeedTool() override;

    QString key() const override { return QStringLiteral("hydraulic-feed"); }
    QString title() const override;
    void retranslate() override;

    /// Simulates the scenario with and without the regulator; false when a job runs or the form is refused.
    bool simulate();
    /// Sweeps xi (or the gain) with the regulator on; false when a job runs or the form is refused.
    bool sweep(core::FeedSweepKind kind);
    /// Stops the running job.
    void cancel();
    bool busy() const;

    /// Writes the chart shown to a PNG file asked through the prompt; false when cancelled or failed.
    bool exportPng();
    /// Writes the curves shown (both runs, or the sweep's family) as CSV; false when cancelled or failed.
    bool exportCsv();

    /// The regulator chosen (feedback by default).
    core::FeedRegulator regulator() const;
    void setRegulator(core::FeedRegulator regulator);

    /// For tests and screenshots.
    FeedBlockDiagram* diagram() const { return m_diagram; }
    FeedParameterForm* form() const { return m_form; }
    FeedChartTabs* charts() const { return m_charts; }
    QString summary() const;
    QString status() const;

private:
    void buildLayout();
    void loadPreset();
    /// The scenario of the form, or nothing (the reason shown) when the engine refuses it.
    std::optional<core::FeedScenario> scenarioFromForm();
    bool startJob(FeedStudyResult::Job job);
    void finishJob(const std::shared_ptr<const FeedStudyResult>& result);
    void designGain();
    void showSummary();
    /// The run's regulator part of the summary: margins (feedback) or the gain's boundary (feed-forward).
    QString regulatorSummary(const FeedStudyResult& r) const;
    /// The warnings of the regulated run, one sentence each.
    QString warningsText(const FeedStudyResult& r) const;
    /// What the last sweep showed, for the sweep's tabs.
    QString sweepSummary() const;
    /// The diagram's texts, which follow the parameters (the loop is drawn when y > 0).
    void refreshDiagram();
    void updateEnabled();
    void setStatus(const QString& text, bool problem);

    AppContext& m_context;
    core::FeedScenario m_preset;
    QString m_presetProblem;
    FeedStudyWorker* m_worker;
    std::shared_ptr<const FeedStudyResult> m_run;
    std::shared_ptr<const FeedStudyResult> m_sweep;

    FeedBlockDiagram* m_diagram;
    FeedParameterForm* m_form;
    QWidget* m_scenarioBox;
    QLabel* m_loadLabel;
    QDoubleSpinBox* m_load;
    QLabel* m_atLabel;
    QDoubleSpinBox* m_stepTime;
    QLabel* m_durationLabel;
    QDoubleSpinBox* m_duration;
    QLabel* m_regulatorLabel;
    QComboBox* m_regulator;
    QPushButton* m_reset;
    QPushButton* m_simulate;
    QPushButton* m_sweepXi;
    QPushButton* m_sweepGain;
    QPushButton* m_cancel;
    FeedChartTabs* m_charts;
    QLabel* m_summary;
    QLabel* m_status;
    QLabel* m_exportLabel;
    QPushButton* m_exportPng;
    QPushButton* m_exportCsv;
    QProgressBar* m_progress;
};

}  // namespace tt::ui
