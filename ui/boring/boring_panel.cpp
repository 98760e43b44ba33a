#include "ui/boring/boring_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "config/boring_config.h"
#include "core/storage/tool_store.h"
#include "plot/chart.h"
#include "runtime/boring/compensation_session.h"
#include "runtime/devices/boring_link.h"
#include "runtime/devices/device_hub.h"
#include "ui/app_state.h"
#include "ui/boring/hold_reason.h"
#include "ui/prompt.h"

namespace tt::ui {

namespace {

constexpr qint64 kRefreshMs = 100;         ///< plots are redrawn at most ten times a second
const int kSpeeds[] = {1, 5, 10, 20, 50};  ///< a source's own pass: PLC cycles per PLC period
constexpr int kDefaultSpeed = 2;
/// The CNC output entry of a source's own simulated pass (its PLC), offered when the source has one.
/// The tool entry of a source's own simulated pass (the scenario's bar).
const QString kPassTool = QStringLiteral("station");

const QColor kMeasured(21, 101, 192);
const QColor kOffset(46, 125, 50);
const QColor kTrue(120, 120, 120);
const QColor kWith(46, 125, 50);
const QColor kWithout(198, 40, 40);

QString mm(double v, int decimals = 3) {
    return QString::number(v, 'f', decimals);
}

}  // namespace

BoringPanel::BoringPanel(AppContext& context, QWidget* parent)
    : QWidget(parent),
      m_context(context),
      m_session(new runtime::CompensationSession(this)),
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
      m_chart(new plot::Chart(this)),
      m_boreChart(new plot::Chart(this)) {
    setObjectName(QStringLiteral("boringPanel"));
    try {
        m_scenario = config::loadBoringScenario(QStringLiteral("heavy-boring"));
    } catch (const std::exception& e) {
        m_scenarioProblem = QString::fromStdString(e.what());
    }
    buildLayout();
    m_sinceRefresh.start();
    connectControls();
    loadSettings();
    watchDevices();
    rebuildChoices();
    retranslate();
}

BoringPanel::~BoringPanel() {
    // No signal from a panel being destroyed: the session stops its thread, the link its relays.
    m_session->stop();
    finishLink();
}

void BoringPanel::finishLink() {
    if (!m_prepared.finish) return;
    const std::optional<double> held = m_prepared.finish();
    m_prepared = {};
    const std::optional<runtime::BoringTarget> target = currentTarget();
    if (held && target && target->can.holdsOffset) {
        m_heldOffsetMm[m_runOutputKey] = *held;
        m_trace.setOffsetMm(*held);
    }
}

void BoringPanel::connectControls() {
    connect(m_session, &runtime::CompensationSession::cycles, this, &BoringPanel::onCycles);
    connect(m_session, &runtime::CompensationSession::passFinished, this, &BoringPanel::finishPass);
    connect(m_start, &QPushButton::clicked, this, &BoringPanel::start);
    connect(m_stop, &QPushButton::clicked, this, &BoringPanel::stop);
    connect(m_zero, &QPushButton::clicked, this, &BoringPanel::zeroOffset);
    connect(m_source, &QComboBox::currentIndexChanged, this, [this] {
        rebuildOutputs();
        rebuildTools();
        syncFaultSwitch();
        retranslate();
    });
    connect(m_tool, &QComboBox::currentIndexChanged, this, [this] { retranslate(); });
    connect(m_output, &QComboBox::currentIndexChanged, this, [this] {
        rebuildTools();
        retranslate();
    });
    connect(m_segment, &QComboBox::currentIndexChanged, this, [this] {
        if (m_running) m_session->setSegment(static_cast<core::SegmentKind>(m_segment->currentData().toInt()));
    });
    connect(m_silent, &QCheckBox::toggled, this, [this](bool on) {
        // The source device's own fault switch, as on the Devices page.
        const runtime::DeviceView* d = sourceDevice();
        if (!d || !d->faults) return;
        devices::FaultSwitches faults = *d->faults;
        faults.silent = on;
        m_devices->setFaults(d->id, faults);
    });
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
    if (m_context.devices != m_devices && !m_running) {
        watchDevices();
        rebuildChoices();
    }
    if (!m_running) {
        rebuildTools();  // the tool table may have changed on the Tools page
        syncFaultSwitch();
        retranslate();
    }
}

void BoringPanel::watchDevices() {
    if (m_devices) disconnect(m_devices, nullptr, this, nullptr);
    m_devices = m_context.devices;
    if (!m_devices) return;
    connect(m_devices, &runtime::DeviceHub::devicesChanged, this, [this] {
        if (m_running) {
            // The run's devices may be gone or replaced: stop before anything touches them.
            stop();
            showProblem(
                tr("The devices were changed, so the compensation stopped. The CNC keeps the offset it "
                   "holds."));
        }
        rebuildChoices();
    });
    // The source's fault switch may be set on the Devices page too: the check box follows it.
    connect(m_devices, &runtime::DeviceHub::deviceChanged, this, [this](const QString& id) {
        if (const std::optional<SourceChoice> source = currentSource(); source && source->deviceId == id)
            syncFaultSwitch();
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
        if (m_devices) {
            for (const QString& id : m_devices->devicesOfKind(devices::DeviceKind::DriveCurrent))
                m_source->addItem(QString(), QStringLiteral("dev:%1:current").arg(id));
            for (const QString& id : m_devices->devicesOfKind(devices::DeviceKind::Probe))
                m_source->addItem(QString(), QStringLiteral("dev:%1:probe").arg(id));
        }
        const int at = m_source->findData(previous);
        m_source->setCurrentIndex(at >= 0 ? at : 0);
    }
    rebuildOutputs();
    rebuildTools();
    syncFaultSwitch();
    retranslate();
}

void BoringPanel::rebuildTools() {
    m_tools.clear();
    m_toolProblem.clear();
    try {
        if (storage::ToolStore* store = m_context.data().tools())
            m_tools = store->tools();
        else
            m_toolProblem = m_context.data().problem();
    } catch (const std::exception& e) {
        m_toolProblem = QString::fromStdString(e.what());
    }
    const QString previous = m_tool->currentData().toString();
    const QSignalBlocker block(m_tool);
    m_tool->clear();
    // A target that bores with a bar of its own offers that bar first.
    if (const std::optional<runtime::BoringTarget> target = currentTarget(); target && target->can.ownTool)
        m_tool->addItem(QString(), kPassTool);
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
    m_targets = runtime::boringTargets(m_devices, source ? source->deviceId : QString(), m_scenarioProblem.isEmpty());
    for (const runtime::BoringTarget& target : m_targets)
        m_output->addItem(target.name, target.key);
    const int at = m_output->findData(previous);
    m_output->setCurrentIndex(at >= 0 ? at : 0);
}

void BoringPanel::syncFaultSwitch() {
    const runtime::DeviceView* source = sourceDevice();
    const QSignalBlocker block(m_silent);
    m_silent->setChecked(source && source->faults && source->faults->silent);
}

std::optional<BoringPanel::SourceChoice> BoringPanel::currentSource() const {
    const QString key = m_source->currentData().toString();
    const QStringList parts = key.split(QLatin1Char(':'));
    if (parts.size() != 3) return std::nullopt;
    SourceChoice c;
    c.key = key;
    c.deviceId = parts[1];
    c.method = parts[2] == QStringLiteral("probe") ? core::BoringMethod::Probe : core::BoringMethod::Current;
    return c;
}

const runtime::DeviceView* BoringPanel::sourceDevice() const {
    const std::optional<SourceChoice> source = currentSource();
    return source && m_devices ? m_devices->view(source->deviceId) : nullptr;
}

std::optional<runtime::BoringTarget> BoringPanel::currentTarget() const {
    for (const runtime::BoringTarget& target : m_targets)
        if (target.key == m_output->currentData().toString()) return target;
    return std::nullopt;
}

bool BoringPanel::selectSource(const QString& key) {
    const int at = m_source->findData(key);
    if (at < 0) return false;
    m_source->setCurrentIndex(at);
    return true;
}

bool BoringPanel::selectOutput(const QString& key) {
    const int at = m_output->findData(key);
    if (at < 0) return false;
    m_output->setCurrentIndex(at);
    return true;
}

std::optional<core::ToolRecord> BoringPanel::currentTool() const {
    const QString key = m_tool->currentData().toString();
    if (key == kPassTool && m_scenarioProblem.isEmpty()) return m_scenario.tool;
    for (const core::ToolRecord& t : m_tools)
        if (QStringLiteral("tool:%1").arg(QString::fromStdString(t.id)) == key) return t;
    return std::nullopt;
}

core::BoringRunChoices BoringPanel::choicesFromForm(const SourceChoice& source, const core::ToolRecord& tool) const {
    core::BoringRunChoices c;
    c.method = source.method;
    c.plane = m_plane->currentData().toInt();
    c.stiffnessNPerMm = core::effectiveStiffnessNPerMm(tool);
    c.currentToForceNPerA = tool.currentToForceGainNPerA;
    c.limits.maxOffsetMm = m_maxOffset->value();
    c.limits.maxRateMmPerS = m_maxRate->value();
    c.plcCycleS = m_plcCycle->value() / 1000.0;
    // The estimator's thresholds of the preset (docs/boring-compensation.md), the engine's
    // defaults when it cannot be read.
    if (m_scenarioProblem.isEmpty()) c.estimator = m_scenario.estimator;
    return c;
}

bool BoringPanel::start() {
    if (m_running) return false;
    m_problem.clear();
    m_result.clear();
    const std::optional<SourceChoice> source = currentSource();
    if (!source) {
        showProblem(tr("Choose where the deflection comes from."));
        return false;
    }
    const std::optional<core::ToolRecord> tool = currentTool();
    if (!tool) {
        showProblem(m_tools.empty() ? tr("No tool: add the boring bar to the tool table on the Tools page.")
                                    : tr("Choose the tool."));
        return false;
    }
    const std::optional<runtime::BoringTarget> target = currentTarget();
    if (!target) {
        showProblem(
            tr("Cannot start: %1").arg(tr("No CNC output for the dynamic X offset: add one on the Devices page.")));
        return false;
    }
    if (!sourceDevice()) {
        showProblem(tr("Cannot start: %1").arg(tr("The chosen source device is gone.")));
        return false;
    }
    core::BoringRunChoices choices = choicesFromForm(*source, *tool);
    std::unique_ptr<core::BoringRun> run;
    m_runOutputKey = target->key;
    try {
        m_prepared = target->prepare({source->deviceId, source->method}, choices, m_scenario,
                                     m_heldOffsetMm.value(target->key, 0.0));
        run = core::buildBoringRun(choices, *m_prepared.station);
    } catch (const core::BoringRunRefused& e) {
        finishLink();
        showProblem(tr("Cannot start: %1").arg(describeRefusal(e)));
        return false;
    } catch (const std::invalid_argument& e) {
        finishLink();
        showProblem(tr("Cannot start: %1").arg(QString::fromStdString(e.what())));
        return false;
    }
    std::shared_ptr<core::BoringStation> station = m_prepared.station;
    run->setSegment(static_cast<core::SegmentKind>(m_segment->currentData().toInt()));
    m_runMethod = choices.method;
    m_trace.reset(run->offsetMm(), m_scenario.cut.boreLengthMm, m_scenario.cut.gaugeMarginMm);
    m_headline = tr("Starting");
    m_reason.clear();
    m_detail.clear();
    m_holding = false;
    m_running = true;
    saveSettings();
    m_session->start(std::move(station), std::move(run), speed());
    updateEnabled();
    showWords();
    refreshPlots();
    emit runningChanged(true);
    return true;
}

void BoringPanel::stop() {
    if (!m_running) return;
    m_session->stop();
    finishLink();
    m_running = false;
    m_headline = tr("Stopped");
    m_holding = false;
    updateEnabled();
    showWords();
    refreshPlots();
    emit runningChanged(false);
}

bool BoringPanel::zeroOffset() {
    if (m_running || !m_devices) return false;
    const std::optional<runtime::BoringTarget> target = currentTarget();
    if (!target || !target->can.holdsOffset) return false;
    const QString key = target->key;
    const double held = m_heldOffsetMm.value(key, 0.0);
    if (m_context.prompt &&
        m_context.prompt->ask(this, tr("Zero the offset"),
                              tr("The CNC holds a dynamic X offset of %1 mm. Set it to 0 now? The tool moves by %2 mm: "
                                 "do this only with the tool out of the bore.")
                                  .arg(mm(held), mm(-held))) != Prompt::Answer::Yes)
        return false;
    const core::OutputResult r = m_devices->writeOffset(key.mid(4), 0.0);
    if (!r.ok) {
        showProblem(tr("The CNC did not take the offset 0: %1").arg(QString::fromStdString(r.message)));
        return false;
    }
    m_heldOffsetMm[key] = 0.0;
    m_trace.setOffsetMm(0.0);
    m_problem.clear();
    updateEnabled();
    showWords();
    return true;
}

void BoringPanel::onCycles(const QVector<core::BoringRunCycle>& batch) {
    if (!m_running) return;
    for (const core::BoringRunCycle& cycle : batch) {
        bool holding = false;
        if (cycle.compensation) {
            const CycleWords words = describeCycle(*cycle.compensation, m_runMethod);
            m_headline = words.headline;
            m_reason = words.reason;
            m_detail = words.holding ? words.detail : QString();
            m_holding = holding = words.holding;
        }
        m_trace.record(cycle, holding);
    }
    if (m_sinceRefresh.elapsed() >= kRefreshMs) {
        m_sinceRefresh.restart();
        showWords();
        refreshPlots();
    }
}

void BoringPanel::finishPass() {
    const BoringRunStats& s = m_trace.stats();
    if (s.boreErrorMaxMm && s.uncompensatedMaxMm && *s.uncompensatedMaxMm > 0.0)
        m_result = tr("The bore is finished: largest diameter error %1 mm with compensation, %2 mm without (%3 %).")
                       .arg(mm(*s.boreErrorMaxMm), mm(*s.uncompensatedMaxMm))
                       .arg(QString::number(100.0 * (*s.boreErrorMaxMm / *s.uncompensatedMaxMm - 1.0), 'f', 0));
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

QString BoringPanel::detail() const {
    return m_detailLabel->text();
}

void BoringPanel::publishLoopState() {
    if (!m_context.state || (!m_running && !m_publishedRun)) return;  // the shaft run's state is left alone
    m_publishedRun = m_running;
    const QString detail = tr("boring bar: %1").arg(m_running ? m_headline : tr("Stopped"));
    m_context.state->setLoop(!m_running  ? AppState::Loop::Idle
                             : m_holding ? AppState::Loop::Paused
                                         : AppState::Loop::Running,
                             detail);
}

void BoringPanel::showWords() {
    publishLoopState();
    const bool run = m_running;
    const BoringRunStats& s = m_trace.stats();
    const QString tone = !run        ? QStringLiteral("#6b7785")
                         : m_holding ? QStringLiteral("#9a5b00")
                                     : QStringLiteral("#2e7d32");
    m_state->setText(!run ? tr("Stopped") : m_holding ? tr("Holding") : m_headline);
    m_state->setStyleSheet(QStringLiteral("font-size: 16pt; font-weight: bold; color: white; background: %1; "
                                          "border-radius: 6px; padding: 6px 14px;")
                               .arg(tone));
    m_offsetValue->setText(tr("Offset %1 mm").arg(mm(s.offsetMm)));
    m_deflectionValue->setText(s.deflectionMm ? tr("Deflection %1 mm").arg(mm(*s.deflectionMm)) : tr("Deflection —"));
    m_forceValue->setText(s.forceN ? tr("Force %1 N").arg(QString::number(*s.forceN, 'f', 0)) : tr("Force —"));
    QString reason;
    QString colour = QStringLiteral("#1f2a36");
    if (!m_problem.isEmpty()) {
        reason = m_problem;
        colour = QStringLiteral("#b71c1c");
    } else if (run && m_holding) {
        reason = m_headline + QStringLiteral(": ") + m_reason;
        colour = QStringLiteral("#9a5b00");
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
    m_detailLabel->setText(run && m_holding ? m_detail : QString());
    m_detailLabel->setVisible(!m_detailLabel->text().isEmpty());
    const std::optional<runtime::BoringTarget> target = currentTarget();
    const bool pass = target && target->can.knowsTruth;
    m_boreValue->setVisible(pass);
    m_boreChart->setVisible(pass);
    m_progress->setVisible(pass);
    if (pass) {
        const QString margin = QString::number(m_scenario.cut.gaugeMarginMm, 'f', 0);
        m_boreValue->setText(s.boreErrorMaxMm && s.uncompensatedMaxMm
                                 ? tr("Bore diameter error from %1 mm in: %2 mm with compensation, %3 mm without")
                                       .arg(margin, mm(*s.boreErrorMaxMm), mm(*s.uncompensatedMaxMm))
                                 : tr("Bore diameter error: shown from %1 mm into the bore").arg(margin));
        const double length = m_scenario.cut.boreLengthMm;
        m_progress->setValue(static_cast<int>(std::lround(1000.0 * std::clamp(s.zMm / length, 0.0, 1.0))));
        m_progress->setFormat(tr("Tool at %1 of %2 mm")
                                  .arg(QString::number(std::max(0.0, s.zMm), 'f', 1), QString::number(length, 'f', 0)));
    }
}

void BoringPanel::refreshPlots() {
    const std::vector<double>& time = m_trace.timeS();
    if (time.empty()) {
        m_chart->clear();
        m_boreChart->clear();
    } else {
        const double t0 = m_trace.startS();  // seconds since the run started
        std::vector<double> t(time.size());
        std::transform(time.begin(), time.end(), t.begin(), [t0](double v) { return v - t0; });
        m_chart->setSeries(QStringLiteral("measured"), tr("Measured"), t, m_trace.measuredMm(), kMeasured);
        m_chart->setSeries(QStringLiteral("offset"), tr("Offset applied"), t, m_trace.offsetMm(), kOffset,
                           plot::Chart::Style::Steps);
        if (m_trace.hasTruth())
            m_chart->setSeries(QStringLiteral("true"), tr("Real (simulator)"), t, m_trace.trueMm(), kTrue);
        else
            m_chart->removeSeries(QStringLiteral("true"));
        m_chart->rescale();
        m_chart->setXRange(std::max(0.0, t.back() - 30.0), std::max(t.back(), 5.0));
        const std::vector<double>& z = m_trace.boreZMm();
        if (!z.empty()) {
            m_boreChart->setSeries(QStringLiteral("without"), tr("Without compensation"), z, m_trace.boreTwinErrorMm(),
                                   kWithout);
            m_boreChart->setSeries(QStringLiteral("with"), tr("With compensation"), z, m_trace.boreErrorMm(), kWith);
            m_boreChart->rescale();
            m_boreChart->setXRange(0.0, std::max(z.back(), 10.0));
        }
    }
    m_chart->refresh();
    m_boreChart->refresh();
}

void BoringPanel::updateEnabled() {
    const bool run = m_running;
    const std::optional<SourceChoice> source = currentSource();
    const runtime::DeviceView* device = sourceDevice();
    const std::optional<runtime::BoringTarget> target = currentTarget();
    const runtime::BoringTargetCapabilities can = target ? target->can : runtime::BoringTargetCapabilities{};
    const bool probe = source && source->method == core::BoringMethod::Probe;
    for (QWidget* w : std::initializer_list<QWidget*>{m_source, m_tool, m_output, m_maxOffset, m_maxRate, m_plcCycle,
                                                      m_plane, m_speed})
        w->setEnabled(!run);
    m_start->setEnabled(!run && source.has_value());
    m_stop->setEnabled(run);
    const QString outputKey = m_output->currentData().toString();
    m_zero->setEnabled(!run && can.holdsOffset && std::abs(m_heldOffsetMm.value(outputKey, 0.0)) > 0.0);
    m_form->setRowVisible(m_plane, probe && can.choosesPlane);
    m_form->setRowVisible(m_segment, !probe);
    m_form->setRowVisible(m_speed, can.adjustableSpeed);
    m_form->setRowVisible(m_silent, device && device->faults);
    m_zero->setVisible(can.holdsOffset);
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
        const QStringList parts = m_source->itemData(i).toString().split(QLatin1Char(':'));
        const runtime::DeviceView* e = m_devices && parts.size() == 3 ? m_devices->view(parts[1]) : nullptr;
        const QString name = e ? e->name : parts.value(1);
        m_source->setItemText(i, parts.value(2) == QStringLiteral("probe") ? tr("%1: probe mandrel").arg(name)
                                                                           : tr("%1: current + dither").arg(name));
    }
    const int passTool = m_tool->findData(kPassTool);
    if (passTool >= 0)
        m_tool->setItemText(passTool, tr("Station: %1").arg(QString::fromStdString(m_scenario.tool.name)));
    if (const std::optional<SourceChoice> source = currentSource(); source && !m_running)
        m_targets = runtime::boringTargets(m_devices, source->deviceId,
                                           m_scenarioProblem.isEmpty());  // names in the new language
    for (int i = 0; i < m_output->count() && i < m_targets.size(); ++i)
        m_output->setItemText(i, m_targets[i].name);
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
    if (!m_running && m_headline.isEmpty()) m_headline = tr("Stopped");
    updateEnabled();
    showWords();
    refreshPlots();
}

}  // namespace tt::ui
