#pragma once

#include <QFutureWatcher>
#include <QString>
#include <memory>
#include <optional>
#include <vector>

#include "core/control/margins.h"
#include "core/control/run_to_run_setup.h"
#include "ui/controller/history_identification.h"
#include "ui/page.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

class TuningWorker;
class WeightEditor;
struct TuningResult;

/// The Controller page for the commissioning engineer (issue 13 item 6): delay z, weights R1 / R2 per
/// point (slider and field), correction limits, dead band and the shaping filter W(z) = (z + b)/(z - a);
/// while anything moves, the LQG design is re-synthesised off the GUI thread (coalesced) and the page
/// shows the predicted k_eff per point beside the best EWMA's, the margins, the step response and |S|.
/// Integral action (on/off, its weight) is part of the previewed and applied setup; "Identify from history"
/// identifies the plant of a stored run off the GUI thread (per point the gain and the disturbance as ARMA(p, q),
/// one plant delay: core::tuneFromStoredRun) and designs for all points with it ("Identified model", per point in
/// the tooltip); a design the adaptive loop proposed (mismatch action propose) can be taken the same way.
/// Apply asks first, records who changed what and keeps the applied setup.
class ControllerPage : public Page {
    Q_OBJECT
public:
    ControllerPage(AppContext& context, QWidget* parent = nullptr);
    ~ControllerPage() override;
    QString title() const override;
    void retranslate() override;

    /// The setup the fields describe now.
    core::RunToRunSetup editedSetup() const;
    /// The setup last applied (the preset's until Apply).
    const core::RunToRunSetup& appliedSetup() const { return m_applied; }
    /// The result shown now (null before the first one arrives).
    const TuningResult* shownResult() const { return m_shown.get(); }
    /// The re-synthesis worker (tests wait for its generation).
    const TuningWorker& worker() const { return *m_worker; }
    /// The record of the last Apply (empty before).
    const QString& lastRecord() const { return m_lastRecord; }
    /// The status line under the points (where the last Apply went, the design's warnings).
    QString statusText() const;
    /// The weight editors of point `point` (tests drive them).
    WeightEditor& r1(int point) { return *m_r1[static_cast<std::size_t>(point)]; }
    WeightEditor& r2(int point) { return *m_r2[static_cast<std::size_t>(point)]; }
    /// The k_eff label of `point` (LQG) as shown.
    QString shownLqgKEff(int point) const;
    /// The integral action check box and its weight field (tests drive them).
    QCheckBox* integralBox() const { return m_integral; }
    QDoubleSpinBox* integralWeightField() const { return m_integralWeight; }
    /// The "Identify from history" button, the run chooser (item 0: the newest run) and what it found.
    QPushButton* identifyButton() const { return m_identify; }
    QComboBox* identifyRunBox() const { return m_identifyRun; }
    QString identifiedText() const;
    /// The identified model the design uses while "Identified model" is checked (none before an identification).
    const std::optional<core::ControllerModel>& identifiedModel() const { return m_identifiedModel; }
    /// The "Identified model" check box and the button that takes the loop's proposal (hidden without one).
    QCheckBox* identifiedModelBox() const { return m_useIdentified; }
    QPushButton* proposalButton() const { return m_takeProposal; }
    /// An identification is running in the background.
    bool identifying() const;
    /// The shaping filter fields: a, b, sigma^2 (mm^2).
    double typedPole() const;
    double typedZero() const;
    double typedVarianceMm2() const;

protected:
    void showEvent(QShowEvent* event) override;

private:
    QWidget* buildSettings();
    QWidget* buildPoints();
    QWidget* buildCharts();
    void loadSetup(const core::RunToRunSetup& setup);
    void requestPreview();
    void showResult(std::shared_ptr<const TuningResult> result);
    void showPredictions(const TuningResult& result);
    /// The smallest phase margin and the largest sensitivity peak over the points, for the status line.
    QString phaseAndPeakText(const core::LoopMargins& margins) const;
    void showCharts(const TuningResult& result);
    void apply();
    /// Hands the applied setup to the Run page's loop (AppContext::tuning) and says where it went.
    void showWhereApplied();
    void revert();
    QWidget* buildExtraRow();
    /// Lists the stored runs in the run chooser (keeps the choice when it is still there).
    void refreshRuns();
    void identify();
    void showIdentification();
    /// The chosen run's last adaptation when it is a proposal waiting for an Apply (the proposal button).
    /// The identification's words under its buttons (the line is hidden while there are none).
    void sayIdentified(const QString& text);
    void findProposal();
    void takeProposal();
    /// Designs with `model` from now on; `text` and `details` describe it under the filter.
    void useModel(const core::ControllerModel& model, const QString& text, const QString& details);

    core::RunToRunSetup m_applied;
    std::unique_ptr<TuningWorker> m_worker;
    std::shared_ptr<const TuningResult> m_shown;
    QString m_lastRecord;
    bool m_loading = false;

    QLabel* m_settingsTitle = nullptr;
    QLabel* m_delayLabel = nullptr;
    QSpinBox* m_delay = nullptr;
    QLabel* m_maxAbsLabel = nullptr;
    QDoubleSpinBox* m_maxAbs = nullptr;
    QLabel* m_maxStepLabel = nullptr;
    QDoubleSpinBox* m_maxStep = nullptr;
    QLabel* m_deadBandLabel = nullptr;
    QDoubleSpinBox* m_deadBand = nullptr;
    QLabel* m_filterLabel = nullptr;
    QDoubleSpinBox* m_pole = nullptr;
    QDoubleSpinBox* m_zero = nullptr;
    QDoubleSpinBox* m_variance = nullptr;
    QLabel* m_poleLabel = nullptr;
    QLabel* m_zeroLabel = nullptr;
    QLabel* m_varianceLabel = nullptr;
    QCheckBox* m_integral = nullptr;
    QLabel* m_integralWeightLabel = nullptr;
    QDoubleSpinBox* m_integralWeight = nullptr;
    QComboBox* m_identifyRun = nullptr;
    QPushButton* m_identify = nullptr;
    QLabel* m_identified = nullptr;
    QFutureWatcher<HistoryIdentification> m_identification;
    QCheckBox* m_useIdentified = nullptr;
    QPushButton* m_takeProposal = nullptr;
    std::optional<core::ControllerModel> m_identifiedModel;
    std::optional<core::AdaptationRecord> m_proposal;
    bool m_identifying = false;  ///< from the click until its result is shown

    std::vector<QLabel*> m_headers;
    std::vector<QLabel*> m_pointNames;
    std::vector<WeightEditor*> m_r1, m_r2;
    std::vector<QLabel*> m_kEffLqg, m_kEffEwma, m_gainMargin, m_delayMargin, m_disk;

    QLabel* m_status = nullptr;
    QLabel* m_timing = nullptr;
    QPushButton* m_apply = nullptr;
    QPushButton* m_revert = nullptr;
    plot::Chart* m_stepChart = nullptr;
    plot::Chart* m_sensitivityChart = nullptr;
};

}  // namespace tt::ui
