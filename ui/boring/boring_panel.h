#pragma once

#include <QElapsedTimer>
#include <QMap>
#include <QPointer>
#include <QString>
#include <QVector>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "core/model/tool_stiffness.h"
#include "core/run/boring_run.h"
#include "runtime/boring/boring_targets.h"
#include "ui/app_context.h"
#include "ui/boring/boring_trace.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::runtime {
class CompensationSession;
class DeviceHub;
struct DeviceView;
}  // namespace tt::runtime

namespace tt::ui {

/// The in-process compensation for the operator (issue 6, item 6; paper 001): choose the source
/// (a device's cross-feed current with dither, or its probe mandrel and plane), the tool (its
/// stiffness and k_p from the tool table), the CNC output for the dynamic X offset, and the rate
/// and range limits; Start and Stop. The run is built by the one run builder (core::buildBoringRun)
/// and runs in its own thread (runtime::CompensationSession), one cycle per PLC period, reaching the devices
/// in the device thread through relays, so a busy window never delays the offset; the plots show the
/// deflection and the offset, and why the offset is held (taper, slide not moving, window too short,
/// device silent) in plain words. Where the offset goes is a runtime::BoringTarget (a CNC output, or a
/// source's own simulated pass): the runtime assembles its station, and the panel asks what the target can
/// do (a known truth to plot, a speed, an offset the CNC holds), never what it is.
class BoringPanel : public QWidget {
    Q_OBJECT
public:
    explicit BoringPanel(AppContext& context, QWidget* parent = nullptr);
    ~BoringPanel() override;

    /// Sets every visible text (also on a language change).
    void retranslate();

    /// Starts a run with the choices made; false (and the reason shown) when it cannot.
    bool start();
    /// Stops the run; the CNC keeps the offset it holds.
    void stop();
    /// Writes an offset of 0 to the CNC after asking (only while stopped; the tool must be out of
    /// the bore); false when refused or not confirmed.
    bool zeroOffset();
    bool running() const { return m_running; }

    // For tests and the Run page.
    QComboBox* sourceBox() const { return m_source; }
    QComboBox* planeBox() const { return m_plane; }
    QComboBox* toolBox() const { return m_tool; }
    QComboBox* outputBox() const { return m_output; }
    QComboBox* segmentBox() const { return m_segment; }
    QComboBox* speedBox() const { return m_speed; }
    QDoubleSpinBox* maxOffsetBox() const { return m_maxOffset; }
    QDoubleSpinBox* maxRateBox() const { return m_maxRate; }
    QSpinBox* plcCycleBox() const { return m_plcCycle; }
    QCheckBox* silentBox() const { return m_silent; }
    QPushButton* startButton() const { return m_start; }
    QPushButton* stopButton() const { return m_stop; }
    QPushButton* zeroButton() const { return m_zero; }
    plot::Chart* offsetChart() const { return m_chart; }
    plot::Chart* boreChart() const { return m_boreChart; }
    const BoringRunStats& stats() const { return m_trace.stats(); }
    /// The headline ("Compensating", "Holding the offset at …") and the reason shown.
    QString headline() const;
    QString reason() const;
    /// The detail line (what the device itself reports while the offset is held); empty if none.
    QString detail() const;
    /// Selects the source entry whose key is `key` ("dev:<id>:current", "dev:<id>:probe"); false
    /// when there is none.
    bool selectSource(const QString& key);
    /// Selects the CNC output entry whose key is `key` ("dev:<id>", or "station": the source's own
    /// simulated pass); false when there is none.
    bool selectOutput(const QString& key);
    /// The compensation's session (its thread, its cycle schedule), for tests.
    runtime::CompensationSession& session() const { return *m_session; }

signals:
    void runningChanged(bool running);

protected:
    void showEvent(QShowEvent* event) override;

private:
    struct SourceChoice {
        QString key;
        QString deviceId;
        core::BoringMethod method = core::BoringMethod::Current;
    };

    void buildLayout();
    void connectControls();
    void watchDevices();
    void rebuildChoices();
    void rebuildTools();
    void rebuildOutputs();
    void updateEnabled();
    void syncFaultSwitch();
    std::optional<SourceChoice> currentSource() const;
    const runtime::DeviceView* sourceDevice() const;
    std::optional<runtime::BoringTarget> currentTarget() const;
    std::optional<core::ToolRecord> currentTool() const;
    core::BoringRunChoices choicesFromForm(const SourceChoice& source, const core::ToolRecord& tool) const;
    void finishLink();
    void onCycles(const QVector<core::BoringRunCycle>& batch);
    void refreshPlots();
    void showWords();
    /// Tells the window's header (AppState) the compensation's state: Running while it compensates, Paused
    /// while it holds the offset, Idle once stopped.
    void publishLoopState();
    void showProblem(const QString& text);
    void finishPass();
    void loadSettings();
    void saveSettings() const;
    int speed() const;

    AppContext& m_context;
    QPointer<runtime::DeviceHub> m_devices;
    QList<runtime::BoringTarget> m_targets;  ///< where the offset can go for the chosen source
    core::BoringScenario m_scenario;         ///< the heavy-boring preset: defaults, and what a source's own pass bores
    QString m_scenarioProblem;
    std::vector<core::ToolRecord> m_tools;
    QString m_toolProblem;

    runtime::CompensationSession* m_session;
    runtime::PreparedStation m_prepared;  ///< the station of the run going (or last run)
    bool m_running = false;
    core::BoringMethod m_runMethod = core::BoringMethod::Current;
    QString m_runOutputKey;
    QMap<QString, double> m_heldOffsetMm;  ///< per output device: what the CNC holds after a run
    BoringTrace m_trace;
    QString m_headline;
    QString m_reason;
    QString m_detail;
    bool m_holding = false;
    QString m_problem;  ///< why Start was refused, or the run stopped
    QString m_result;   ///< the simulated pass's result when it finished
    QElapsedTimer m_sinceRefresh;

    // Widgets.
    QGroupBox* m_setup;
    QFormLayout* m_form;
    QLabel* m_sourceLabel;
    QComboBox* m_source;
    QLabel* m_planeLabel;
    QComboBox* m_plane;
    QLabel* m_toolLabel;
    QComboBox* m_tool;
    QLabel* m_toolInfo;
    QLabel* m_outputLabel;
    QComboBox* m_output;
    QLabel* m_maxOffsetLabel;
    QDoubleSpinBox* m_maxOffset;
    QLabel* m_maxRateLabel;
    QDoubleSpinBox* m_maxRate;
    QLabel* m_plcCycleLabel;
    QSpinBox* m_plcCycle;
    QLabel* m_segmentLabel;
    QComboBox* m_segment;
    QLabel* m_speedLabel;
    QComboBox* m_speed;
    QCheckBox* m_silent;
    QPushButton* m_start;
    QPushButton* m_stop;
    QPushButton* m_zero;
    QLabel* m_state;
    bool m_publishedRun = false;  ///< the header shows this panel's run (set Idle again when it stops)
    QLabel* m_reasonLabel;
    QLabel* m_detailLabel;
    QLabel* m_offsetValue;
    QLabel* m_deflectionValue;
    QLabel* m_forceValue;
    QLabel* m_boreValue;
    QProgressBar* m_progress;
    plot::Chart* m_chart;
    plot::Chart* m_boreChart;
};

}  // namespace tt::ui
