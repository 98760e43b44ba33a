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

namespace tt::devices {
class Device;
class DeviceManager;
}  // namespace tt::devices

namespace tt::ui {

class BoringLink;
class Chart;
class CompensationSession;

/// The in-process compensation for the operator (issue 6, item 6; paper 001): choose the source
/// (a device's cross-feed current with dither, or its probe mandrel and plane), the tool (its
/// stiffness and k_p from the tool table), the CNC output for the dynamic X offset, and the rate
/// and range limits; Start and Stop. The run is built by the one run builder (core::buildBoringRun)
/// and runs in its own thread (CompensationSession), one cycle per PLC period, reaching the devices
/// through relays (BoringLink), so a busy window never delays the offset; the plots show the
/// deflection and the offset, and why the offset is held (taper, slide not moving, window too short,
/// device silent) in plain words. A source that offers a simulated boring pass of its own
/// (devices::BoringTruth) can run the compensation on the pass's own PLC instead of a CNC output,
/// faster than real time, and then the bore error with and without compensation is plotted along
/// the bore. The panel asks the devices for capabilities only, never what they are.
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
    Chart* offsetChart() const { return m_chart; }
    Chart* boreChart() const { return m_boreChart; }
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
    CompensationSession& session() const { return *m_session; }

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
    devices::Device* sourceDevice() const;
    std::optional<core::ToolRecord> currentTool() const;
    bool onSourcesPass() const;
    core::BoringRunChoices choicesFromForm(const SourceChoice& source, const core::ToolRecord& tool) const;
    std::shared_ptr<core::BoringStation> makeStation(const SourceChoice& source, core::BoringRunChoices& choices);
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
    QPointer<devices::DeviceManager> m_devices;
    core::BoringScenario m_scenario;  ///< the heavy-boring preset: defaults, and what a source's own pass bores
    QString m_scenarioProblem;
    std::vector<core::ToolRecord> m_tools;
    QString m_toolProblem;

    CompensationSession* m_session;
    BoringLink* m_link = nullptr;
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
    Chart* m_chart;
    Chart* m_boreChart;
};

}  // namespace tt::ui
