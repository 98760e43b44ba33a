#pragma once

#include <QElapsedTimer>
#include <QMap>
#include <QPointer>
#include <QString>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "core/model/tool_stiffness.h"
#include "core/sim/boring/boring_machine.h"
#include "ui/app_context.h"
#include "ui/boring/boring_rig.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTimer;

namespace tt::devices {
class DeviceManager;
}

namespace tt::ui {

class Chart;
class SimulatedBoringStation;

/// What a run has done so far, for the operator's numbers and for tests.
struct BoringRunStats {
    int cycles = 0;
    int holdingCycles = 0;
    int sentCycles = 0;                        ///< cycles whose offset the CNC took
    double offsetMm = 0.0;                     ///< the offset the CNC holds now, mm
    double largestOffsetMm = 0.0;              ///< largest |offset| sent, mm
    double largestStepMm = 0.0;                ///< largest change of the offset in one cycle, mm
    std::optional<double> deflectionMm;        ///< the source's latest deflection, mm
    std::optional<double> forceN;              ///< the source's latest force, N
    std::optional<double> boreErrorMaxMm;      ///< simulated station: max |diameter error| gauged so far
    std::optional<double> uncompensatedMaxMm;  ///< the same on the twin pass without compensation
    double zMm = 0.0;                          ///< simulated station: where the tool is
};

/// The in-process compensation for the operator (issue 6, item 6; paper 001): choose the source
/// (the cross-feed current with dither, or the probe mandrel and its plane), the tool (its
/// stiffness and k_p from the tool table), the CNC output for the dynamic X offset, and the rate
/// and range limits; Start and Stop. Each PLC cycle (a timer in the GUI thread, where the devices
/// live) the compensator reads the source and writes the offset; the plots show the deflection
/// and the offset, and why the offset is held (taper, slide not moving, window too short, device
/// silent) in plain words. Without devices (or by choice) it runs the built-in simulated boring
/// station, whose plot of the bore error with and without compensation shows it working.
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
    /// Runs `cycles` PLC cycles now (the timer runs one per PLC cycle, or `speed` of them on the
    /// simulated station). Stops by itself when the simulated bore is finished.
    void runCycles(int cycles);
    bool running() const { return m_rig != nullptr; }

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
    const BoringRunStats& stats() const { return m_stats; }
    /// The headline ("Compensating", "Holding the offset at …") and the reason shown.
    QString headline() const;
    QString reason() const;
    /// The simulated station of the current run; null otherwise.
    SimulatedBoringStation* station() const;
    /// Selects the source entry whose key is `key` ("sim:current", "sim:probe", "dev:<id>:current",
    /// "dev:<id>:probe"); false when there is none.
    bool selectSource(const QString& key);

signals:
    void runningChanged(bool running);

protected:
    void showEvent(QShowEvent* event) override;

private:
    struct SourceChoice {
        QString key;
        bool simulated = false;
        BoringSource source = BoringSource::Current;
        QString deviceId;
    };

    void buildLayout();
    void watchDevices();
    void rebuildChoices();
    void rebuildTools();
    void rebuildOutputs();
    void updateEnabled();
    std::optional<SourceChoice> currentSource() const;
    std::optional<core::ToolRecord> currentTool() const;
    BoringRunSettings settingsFromForm() const;
    std::unique_ptr<BoringRig> makeRig(const SourceChoice& source, const BoringRunSettings& settings,
                                       QString& outputKey);
    void record(const BoringCycleView& view);
    void refreshPlots();
    void showWords();
    void showProblem(const QString& text);
    void finishPass();
    void loadSettings();
    void saveSettings() const;
    int speed() const;

    AppContext& m_context;
    QPointer<devices::DeviceManager> m_devices;
    core::BoringScenario m_scenario;
    QString m_scenarioProblem;
    std::vector<core::ToolRecord> m_tools;
    QString m_toolProblem;

    std::unique_ptr<BoringRig> m_rig;
    BoringSource m_runSource = BoringSource::Current;
    QString m_runOutputKey;
    QStringList m_runDevices;              ///< device ids the run uses
    QMap<QString, double> m_heldOffsetMm;  ///< per output: what the CNC holds after a run
    QTimer* m_timer;
    BoringRunStats m_stats;
    QString m_headline;
    QString m_reason;
    QString m_detail;
    bool m_holding = false;
    QString m_problem;  ///< why Start was refused, or the run stopped
    QString m_result;   ///< the simulated pass's result when it finished

    // Plot data.
    std::vector<double> m_timeS, m_measuredMm, m_offsetMm, m_trueMm;
    double m_runStartS = 0.0;
    std::vector<double> m_zMm, m_errorMm, m_twinErrorMm;
    double m_lastBoreZ = -1e9;
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
