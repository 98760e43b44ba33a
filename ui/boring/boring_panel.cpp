#include "ui/boring/boring_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

#include "config/boring_config.h"
#include "core/storage/tool_store.h"
#include "devices/api/device_manager.h"
#include "ui/boring/device_boring_rig.h"
#include "ui/boring/hold_reason.h"
#include "ui/boring/simulated_boring_station.h"
#include "ui/plot/chart.h"
#include "ui/prompt.h"
#include "ui/tools/database_connection.h"

namespace tt::ui {

namespace {

constexpr double kWindowS = 30.0;          ///< the offset chart shows the last 30 s
constexpr double kBoreStepMm = 0.1;        ///< the bore chart keeps a point every 0.1 mm of the bore
constexpr qint64 kRefreshMs = 100;         ///< plots are redrawn at most ten times a second
const int kSpeeds[] = {1, 5, 10, 20, 50};  ///< simulated station: PLC cycles per timer tick
constexpr int kDefaultSpeed = 2;
const QString kSimCurrent = QStringLiteral("sim:current");
const QString kSimProbe = QStringLiteral("sim:probe");
const QString kStationTool = QStringLiteral("station");
const QString kStationOutput = QStringLiteral("sim");

const QColor kMeasured(21, 101, 192);
const QColor kOffset(46, 125, 50);
const QColor kTrue(120, 120, 120);
const QColor kWith(46, 125, 50);
const QColor kWithout(198, 40, 40);

QString mm(double v, int decimals = 3) {
    return QString::number(v, 'f', decimals);
}

double nan() {
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

BoringPanel::BoringPanel(AppContext& context, QWidget* parent)
    : QWidget(parent),
      m_context(context),
      m_timer(new QTimer(this)),
      m_setup(new QGroupBox(this)),
      m_form(new QFormLayout),
      m_sourceLabel(new QLabel(this)),
      m_source(new QComboBox(this)),
      m_planeLabel(new QLabel(this)),
      m_plane(new QComboBox(this)),
      m_toolLabel(new QLabel(this)),
      m_tool(new QComboBox(this)),
      m_toolInfo(new QLabel(this)),
      m_outputLabel(new QLabel(this)),
      m_output(new QComboBox(this)),
      m_maxOffsetLabel(new QLabel(this)),
      m_maxOffset(new QDoubleSpinBox(this)),
      m_maxRateLabel(new QLabel(this)),
      m_maxRate(new QDoubleSpinBox(this)),
      m_plcCycleLabel(new QLabel(this)),
      m_plcCycle(new QSpinBox(this)),
      m_segmentLabel(new QLabel(this)),
      m_segment(new QComboBox(this)),
      m_speedLabel(new QLabel(this)),
      m_speed(new QComboBox(this)),
      m_silent(new QCheckBox(this)),
      m_start(new QPushButton(this)),
      m_stop(new QPushButton(this)),
      m_zero(new QPushButton(this)),
      m_state(new QLabel(this)),
      m_reasonLabel(new QLabel(this)),
      m_detailLabel(new QLabel(this)),
      m_offsetValue(new QLabel(this)),
      m_deflectionValue(new QLabel(this)),
      m_forceValue(new QLabel(this)),
      m_boreValue(new QLabel(this)),
      m_progress(new QProgressBar(this)),
      m_chart(new Chart(this)),
      m_boreChart(new Chart(this)) {
    setObjectName(QStringLiteral("boringPanel"));
    try {
        m_scenario = config::loadBoringScenario(QStringLiteral("heavy-boring"));
    } catch (const std::exception& e) {
        m_scenarioProblem = QString::fromStdString(e.what());
    }
    buildLayout();
    m_timer->setTimerType(Qt::PreciseTimer);
    m_sinceRefresh.start();
    connect(m_timer, &QTimer::timeout, this, [this] {
        const bool simulated = station() != nullptr;
        for (int i = 0, n = simulated ? speed() : 1; i < n && m_rig; ++i) {
            record(m_rig->cycle());
            if (m_rig->finished()) finishPass();
        }
        if (!m_rig || m_sinceRefresh.elapsed() >= kRefreshMs) {
            m_sinceRefresh.restart();
            showWords();
            refreshPlots();
        }
    });
    connect(m_start, &QPushButton::clicked, this, &BoringPanel::start);
    connect(m_stop, &QPushButton::clicked, this, &BoringPanel::stop);
    connect(m_zero, &QPushButton::clicked, this, &BoringPanel::zeroOffset);
    connect(m_source, &QComboBox::currentIndexChanged, this, [this] {
        rebuildTools();
        rebuildOutputs();
        retranslate();
    });
    connect(m_tool, &QComboBox::currentIndexChanged, this, [this] { retranslate(); });
    connect(m_output, &QComboBox::currentIndexChanged, this, [this] { updateEnabled(); });
    connect(m_segment, &QComboBox::currentIndexChanged, this, [this] {
        if (m_rig) m_rig->setSegment(static_cast<core::SegmentKind>(m_segment->currentData().toInt()));
    });
    connect(m_silent, &QCheckBox::toggled, this, [this](bool on) {
        if (SimulatedBoringStation* s = station()) s->setSourceSilent(on);
    });
    loadSettings();
    watchDevices();
    rebuildChoices();
    retranslate();
}

BoringPanel::~BoringPanel() {
    m_timer->stop();
}

void BoringPanel::buildLayout() {
    for (QComboBox* box : {m_source, m_plane, m_tool, m_output, m_segment, m_speed}) {
        box->setMinimumWidth(250);
        box->setMaximumWidth(320);
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    }
    m_source->setObjectName(QStringLiteral("boringSource"));
    m_plane->setObjectName(QStringLiteral("boringPlane"));
    m_tool->setObjectName(QStringLiteral("boringTool"));
    m_output->setObjectName(QStringLiteral("boringOutput"));
    m_segment->setObjectName(QStringLiteral("boringSegment"));
    m_speed->setObjectName(QStringLiteral("boringSpeed"));
    m_silent->setObjectName(QStringLiteral("boringSilent"));
    m_maxOffset->setObjectName(QStringLiteral("boringMaxOffset"));
    m_maxRate->setObjectName(QStringLiteral("boringMaxRate"));
    m_plcCycle->setObjectName(QStringLiteral("boringPlcCycle"));
    m_start->setObjectName(QStringLiteral("boringStart"));
    m_stop->setObjectName(QStringLiteral("boringStop"));
    m_zero->setObjectName(QStringLiteral("boringZero"));
    m_state->setObjectName(QStringLiteral("boringState"));
    m_start->setProperty("role", QStringLiteral("primary"));
    m_stop->setProperty("role", QStringLiteral("danger"));

    m_plane->addItem(QString(), 0);
    m_plane->addItem(QString(), 1);
    m_segment->addItem(QString(), static_cast<int>(core::SegmentKind::Cylinder));
    m_segment->addItem(QString(), static_cast<int>(core::SegmentKind::Taper));
    m_segment->addItem(QString(), static_cast<int>(core::SegmentKind::Contour));
    for (int s : kSpeeds)
        m_speed->addItem(QStringLiteral("× %1").arg(s), s);
    m_speed->setCurrentIndex(kDefaultSpeed);

    // Limits: paper 001's PLC cycle of 10..100 ms; an offset beyond 2 mm is no deflection.
    m_maxOffset->setRange(0.01, 2.0);
    m_maxOffset->setDecimals(3);
    m_maxOffset->setSingleStep(0.01);
    m_maxOffset->setValue(m_scenarioProblem.isEmpty() ? m_scenario.limits.maxOffsetMm : 0.5);
    m_maxRate->setRange(0.001, 1.0);
    m_maxRate->setDecimals(3);
    m_maxRate->setSingleStep(0.005);
    m_maxRate->setValue(m_scenarioProblem.isEmpty() ? m_scenario.limits.maxRateMmPerS : 0.05);
    m_plcCycle->setRange(10, 100);
    m_plcCycle->setValue(m_scenarioProblem.isEmpty() ? static_cast<int>(std::lround(m_scenario.plcCycleS * 1000.0))
                                                     : 20);

    m_toolInfo->setWordWrap(true);
    m_toolInfo->setStyleSheet(QStringLiteral("color: #38434f; font-size: 11pt;"));
    m_form->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_form->setVerticalSpacing(4);
    m_form->addRow(m_sourceLabel, m_source);
    m_form->addRow(m_planeLabel, m_plane);
    m_form->addRow(m_toolLabel, m_tool);
    m_form->addRow(QString(), m_toolInfo);
    m_form->addRow(m_outputLabel, m_output);
    m_form->addRow(m_maxOffsetLabel, m_maxOffset);
    m_form->addRow(m_maxRateLabel, m_maxRate);
    m_form->addRow(m_plcCycleLabel, m_plcCycle);
    m_form->addRow(m_segmentLabel, m_segment);
    m_form->addRow(m_speedLabel, m_speed);
    m_form->addRow(QString(), m_silent);
    m_setup->setLayout(m_form);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_start, 1);
    buttons->addWidget(m_stop, 1);
    auto* left = new QVBoxLayout;
    left->addWidget(m_setup);
    left->addLayout(buttons);
    left->addWidget(m_zero);
    left->addWidget(m_progress);
    left->addStretch(1);

    m_state->setAlignment(Qt::AlignCenter);
    m_state->setMinimumWidth(190);
    m_offsetValue->setStyleSheet(QStringLiteral("font-size: 20pt; font-weight: bold; color: #1f2a36;"));
    for (QLabel* value : {m_deflectionValue, m_forceValue})
        value->setStyleSheet(QStringLiteral("font-size: 15pt; font-weight: bold; color: #38434f;"));
    m_reasonLabel->setWordWrap(true);
    m_reasonLabel->setObjectName(QStringLiteral("boringReason"));
    m_detailLabel->setWordWrap(true);
    m_detailLabel->setStyleSheet(QStringLiteral("color: #56616d; font-size: 11pt;"));
    m_boreValue->setWordWrap(true);
    m_boreValue->setStyleSheet(QStringLiteral("font-size: 14pt; font-weight: bold; color: #1f2a36;"));
    m_progress->setRange(0, 1000);
    m_progress->setTextVisible(true);

    auto* headline = new QHBoxLayout;
    headline->addWidget(m_state);
    headline->addSpacing(16);
    headline->addWidget(m_offsetValue);
    headline->addStretch(1);
    auto* numbers = new QHBoxLayout;
    numbers->addWidget(m_deflectionValue);
    numbers->addSpacing(28);
    numbers->addWidget(m_forceValue);
    numbers->addStretch(1);

    m_chart->setMinimumHeight(170);
    m_boreChart->setMinimumHeight(170);
    m_chart->setLegendBelow(3);
    m_boreChart->setLegendBelow(2);
    m_chart->setYTickCount(5);
    m_boreChart->setYTickCount(5);
    auto* right = new QVBoxLayout;
    right->addLayout(headline);
    right->addLayout(numbers);
    right->addWidget(m_reasonLabel);
    right->addWidget(m_detailLabel);
    right->addWidget(m_boreValue);
    right->addWidget(m_chart, 1);
    right->addWidget(m_boreChart, 1);

    auto* root = new QHBoxLayout(this);
    root->setContentsMargins(8, 8, 8, 8);
    root->addLayout(left, 0);
    root->addSpacing(8);
    root->addLayout(right, 1);
}

void BoringPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (m_context.devices != m_devices) {
        watchDevices();
        rebuildChoices();
    }
    if (!m_rig) {
        rebuildTools();  // the tool table may have changed on the Tools page
        retranslate();
    }
}

void BoringPanel::watchDevices() {
    if (m_devices) disconnect(m_devices, nullptr, this, nullptr);
    m_devices = m_context.devices;
    if (!m_devices) return;
    connect(m_devices, &devices::DeviceManager::devicesChanged, this, [this] {
        if (m_rig && !station()) {
            // The run's devices may be gone or replaced: stop before anything touches them.
            stop();
            showProblem(
                tr("The devices were changed, so the compensation stopped. The CNC keeps the offset it "
                   "holds."));
        }
        rebuildChoices();
    });
}

int BoringPanel::speed() const {
    return std::max(1, m_speed->currentData().toInt());
}

void BoringPanel::rebuildChoices() {
    const QString previous = m_source->currentData().toString();
    {
        const QSignalBlocker block(m_source);
        m_source->clear();
        if (m_scenarioProblem.isEmpty()) {
            m_source->addItem(QString(), kSimCurrent);
            m_source->addItem(QString(), kSimProbe);
        }
        if (m_devices) {
            for (const QString& id : m_devices->devicesOfKind(devices::DeviceKind::DriveCurrent))
                m_source->addItem(QString(), QStringLiteral("dev:%1:current").arg(id));
            for (const QString& id : m_devices->devicesOfKind(devices::DeviceKind::Probe))
                m_source->addItem(QString(), QStringLiteral("dev:%1:probe").arg(id));
        }
        const int at = m_source->findData(previous);
        m_source->setCurrentIndex(at >= 0 ? at : 0);
    }
    rebuildTools();
    rebuildOutputs();
    retranslate();
}

void BoringPanel::rebuildTools() {
    m_tools.clear();
    m_toolProblem.clear();
    try {
        const std::unique_ptr<storage::Database> db = openContextDatabase(m_context.databasePath);
        storage::ToolStore store(*db);
        m_tools = store.tools();
    } catch (const std::exception& e) {
        m_toolProblem = QString::fromStdString(e.what());
    }
    const QString previous = m_tool->currentData().toString();
    const std::optional<SourceChoice> source = currentSource();
    const QSignalBlocker block(m_tool);
    m_tool->clear();
    if (source && source->simulated) m_tool->addItem(QString(), kStationTool);
    for (const core::ToolRecord& t : m_tools)
        m_tool->addItem(QString::fromStdString(t.id + " — " + t.name),
                        QStringLiteral("tool:%1").arg(QString::fromStdString(t.id)));
    const int at = m_tool->findData(previous);
    m_tool->setCurrentIndex(at >= 0 ? at : 0);
}

void BoringPanel::rebuildOutputs() {
    const QString previous = m_output->currentData().toString();
    const std::optional<SourceChoice> source = currentSource();
    const QSignalBlocker block(m_output);
    m_output->clear();
    if (source && source->simulated) {
        m_output->addItem(QString(), kStationOutput);
    } else if (m_devices) {
        for (const QString& id : m_devices->devicesOfKind(devices::DeviceKind::CorrectionOutput))
            if (const devices::DeviceEntry* e = m_devices->entry(id))
                m_output->addItem(e->name, QStringLiteral("dev:%1").arg(id));
    }
    const int at = m_output->findData(previous);
    m_output->setCurrentIndex(at >= 0 ? at : 0);
}

std::optional<BoringPanel::SourceChoice> BoringPanel::currentSource() const {
    const QString key = m_source->currentData().toString();
    if (key.isEmpty()) return std::nullopt;
    SourceChoice c;
    c.key = key;
    if (key == kSimCurrent || key == kSimProbe) {
        c.simulated = true;
        c.source = key == kSimCurrent ? BoringSource::Current : BoringSource::Probe;
        return c;
    }
    const QStringList parts = key.split(QLatin1Char(':'));
    if (parts.size() != 3) return std::nullopt;
    c.deviceId = parts[1];
    c.source = parts[2] == QStringLiteral("probe") ? BoringSource::Probe : BoringSource::Current;
    return c;
}

bool BoringPanel::selectSource(const QString& key) {
    const int at = m_source->findData(key);
    if (at < 0) return false;
    m_source->setCurrentIndex(at);
    return true;
}

std::optional<core::ToolRecord> BoringPanel::currentTool() const {
    const QString key = m_tool->currentData().toString();
    if (key == kStationTool && m_scenarioProblem.isEmpty()) return m_scenario.tool;
    for (const core::ToolRecord& t : m_tools)
        if (QStringLiteral("tool:%1").arg(QString::fromStdString(t.id)) == key) return t;
    return std::nullopt;
}

SimulatedBoringStation* BoringPanel::station() const {
    return dynamic_cast<SimulatedBoringStation*>(m_rig.get());
}

BoringRunSettings BoringPanel::settingsFromForm() const {
    BoringRunSettings s;
    const std::optional<SourceChoice> source = currentSource();
    s.source = source ? source->source : BoringSource::Current;
    s.plane = m_plane->currentData().toInt();
    if (const std::optional<core::ToolRecord> tool = currentTool()) {
        s.stiffnessNPerMm = core::effectiveStiffnessNPerMm(*tool);
        s.currentToForceNPerA = tool->currentToForceGainNPerA;
    }
    s.limits.maxOffsetMm = m_maxOffset->value();
    s.limits.maxRateMmPerS = m_maxRate->value();
    s.plcCycleS = m_plcCycle->value() / 1000.0;
    // The simulated station's estimator thresholds come with its preset; on a machine the
    // engine's defaults (docs/boring-compensation.md) apply.
    if (source && source->simulated) s.estimator = m_scenario.estimator;
    return s;
}

std::unique_ptr<BoringRig> BoringPanel::makeRig(const SourceChoice& source, const BoringRunSettings& settings,
                                                QString& outputKey) {
    outputKey = m_output->currentData().toString();
    if (source.simulated) return std::make_unique<SimulatedBoringStation>(m_scenario, settings);
    if (!m_devices) throw std::invalid_argument(tr("No devices are configured.").toStdString());
    devices::Device* sourceDevice = m_devices->device(source.deviceId);
    if (!sourceDevice) throw std::invalid_argument(tr("The chosen source device is gone.").toStdString());
    if (outputKey.isEmpty())
        throw std::invalid_argument(
            tr("No CNC output for the dynamic X offset: add one on the Devices page.").toStdString());
    devices::Device* outputDevice = m_devices->device(outputKey.mid(4));
    if (!outputDevice) throw std::invalid_argument(tr("The chosen CNC output is gone.").toStdString());
    const double held = m_heldOffsetMm.value(outputKey, 0.0);
    if (std::abs(held) > settings.limits.maxOffsetMm)
        throw std::invalid_argument(tr("The CNC holds an offset of %1 mm, more than the limit of %2 mm: zero the "
                                       "offset first (tool out of the bore).")
                                        .arg(mm(held), mm(settings.limits.maxOffsetMm))
                                        .toStdString());
    m_runDevices = {source.deviceId, outputKey.mid(4)};
    return std::make_unique<DeviceBoringRig>(*sourceDevice, *outputDevice, m_devices->clock(), settings, held);
}

bool BoringPanel::start() {
    if (m_rig) return false;
    m_problem.clear();
    m_result.clear();
    const std::optional<SourceChoice> source = currentSource();
    if (!source) {
        showProblem(tr("Choose where the deflection comes from."));
        return false;
    }
    if (!currentTool()) {
        showProblem(m_tools.empty() ? tr("No tool: add the boring bar to the tool table on the Tools page.")
                                    : tr("Choose the tool."));
        return false;
    }
    const BoringRunSettings settings = settingsFromForm();
    try {
        m_rig = makeRig(*source, settings, m_runOutputKey);
    } catch (const std::exception& e) {
        m_rig.reset();
        showProblem(tr("Cannot start: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
    m_runSource = settings.source;
    m_rig->setSegment(static_cast<core::SegmentKind>(m_segment->currentData().toInt()));
    if (SimulatedBoringStation* s = station()) s->setSourceSilent(m_silent->isChecked());
    m_stats = BoringRunStats{};
    m_stats.offsetMm = m_rig->offsetMm();
    for (auto* v : {&m_timeS, &m_measuredMm, &m_offsetMm, &m_trueMm, &m_zMm, &m_errorMm, &m_twinErrorMm})
        v->clear();
    m_lastBoreZ = -1e9;
    m_headline = tr("Starting");
    m_reason.clear();
    m_detail.clear();
    m_holding = false;
    saveSettings();
    m_timer->start(static_cast<int>(std::lround(m_rig->plcCycleS() * 1000.0)));
    updateEnabled();
    showWords();
    refreshPlots();
    emit runningChanged(true);
    return true;
}

void BoringPanel::stop() {
    if (!m_rig) return;
    m_timer->stop();
    m_heldOffsetMm[m_runOutputKey] = station() ? 0.0 : m_rig->offsetMm();
    m_rig.reset();
    m_runDevices.clear();
    m_headline = tr("Stopped");
    m_holding = false;
    updateEnabled();
    showWords();
    refreshPlots();
    emit runningChanged(false);
}

bool BoringPanel::zeroOffset() {
    if (m_rig || !m_devices) return false;
    const QString key = m_output->currentData().toString();
    const double held = m_heldOffsetMm.value(key, 0.0);
    devices::Device* device = key.startsWith(QStringLiteral("dev:")) ? m_devices->device(key.mid(4)) : nullptr;
    if (!device || !device->correctionOutput()) return false;
    if (m_context.prompt &&
        m_context.prompt->ask(this, tr("Zero the offset"),
                              tr("The CNC holds a dynamic X offset of %1 mm. Set it to 0 now? The tool moves by %2 mm: "
                                 "do this only with the tool out of the bore.")
                                  .arg(mm(held), mm(-held))) != Prompt::Answer::Yes)
        return false;
    const core::OutputResult r = device->correctionOutput()->sendDynamicOffset(0.0);
    if (!r.ok) {
        showProblem(tr("The CNC did not take the offset 0: %1").arg(QString::fromStdString(r.message)));
        return false;
    }
    m_heldOffsetMm[key] = 0.0;
    m_stats.offsetMm = 0.0;
    m_problem.clear();
    updateEnabled();
    showWords();
    return true;
}

void BoringPanel::runCycles(int cycles) {
    for (int i = 0; i < cycles && m_rig; ++i) {
        record(m_rig->cycle());
        if (m_rig->finished()) finishPass();
    }
    showWords();
    refreshPlots();
}

void BoringPanel::record(const BoringCycleView& view) {
    const core::CompensationCycle& c = view.cycle;
    const CycleWords words = describeCycle(c, m_runSource);
    m_headline = words.headline;
    m_reason = words.reason;
    m_detail = words.holding ? words.detail : QString();
    m_holding = words.holding;
    const double previous = m_stats.offsetMm;
    ++m_stats.cycles;
    if (words.holding) ++m_stats.holdingCycles;
    if (c.sent) ++m_stats.sentCycles;
    m_stats.offsetMm = c.step.offsetMm;
    m_stats.largestOffsetMm = std::max(m_stats.largestOffsetMm, std::abs(c.step.offsetMm));
    m_stats.largestStepMm = std::max(m_stats.largestStepMm, std::abs(c.step.offsetMm - previous));
    m_stats.deflectionMm = c.reading.deflectionMm;
    m_stats.forceN = c.reading.forceN;

    if (m_timeS.size() > 1 && m_timeS.back() - m_timeS.front() > kWindowS) {
        const auto drop = static_cast<std::ptrdiff_t>(m_timeS.size() / 10 + 1);
        for (auto* v : {&m_timeS, &m_measuredMm, &m_offsetMm, &m_trueMm})
            v->erase(v->begin(), v->begin() + std::min<std::ptrdiff_t>(drop, static_cast<std::ptrdiff_t>(v->size())));
    }
    if (m_stats.cycles == 1) m_runStartS = c.timeS;
    m_timeS.push_back(c.timeS);
    m_measuredMm.push_back(c.reading.deflectionMm.value_or(nan()));
    m_offsetMm.push_back(c.step.offsetMm);
    m_trueMm.push_back(view.truth ? view.truth->deflectionMm : nan());

    if (!view.truth) return;
    const StationTruth& t = *view.truth;
    m_stats.zMm = t.zMm;
    if (!t.cutting) return;
    if (t.zMm - m_lastBoreZ >= kBoreStepMm) {
        m_lastBoreZ = t.zMm;
        m_zMm.push_back(t.zMm);
        m_errorMm.push_back(t.diameterErrorMm);
        m_twinErrorMm.push_back(t.uncompensatedErrorMm);
    }
    // Gauged as `trueturn boring` does: from the margin inside each end of the bore.
    const double margin = m_scenario.cut.gaugeMarginMm;
    if (t.zMm >= margin && t.zMm <= m_scenario.cut.boreLengthMm - margin) {
        m_stats.boreErrorMaxMm = std::max(m_stats.boreErrorMaxMm.value_or(0.0), std::abs(t.diameterErrorMm));
        m_stats.uncompensatedMaxMm =
            std::max(m_stats.uncompensatedMaxMm.value_or(0.0), std::abs(t.uncompensatedErrorMm));
    }
}

void BoringPanel::finishPass() {
    if (m_stats.boreErrorMaxMm && m_stats.uncompensatedMaxMm && *m_stats.uncompensatedMaxMm > 0.0)
        m_result =
            tr("The bore is finished: largest diameter error %1 mm with compensation, %2 mm without (%3 %).")
                .arg(mm(*m_stats.boreErrorMaxMm), mm(*m_stats.uncompensatedMaxMm))
                .arg(QString::number(100.0 * (*m_stats.boreErrorMaxMm / *m_stats.uncompensatedMaxMm - 1.0), 'f', 0));
    stop();
}

void BoringPanel::showProblem(const QString& text) {
    m_problem = text;
    showWords();
}

QString BoringPanel::headline() const {
    return m_state->text();
}

QString BoringPanel::reason() const {
    return m_reasonLabel->text();
}

void BoringPanel::showWords() {
    const bool run = m_rig != nullptr;
    const QString tone = !run        ? QStringLiteral("#6b7785")
                         : m_holding ? QStringLiteral("#b26a00")
                                     : QStringLiteral("#2e7d32");
    m_state->setText(!run ? tr("Stopped") : m_holding ? tr("Holding") : m_headline);
    m_state->setStyleSheet(QStringLiteral("font-size: 16pt; font-weight: bold; color: white; background: %1; "
                                          "border-radius: 6px; padding: 6px 14px;")
                               .arg(tone));
    m_offsetValue->setText(tr("Offset %1 mm").arg(mm(m_stats.offsetMm)));
    m_deflectionValue->setText(m_stats.deflectionMm ? tr("Deflection %1 mm").arg(mm(*m_stats.deflectionMm))
                                                    : tr("Deflection —"));
    m_forceValue->setText(m_stats.forceN ? tr("Force %1 N").arg(QString::number(*m_stats.forceN, 'f', 0))
                                         : tr("Force —"));
    QString reason;
    QString colour = QStringLiteral("#1f2a36");
    if (!m_problem.isEmpty()) {
        reason = m_problem;
        colour = QStringLiteral("#b71c1c");
    } else if (run && m_holding) {
        reason = m_headline + QStringLiteral(": ") + m_reason;
        colour = QStringLiteral("#b26a00");
    } else if (run) {
        reason = m_reason;
    } else if (!m_result.isEmpty()) {
        reason = m_result;
        colour = QStringLiteral("#1b5e20");
    } else {
        reason =
            tr("Stopped. The CNC keeps the offset it holds. Choose the source, the tool and the limits, then "
               "Start.");
    }
    m_reasonLabel->setText(reason);
    m_reasonLabel->setStyleSheet(QStringLiteral("font-size: 14pt; font-weight: bold; color: %1;").arg(colour));
    m_detailLabel->setText(
        run && m_holding && !m_detail.isEmpty() && m_detail != m_reason ? tr("Engine: %1").arg(m_detail) : QString());
    m_detailLabel->setVisible(!m_detailLabel->text().isEmpty());
    const std::optional<SourceChoice> source = currentSource();
    const bool simulated = source && source->simulated;
    m_boreValue->setVisible(simulated);
    m_boreChart->setVisible(simulated);
    m_progress->setVisible(simulated);
    if (simulated) {
        m_boreValue->setText(m_stats.boreErrorMaxMm && m_stats.uncompensatedMaxMm
                                 ? tr("Bore diameter error from %1 mm in: %2 mm with compensation, %3 mm without")
                                       .arg(QString::number(m_scenario.cut.gaugeMarginMm, 'f', 0),
                                            mm(*m_stats.boreErrorMaxMm), mm(*m_stats.uncompensatedMaxMm))
                                 : tr("Bore diameter error: shown from %1 mm into the bore")
                                       .arg(QString::number(m_scenario.cut.gaugeMarginMm, 'f', 0)));
        const double length = m_scenario.cut.boreLengthMm;
        m_progress->setValue(static_cast<int>(std::lround(1000.0 * std::clamp(m_stats.zMm / length, 0.0, 1.0))));
        m_progress->setFormat(
            tr("Tool at %1 of %2 mm")
                .arg(QString::number(std::max(0.0, m_stats.zMm), 'f', 1), QString::number(length, 'f', 0)));
    }
}

void BoringPanel::refreshPlots() {
    if (m_timeS.empty()) {
        m_chart->clear();
        m_boreChart->clear();
    } else {
        const double t0 = m_runStartS;  // seconds since the run started
        std::vector<double> t(m_timeS.size());
        std::transform(m_timeS.begin(), m_timeS.end(), t.begin(), [t0](double v) { return v - t0; });
        m_chart->setSeries(QStringLiteral("measured"), tr("Deflection measured"), t, m_measuredMm, kMeasured);
        m_chart->setSeries(QStringLiteral("offset"), tr("Offset applied"), t, m_offsetMm, kOffset, Chart::Style::Steps);
        if (station() || std::any_of(m_trueMm.begin(), m_trueMm.end(), [](double v) { return std::isfinite(v); }))
            m_chart->setSeries(QStringLiteral("true"), tr("Real deflection (simulator)"), t, m_trueMm, kTrue);
        else
            m_chart->removeSeries(QStringLiteral("true"));
        m_chart->rescale();
        m_chart->setXRange(std::max(0.0, t.back() - kWindowS), std::max(t.back(), 5.0));
        if (!m_zMm.empty()) {
            m_boreChart->setSeries(QStringLiteral("without"), tr("Without compensation"), m_zMm, m_twinErrorMm,
                                   kWithout);
            m_boreChart->setSeries(QStringLiteral("with"), tr("With compensation"), m_zMm, m_errorMm, kWith);
            m_boreChart->rescale();
            m_boreChart->setXRange(0.0, std::max(m_zMm.back(), 10.0));
        }
    }
    m_chart->refresh();
    m_boreChart->refresh();
}

void BoringPanel::updateEnabled() {
    const bool run = m_rig != nullptr;
    const std::optional<SourceChoice> source = currentSource();
    const bool simulated = source && source->simulated;
    const bool probe = source && source->source == BoringSource::Probe;
    for (QWidget* w : std::initializer_list<QWidget*>{m_source, m_tool, m_output, m_maxOffset, m_maxRate, m_plcCycle,
                                                      m_plane, m_speed})
        w->setEnabled(!run);
    m_start->setEnabled(!run && source.has_value());
    m_stop->setEnabled(run);
    const QString outputKey = m_output->currentData().toString();
    m_zero->setEnabled(!run && !simulated && std::abs(m_heldOffsetMm.value(outputKey, 0.0)) > 0.0);
    m_form->setRowVisible(m_plane, probe && !simulated);
    m_form->setRowVisible(m_segment, !probe);
    m_form->setRowVisible(m_speed, simulated);
    m_form->setRowVisible(m_silent, simulated);
    m_zero->setVisible(!simulated);
}

void BoringPanel::loadSettings() {
    QSettings settings;
    settings.beginGroup(QStringLiteral("boringPanel"));
    if (settings.contains(QStringLiteral("maxOffsetMm")))
        m_maxOffset->setValue(settings.value(QStringLiteral("maxOffsetMm")).toDouble());
    if (settings.contains(QStringLiteral("maxRateMmPerS")))
        m_maxRate->setValue(settings.value(QStringLiteral("maxRateMmPerS")).toDouble());
    if (settings.contains(QStringLiteral("plcCycleMs")))
        m_plcCycle->setValue(settings.value(QStringLiteral("plcCycleMs")).toInt());
    const int speedAt = m_speed->findData(settings.value(QStringLiteral("speed")).toInt());
    if (speedAt >= 0) m_speed->setCurrentIndex(speedAt);
    m_plane->setCurrentIndex(std::clamp(settings.value(QStringLiteral("plane")).toInt(), 0, 1));
    // The lists are built later and keep the entry whose key was selected: seed them with the
    // saved keys.
    m_source->addItem(QString(), settings.value(QStringLiteral("source")).toString());
    m_tool->addItem(QString(), settings.value(QStringLiteral("tool")).toString());
    m_output->addItem(QString(), settings.value(QStringLiteral("output")).toString());
}

void BoringPanel::saveSettings() const {
    QSettings settings;
    settings.beginGroup(QStringLiteral("boringPanel"));
    settings.setValue(QStringLiteral("source"), m_source->currentData());
    settings.setValue(QStringLiteral("tool"), m_tool->currentData());
    settings.setValue(QStringLiteral("output"), m_output->currentData());
    settings.setValue(QStringLiteral("plane"), m_plane->currentIndex());
    settings.setValue(QStringLiteral("maxOffsetMm"), m_maxOffset->value());
    settings.setValue(QStringLiteral("maxRateMmPerS"), m_maxRate->value());
    settings.setValue(QStringLiteral("plcCycleMs"), m_plcCycle->value());
    settings.setValue(QStringLiteral("speed"), m_speed->currentData());
}

void BoringPanel::retranslate() {
    m_setup->setTitle(tr("Set-up"));
    m_sourceLabel->setText(tr("Source"));
    m_planeLabel->setText(tr("Plane along X"));
    m_toolLabel->setText(tr("Tool"));
    m_outputLabel->setText(tr("CNC output"));
    m_maxOffsetLabel->setText(tr("Offset limit ±"));
    m_maxRateLabel->setText(tr("Rate limit"));
    m_plcCycleLabel->setText(tr("PLC cycle"));
    m_maxOffset->setSuffix(tr(" mm"));
    m_maxRate->setSuffix(tr(" mm/s"));
    m_plcCycle->setSuffix(tr(" ms"));
    m_segmentLabel->setText(tr("Cutting"));
    m_speedLabel->setText(tr("Speed"));
    m_silent->setText(tr("Simulate a silent read-out"));
    m_start->setText(tr("Start"));
    m_stop->setText(tr("Stop"));
    m_zero->setText(tr("Zero the offset…"));
    m_plane->setItemText(0, tr("Plane 1"));
    m_plane->setItemText(1, tr("Plane 2"));
    m_segment->setItemText(0, tr("Cylinder"));
    m_segment->setItemText(1, tr("Taper"));
    m_segment->setItemText(2, tr("Contour"));
    for (int i = 0; i < m_source->count(); ++i) {
        const QString key = m_source->itemData(i).toString();
        QString text;
        if (key == kSimCurrent) {
            text = tr("Station: current + dither");
        } else if (key == kSimProbe) {
            text = tr("Station: probe mandrel");
        } else {
            const QStringList parts = key.split(QLatin1Char(':'));
            const devices::DeviceEntry* e = m_devices && parts.size() == 3 ? m_devices->entry(parts[1]) : nullptr;
            const QString name = e ? e->name : key;
            text = parts.value(2) == QStringLiteral("probe") ? tr("%1: probe mandrel").arg(name)
                                                             : tr("%1: current + dither").arg(name);
        }
        m_source->setItemText(i, text);
    }
    const int station = m_tool->findData(kStationTool);
    if (station >= 0) m_tool->setItemText(station, tr("Station: %1").arg(QString::fromStdString(m_scenario.tool.name)));
    const int stationOutput = m_output->findData(kStationOutput);
    if (stationOutput >= 0) m_output->setItemText(stationOutput, tr("Station's PLC"));
    if (const std::optional<core::ToolRecord> tool = currentTool()) {
        const double k = core::effectiveStiffnessNPerMm(*tool);
        m_toolInfo->setText(tr("k %1 N/mm%2 · k_p %3 N/A\nL/d %4")
                                .arg(QString::number(k, 'f', 0), tool->measured ? tr(" (measured)") : QString(),
                                     tool->currentToForceGainNPerA > 0.0
                                         ? QString::number(tool->currentToForceGainNPerA, 'f', 1)
                                         : tr("not calibrated"),
                                     QString::number(core::slendernessRatio(*tool), 'f', 1)));
    } else {
        m_toolInfo->setText(!m_toolProblem.isEmpty() ? tr("The tool table cannot be read: %1").arg(m_toolProblem)
                                                     : tr("No tool in the tool table (Tools page)."));
    }
    m_chart->setTitle(tr("Deflection and dynamic X offset"));
    m_chart->setAxisTitles(tr("Time, s"), tr("mm"));
    m_boreChart->setTitle(tr("Bore diameter error along the bore (simulated station)"));
    m_boreChart->setAxisTitles(tr("Position in the bore, mm"), tr("Diameter error, mm"));
    if (!m_rig && m_headline.isEmpty()) m_headline = tr("Stopped");
    updateEnabled();
    showWords();
    refreshPlots();
}

}  // namespace tt::ui
