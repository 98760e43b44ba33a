#include "ui/run/shaft_run_panel.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QRandomGenerator>
#include <QSettings>
#include <QSpinBox>
#include <QTime>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "config/controller_tuning_json.h"
#include "plot/chart.h"
#include "runtime/devices/device_hub.h"
#include "runtime/run/run_session.h"
#include "ui/app_state.h"
#include "ui/auth/audit_trail.h"
#include "ui/controller/controller_tuning.h"
#include "ui/prompt.h"
#include "ui/run/lathe_panel.h"
#include "ui/run/manual_entry_panel.h"
#include "ui/run/notice_text.h"
#include "ui/run/plant_link_text.h"
#include "ui/run/profile_panel.h"
#include "ui/run/verdict_counter.h"

namespace tt::ui {

namespace {

const QStringList kPresets = {QStringLiteral("paper-2012-group1"), QStringLiteral("paper-2012-group2"),
                              QStringLiteral("paper-2012-group3"), QStringLiteral("paper-2012")};
const QStringList kControllers = {QStringLiteral("lqg"), QStringLiteral("ewma"), QStringLiteral("open")};
const double kSpeeds[] = {1.0, 60.0, 360.0, 3600.0};
constexpr int kDefaultSpeed = 2;
constexpr int kMaxAlarms = 200;

AppState::Loop toAppLoop(core::LoopState s) {
    switch (s) {
        case core::LoopState::Running:
            return AppState::Loop::Running;
        case core::LoopState::Paused:
            return AppState::Loop::Paused;
        case core::LoopState::Fault:
            return AppState::Loop::Fault;
        case core::LoopState::Idle:
            break;
    }
    return AppState::Loop::Idle;
}

QString healthWord(core::DeviceState state) {
    switch (state) {
        case core::DeviceState::Ready:
            return ShaftRunPanel::tr("ready");
        case core::DeviceState::Connecting:
            return ShaftRunPanel::tr("connecting");
        case core::DeviceState::Disconnected:
            return ShaftRunPanel::tr("not answering");
        case core::DeviceState::Error:
            return ShaftRunPanel::tr("error");
    }
    return {};
}

QString healthText(const core::DeviceHealth& h) {
    return h.message.empty() ? healthWord(h.state)
                             : QStringLiteral("%1 (%2)").arg(healthWord(h.state), QString::fromStdString(h.message));
}

void setChoice(QComboBox* combo, const QString& data) {
    const int index = combo->findData(data);
    if (index >= 0) combo->setCurrentIndex(index);
}

/// The speed choice nearest to `speed` machine s per wall s.
int speedIndex(double speed) {
    int best = kDefaultSpeed;
    for (int i = 0; i < 4; ++i)
        if (speed > 0.0 && std::abs(std::log(kSpeeds[i] / speed)) < std::abs(std::log(kSpeeds[best] / speed))) best = i;
    return best;
}

}  // namespace

ShaftRunPanel::ShaftRunPanel(AppContext& context, QWidget* parent)
    : QWidget(parent),
      m_context(context),
      m_session(new runtime::RunSession(this)),
      m_catalog(context.devices),
      m_start(new QPushButton(this)),
      m_pause(new QPushButton(this)),
      m_stop(new QPushButton(this)),
      m_presetLabel(new QLabel(this)),
      m_preset(new QComboBox(this)),
      m_controllerLabel(new QLabel(this)),
      m_controller(new QComboBox(this)),
      m_delayLabel(new QLabel(this)),
      m_delay(new QSpinBox(this)),
      m_speedLabel(new QLabel(this)),
      m_speed(new QComboBox(this)),
      m_machineLabel(new QLabel(this)),
      m_machine(new QComboBox(this)),
      m_outputLabel(new QLabel(this)),
      m_output(new QComboBox(this)),
      m_gaugeLabel(new QLabel(this)),
      m_gauge(new QComboBox(this)),
      m_partCounter(new QLabel(this)),
      m_verdicts(new VerdictCounter(this)),
      m_pauseOnScrap(new QCheckBox(this)),
      m_profile(new ProfilePanel(this)),
      m_lathePanel(new LathePanel(this)),
      m_state(new QLabel(this)),
      m_detail(new QLabel(this)),
      m_devices(new QLabel(this)),
      m_manualMode(new QCheckBox(this)),
      m_manual(new ManualEntryPanel(this)),
      m_skip(new QPushButton(this)),
      m_alarmsTitle(new QLabel(this)),
      m_alarms(new QListWidget(this)) {
    auto* body = new QHBoxLayout;
    body->addWidget(buildLeft(), 4);
    body->addWidget(buildSide(), 3);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(8, 8, 8, 4);
    layout->addWidget(buildControls());
    layout->addWidget(buildSetupRow());
    layout->addLayout(body, 1);
    connectControls();
    connectSession();
    connectDevices();
    m_manual->setVisible(false);
    m_skip->setVisible(false);
    fillDeviceChoices();
    restoreChoices();
    retranslate();
    updateControls();
}

ShaftRunPanel::~ShaftRunPanel() {
    releaseMachine(tr("the Run page was closed"));
}

QWidget* ShaftRunPanel::buildLeft() {
    // Left: the profile, the operator's part cycle, the diameters by hand (in manual mode). Right: the loop,
    // the devices, the history strip, the alarms.
    auto* left = new QWidget(this);
    auto* column = new QVBoxLayout(left);
    column->setContentsMargins(0, 0, 0, 0);
    column->addWidget(m_profile, 1);
    column->addWidget(buildDevicePicker());
    column->addWidget(m_lathePanel);
    // The run's options under the profile: "by hand" just above the entry fields it shows (the set-up row and
    // the side column fit 1280 x 800).
    auto* options = new QHBoxLayout;
    options->addWidget(m_manualMode);
    options->addSpacing(16);
    options->addWidget(m_pauseOnScrap);
    options->addStretch(1);
    column->addLayout(options);
    column->addWidget(m_devices);  // the machine and its devices in words, under the profile
    m_plantLink = new QLabel(left);
    m_plantLink->setObjectName(QStringLiteral("plantLink"));
    m_plantLink->setWordWrap(true);
    m_plantLink->hide();
    column->addWidget(m_plantLink);
    m_controllerInUse = new QLabel(left);
    m_controllerInUse->setObjectName(QStringLiteral("controllerInUse"));
    m_controllerInUse->setWordWrap(true);
    m_controllerInUse->hide();
    column->addWidget(m_controllerInUse);
    column->addWidget(m_manual);
    return left;
}

void ShaftRunPanel::connectControls() {
    connect(m_start, &QPushButton::clicked, this, &ShaftRunPanel::onStart);
    connect(m_pause, &QPushButton::clicked, this, &ShaftRunPanel::onPauseContinue);
    connect(m_stop, &QPushButton::clicked, this, &ShaftRunPanel::onStop);
    connect(m_speed, &QComboBox::activated, this,
            [this](int index) { m_session->setSpeed(kSpeeds[std::clamp(index, 0, 3)]); });
    connect(m_manualMode, &QCheckBox::toggled, this, [this](bool manual) {
        m_session->setManualEntry(manual);
        m_manual->setVisible(manual);
        m_skip->setVisible(manual);
        updateLathePanel();
    });
    connect(m_machine, &QComboBox::currentIndexChanged, this, [this] {
        updateControls();
        updateTexts();
    });
    connect(m_output, &QComboBox::currentIndexChanged, this, [this] { updateTexts(); });
    connect(m_gauge, &QComboBox::currentIndexChanged, this, [this] {
        // Diameters "typed in by hand" is the gauge choice without a device.
        const std::optional<runtime::MachineOffer> offer = chosenOffer();
        if (offer && offer->can.usesDevices && m_gauge->currentIndex() >= 0)
            m_manualMode->setChecked(m_gauge->currentData().toString().isEmpty());
        updateTexts();
    });
    connect(m_verdicts, &VerdictCounter::outOfTolerance, this, &ShaftRunPanel::onOutOfTolerance);
    connect(m_manual, &ManualEntryPanel::valueRefused, this, [this](const QString& text) { addAlarm(text, true); });
    connect(m_lathePanel, &LathePanel::partFinished, this, &ShaftRunPanel::onPartFinished);
    connect(m_lathePanel, &LathePanel::readingRequested, this, [this] {
        if (m_context.devices && !m_running.gauge.isEmpty()) m_context.devices->requestReading(m_running.gauge);
    });
}

void ShaftRunPanel::connectSession() {
    connect(m_skip, &QPushButton::clicked, m_session, &runtime::RunSession::skipMeasurement);
    connect(m_manual, &ManualEntryPanel::diametersEntered, m_session, &runtime::RunSession::submitDiameters);
    connect(m_session, &runtime::RunSession::started, this, &ShaftRunPanel::onStarted);
    connect(m_session, &runtime::RunSession::startFailed, this, &ShaftRunPanel::onStartFailed);
    connect(m_session, &runtime::RunSession::snapshotChanged, this, &ShaftRunPanel::onSnapshot);
    connect(m_session, &runtime::RunSession::loopEvent, this, &ShaftRunPanel::onLoopEvent);
    connect(m_session, &runtime::RunSession::partProfile, m_profile, &ProfilePanel::onPartProfile);
    connect(m_session, &runtime::RunSession::notice, this, [this](const QString& text) { addAlarm(text, false); });
    connect(m_session, &runtime::RunSession::tuningTaken, this,
            [this](qint64 part) { addAlarm(tr("The new controller tuning took over at part %1.").arg(part), false); });
    connect(m_session, &runtime::RunSession::plantStatus, this, &ShaftRunPanel::onPlantStatus);
    connect(m_session, &runtime::RunSession::machineIncident, this,
            [this](const QString& text) { addAlarm(text, true); });
    if (ControllerTuning* tuning = m_context.tuning)
        connect(tuning, &ControllerTuning::applied, m_session, &runtime::RunSession::applyTuning);
}

void ShaftRunPanel::connectDevices() {
    runtime::DeviceHub* hub = m_context.devices;
    if (!hub) return;
    connect(hub, &runtime::DeviceHub::devicesChanged, this, [this] {
        fillDeviceChoices();
        fillMachineChoices();  // a configured device may offer a machine (a LinuxCNC device: the LinuxCNC lathe)
        updateTexts();
    });
    connect(hub, &runtime::DeviceHub::deviceChanged, this, [this](const QString& id) {
        for (QComboBox* combo : {m_output, m_gauge})
            if (const int index = combo->findData(id); index >= 0) combo->setItemText(index, deviceChoiceText(id));
        updateTexts();
    });
}

QWidget* ShaftRunPanel::buildControls() {
    auto* bar = new QWidget(this);
    auto* row = new QHBoxLayout(bar);
    row->setContentsMargins(0, 0, 0, 4);
    m_start->setObjectName(QStringLiteral("startButton"));
    m_pause->setObjectName(QStringLiteral("pauseButton"));
    m_stop->setObjectName(QStringLiteral("stopButton"));
    m_start->setProperty("role", QStringLiteral("primary"));
    m_stop->setProperty("role", QStringLiteral("danger"));
    for (QPushButton* b : {m_start, m_pause, m_stop}) {
        b->setMinimumHeight(60);
        b->setMinimumWidth(110);
        QFont f = b->font();
        f.setPointSize(16);
        b->setFont(f);
    }
    m_preset->setObjectName(QStringLiteral("presetCombo"));
    m_controller->setObjectName(QStringLiteral("controllerCombo"));
    m_delay->setObjectName(QStringLiteral("delaySpin"));
    m_speed->setObjectName(QStringLiteral("speedCombo"));
    m_partCounter->setObjectName(QStringLiteral("partCounter"));
    for (const QString& p : kPresets)
        m_preset->addItem(p, p);
    for (int i = 0; i < kControllers.size(); ++i)
        m_controller->addItem(QString(), kControllers[i]);
    for (int i = 0; i < 4; ++i)
        m_speed->addItem(QString());
    m_speed->setCurrentIndex(kDefaultSpeed);
    m_delay->setRange(1, 8);
    m_delay->setValue(2);
    m_delay->setMinimumWidth(96);  // the digit beside the wide arrows of the style
    QFont counter = m_partCounter->font();
    counter.setPointSize(16);
    counter.setBold(true);
    m_partCounter->setFont(counter);
    row->addWidget(m_start);
    row->addWidget(m_pause);
    row->addWidget(m_stop);
    row->addSpacing(12);
    m_machine->setObjectName(QStringLiteral("machineCombo"));
    fillMachineChoices();
    // The label above its field: the row of the big buttons fits 1280 px in every language.
    for (auto [label, field] : {std::pair<QLabel*, QWidget*>{m_machineLabel, m_machine}, {m_presetLabel, m_preset}}) {
        auto* box = new QVBoxLayout;
        box->setSpacing(0);
        box->addWidget(label);
        box->addWidget(field);
        row->addSpacing(8);
        row->addLayout(box);
    }
    row->addStretch(1);
    return bar;
}

QWidget* ShaftRunPanel::buildSetupRow() {
    auto* bar = new QWidget(this);
    auto* row = new QHBoxLayout(bar);
    row->setContentsMargins(0, 0, 0, 4);
    bool first = true;
    for (auto [label, field] : {std::pair<QLabel*, QWidget*>{m_controllerLabel, m_controller},
                                {m_delayLabel, m_delay},
                                {m_speedLabel, m_speed}}) {
        if (!first) row->addSpacing(8);
        first = false;
        row->addWidget(label);
        row->addWidget(field);
    }
    row->addStretch(1);
    return bar;
}

QWidget* ShaftRunPanel::buildDevicePicker() {
    m_devicePicker = new QWidget(this);
    m_devicePicker->setObjectName(QStringLiteral("devicePicker"));
    auto* row = new QHBoxLayout(m_devicePicker);
    row->setContentsMargins(0, 4, 0, 0);
    m_output->setObjectName(QStringLiteral("cncOutputCombo"));
    m_gauge->setObjectName(QStringLiteral("gaugeCombo"));
    for (auto [label, combo] : {std::pair<QLabel*, QComboBox*>{m_outputLabel, m_output}, {m_gaugeLabel, m_gauge}}) {
        combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        combo->setMinimumContentsLength(14);
        auto* box = new QVBoxLayout;
        box->setSpacing(2);
        box->addWidget(label);
        box->addWidget(combo);
        row->addLayout(box, 1);
    }
    return m_devicePicker;
}

QWidget* ShaftRunPanel::buildSide() {
    auto* side = new QWidget(this);
    auto* column = new QVBoxLayout(side);
    column->setContentsMargins(12, 0, 0, 0);
    m_state->setObjectName(QStringLiteral("loopStateText"));
    QFont big = m_state->font();
    big.setPointSize(18);
    big.setBold(true);
    m_state->setFont(big);
    m_state->setWordWrap(true);
    m_detail->setObjectName(QStringLiteral("loopDetail"));
    m_detail->setWordWrap(true);
    m_devices->setObjectName(QStringLiteral("deviceText"));
    m_devices->setWordWrap(true);
    m_manualMode->setObjectName(QStringLiteral("manualEntryCheck"));
    m_manualMode->setStyleSheet(
        QStringLiteral("QCheckBox { min-height: 40px; } QCheckBox::indicator { width: 26px; height: 26px; }"));
    m_skip->setObjectName(QStringLiteral("skipButton"));
    m_alarmsTitle->setObjectName(QStringLiteral("SectionTitle"));
    m_alarms->setObjectName(QStringLiteral("alarmList"));
    m_alarms->setWordWrap(true);
    m_alarms->setMinimumHeight(70);
    auto* stateRow = new QHBoxLayout;
    stateRow->addWidget(m_state, 1);
    stateRow->addWidget(m_partCounter, 0, Qt::AlignRight | Qt::AlignTop);
    column->addLayout(stateRow);
    m_pauseOnScrap->setObjectName(QStringLiteral("pauseOnScrapCheck"));
    m_pauseOnScrap->setStyleSheet(m_manualMode->styleSheet());
    column->addWidget(m_verdicts);
    column->addWidget(m_detail);
    column->addWidget(m_skip);
    column->addWidget(m_profile->historyChart(), 3);
    column->addWidget(m_alarmsTitle);
    column->addWidget(m_alarms, 2);
    return side;
}

void ShaftRunPanel::retranslate() {
    m_start->setText(tr("Start"));
    m_stop->setText(tr("Stop"));
    m_presetLabel->setText(tr("Set-up"));
    m_controllerLabel->setText(tr("Controller"));
    m_delayLabel->setText(tr("Delay z, parts"));
    m_pauseOnScrap->setText(tr("Pause on scrap"));
    m_speedLabel->setText(tr("Speed"));
    m_controller->setItemText(0, tr("LQG"));
    m_controller->setItemText(1, tr("EWMA"));
    m_controller->setItemText(2, tr("Open loop"));
    m_speed->setItemText(0, tr("×1 (6 min a part)"));
    m_speed->setItemText(1, tr("×60 (6 s a part)"));
    m_speed->setItemText(2, tr("×360 (1 s a part)"));
    m_speed->setItemText(3, tr("×3600 (fastest)"));
    m_machineLabel->setText(tr("Machine"));
    fillMachineChoices();
    m_outputLabel->setText(tr("CNC output"));
    m_gaugeLabel->setText(tr("Diameters from"));
    if (const int byHand = m_gauge->findData(QString()); byHand >= 0)
        m_gauge->setItemText(byHand, tr("Typed in by hand"));
    m_manualMode->setText(tr("Diameters by hand"));
    m_skip->setText(tr("Part not measured"));
    m_pause->setText(m_snapshot.state == core::LoopState::Paused ? tr("Continue") : tr("Pause"));
    m_alarmsTitle->setText(tr("Alarms"));
    m_profile->retranslate();
    m_manual->retranslate();
    m_lathePanel->retranslate();
    updateTexts();
}

// ---- the machines and devices to choose from ----------------------------------------------------------------

QString ShaftRunPanel::deviceChoiceText(const QString& id) const {
    const runtime::DeviceView* v = m_context.devices ? m_context.devices->view(id) : nullptr;
    if (!v) return id;
    return tr("%1 — %2").arg(v->name, healthWord(v->health.state));
}

void ShaftRunPanel::fillDeviceChoices() {
    const QString output = m_output->currentData().toString();
    const QString gauge = m_gauge->count() > 0 ? m_gauge->currentData().toString() : QStringLiteral("?");
    const QSignalBlocker blockOutput(m_output);
    const QSignalBlocker blockGauge(m_gauge);
    m_output->clear();
    m_gauge->clear();
    if (const runtime::DeviceHub* hub = m_context.devices) {
        for (const QString& id : hub->devicesOfKind(devices::DeviceKind::CorrectionOutput))
            m_output->addItem(deviceChoiceText(id), id);
        for (const QString& id : hub->devicesOfKind(devices::DeviceKind::Gauge))
            m_gauge->addItem(deviceChoiceText(id), id);
    }
    m_gauge->addItem(tr("Typed in by hand"), QString());
    setChoice(m_output, output);
    setChoice(m_gauge, gauge);
}

void ShaftRunPanel::restoreChoices() {
    const QSettings settings;
    setChoice(m_machine, runtime::currentMachineKey(settings.value(QStringLiteral("run/machine")).toString()));
    setChoice(m_output, settings.value(QStringLiteral("run/cncOutput")).toString());
    if (settings.contains(QStringLiteral("run/gauge")))
        setChoice(m_gauge, settings.value(QStringLiteral("run/gauge")).toString());
}

void ShaftRunPanel::saveChoices() const {
    QSettings settings;
    settings.setValue(QStringLiteral("run/machine"), m_machine->currentData().toString());
    const std::optional<runtime::MachineOffer> offer = chosenOffer();
    if (offer && offer->can.usesDevices) {
        settings.setValue(QStringLiteral("run/cncOutput"), m_output->currentData().toString());
        settings.setValue(QStringLiteral("run/gauge"), m_gauge->currentData().toString());
    }
}

std::optional<runtime::MachineOffer> ShaftRunPanel::chosenOffer() const {
    for (const runtime::MachineOffer& offer : m_offers)
        if (offer.key == m_machine->currentData().toString()) return offer;
    return std::nullopt;
}

std::optional<runtime::MachineOffer> ShaftRunPanel::shownOffer() const {
    return m_snapshot.state == core::LoopState::Idle ? chosenOffer() : m_onMachine;
}

void ShaftRunPanel::fillMachineChoices() {
    const QString chosen = m_machine->currentData().toString();
    const QSignalBlocker block(m_machine);
    m_offers = m_catalog.offers();
    m_machine->clear();
    for (const runtime::MachineOffer& offer : m_offers)
        m_machine->addItem(offer.name, offer.key);
    setChoice(m_machine, chosen);
}

// ---- commands -----------------------------------------------------------------------------------------

runtime::RunRequest ShaftRunPanel::request() const {
    runtime::RunRequest r;
    r.machine = m_machine->currentData().toString();
    r.preset = m_preset->currentData().toString();
    r.controller = core::controllerKindFromName(m_controller->currentData().toString().toStdString());
    r.delay = m_delay->value();
    r.speed = kSpeeds[std::clamp(m_speed->currentIndex(), 0, 3)];
    r.manualEntry = m_manualMode->isChecked();
    r.pauseOnScrap = m_pauseOnScrap->isChecked();
    r.database = m_context.databasePath;
    r.seed = QRandomGenerator::global()->generate64() >> 12;
    if (m_context.tuning && m_context.tuning->current())
        r.tuning = config::controllerTuningToJson(*m_context.tuning->current());
    const std::optional<runtime::MachineOffer> offer = chosenOffer();
    if (offer && !offer->cnc.isEmpty()) {
        r.cnc = offer->cnc;  // the machine's parts are cut by that CNC, at its own pace
        r.cncMode = offer->cncMode;
        r.speed = 0.0;
    }
    if (offer && offer->can.usesDevices) {
        r.cncOutput = m_output->currentData().toString();
        r.gauge = m_gauge->currentData().toString();
        if (r.gauge.isEmpty()) r.manualEntry = true;
    }
    return r;
}

bool ShaftRunPanel::mayRunMachine() {
    try {
        AuditTrail(m_context).require(core::auth::Permission::RunMachine);
        return true;
    } catch (const core::auth::PermissionDenied& refused) {
        refuseStart(QString::fromStdString(refused.what()));
        return false;
    }
}

void ShaftRunPanel::showRequest(const runtime::RunRequest& request) {
    setChoice(m_machine, request.machine);
    setChoice(m_preset, request.preset);
    setChoice(m_controller, QString::fromStdString(core::controllerKindName(request.controller)));
    if (request.delay) m_delay->setValue(*request.delay);
    m_speed->setCurrentIndex(speedIndex(request.speed));
    setChoice(m_output, request.cncOutput);
    setChoice(m_gauge, request.gauge);
    const QSignalBlocker block(m_manualMode);
    m_manualMode->setChecked(request.manualEntry);
    m_manual->setVisible(request.manualEntry);
    m_skip->setVisible(request.manualEntry);
    m_pauseOnScrap->setChecked(request.pauseOnScrap);
}

bool ShaftRunPanel::launch(const runtime::RunRequest& request, std::optional<qint64> resumeRunId) {
    if (!mayRunMachine()) return false;
    if (m_snapshot.state != core::LoopState::Idle) {
        refuseStart(tr("A run is already going; stop it first."));
        return false;
    }
    m_offers = m_catalog.offers();
    std::optional<runtime::MachineOffer> offer;
    for (const runtime::MachineOffer& o : m_offers)
        if (o.key == request.machine) offer = o;
    if (!offer) {
        refuseStart(tr("The machine “%1” is not offered; choose another.").arg(request.machine));
        return false;
    }
    const runtime::DeviceView* output =
        m_context.devices && !request.cncOutput.isEmpty() ? m_context.devices->view(request.cncOutput) : nullptr;
    runtime::RunStart start{request, offer->name, output ? output->name : QString(), offer->can, {}};
    try {
        start.make = offer->prepare(request);
    } catch (const std::invalid_argument& e) {
        refuseStart(QString::fromStdString(e.what()));
        return false;
    }
    m_onMachine = offer;
    m_running = request;
    if (resumeRunId)
        m_session->resume(start, *resumeRunId);
    else
        m_session->start(start);
    m_start->setEnabled(false);
    return true;
}

bool ShaftRunPanel::startRequest(const runtime::RunRequest& request) {
    showRequest(request);
    return launch(request, std::nullopt);
}

bool ShaftRunPanel::resumeRun(const runtime::InterruptedRun& run) {
    runtime::RunRequest request = run.request;
    request.database = m_context.databasePath;
    request.speed = kSpeeds[std::clamp(m_speed->currentIndex(), 0, 3)];
    showRequest(request);
    if (!launch(request, run.point.run.runId)) return false;
    addAlarm(tr("Continuing run %1 from part %2.").arg(run.point.run.runId).arg(run.nextPart()), false);
    return true;
}

void ShaftRunPanel::onStart() {
    const runtime::RunRequest r = request();
    if (const std::optional<runtime::MachineOffer> offer = chosenOffer()) {
        if (const QString problem = offer->startProblem(r); !problem.isEmpty()) {
            refuseStart(problem);
            return;
        }
    }
    if (launch(r, std::nullopt)) saveChoices();
}

void ShaftRunPanel::refuseStart(const QString& reason) {
    addAlarm(tr("Not started: %1").arg(reason), true);
    if (m_context.prompt) m_context.prompt->warn(this, tr("The run cannot start"), reason);
}

void ShaftRunPanel::onPauseContinue() {
    if (m_snapshot.state == core::LoopState::Paused)
        m_session->continueRun();
    else
        m_session->pause();
}

void ShaftRunPanel::onStop() {
    m_session->stop();
}

void ShaftRunPanel::onPartFinished() {
    m_session->confirmPartFinished();
}

void ShaftRunPanel::releaseMachine(const QString& reason) {
    if (m_onMachine) m_onMachine->release(reason);
}

// ---- what the loop reports -------------------------------------------------------------------------------

void ShaftRunPanel::onStarted(const runtime::RunLayout& layout) {
    m_layout = layout;
    m_haveRun = true;
    m_profile->setRun(layout);
    m_verdicts->reset();
    m_controllerInUse->hide();
    m_manual->setPoints(layout.pointZMm, layout.nominalDiameterMm, layout.plausibleRangeMm);
    addAlarm(tr("Run started: %1, %2, z = %3, %4")
                 .arg(layout.preset, m_controller->itemText(m_controller->findData(layout.controller)))
                 .arg(layout.delay)
                 .arg(layout.machineName),
             false);
    updateControls();
}

void ShaftRunPanel::onStartFailed(const QString& reason) {
    releaseMachine(tr("the run did not start"));
    addAlarm(reason, true);
    updateControls();
}

void ShaftRunPanel::onSnapshot(const runtime::LoopSnapshot& snapshot) {
    const bool ended = snapshot.state == core::LoopState::Idle && m_snapshot.state != core::LoopState::Idle;
    m_snapshot = snapshot;
    if (ended) releaseMachine(tr("the run is over"));
    m_manual->setAwaitingPart(snapshot.manualEntry ? snapshot.awaitingPart : std::nullopt);
    if (m_context.state) m_context.state->setLoop(toAppLoop(snapshot.state), noticeText(snapshot.status));
    if (m_context.tuning)
        m_context.tuning->setLoopTakesTuning(snapshot.state == core::LoopState::Running ||
                                             snapshot.state == core::LoopState::Paused);
    updateControls();
    updateTexts();
}

void ShaftRunPanel::onLoopEvent(const core::LoopEvent& event) {
    m_profile->onLoopEvent(event);
    m_verdicts->onLoopEvent(event);
    if (event.kind == core::LoopEvent::Kind::Alarm) {
        addAlarm(alarmText(event.notice), event.alarmKind != "correction-limited");
        showControllerInUse(event.notice);
    }
    if (event.kind == core::LoopEvent::Kind::PartStarted) updateLathePanel();
}

void ShaftRunPanel::onOutOfTolerance() {
    if (!QSettings().value(kSoundOnOutOfTolerance, false).toBool()) return;
    QApplication::beep();  // the terminal's bell (docs/DECISIONS.md: why no generated tone)
    emit alertSounded();
}

void ShaftRunPanel::addAlarm(const QString& text, bool severe) {
    auto* item = new QListWidgetItem(
        QStringLiteral("%1  %2").arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")), text));
    if (severe) item->setForeground(QColor(198, 40, 40));
    m_alarms->insertItem(0, item);
    while (m_alarms->count() > kMaxAlarms)
        delete m_alarms->takeItem(m_alarms->count() - 1);
}

// ---- what the page shows ---------------------------------------------------------------------------------

void ShaftRunPanel::updateControls() {
    const core::LoopState s = m_snapshot.state;
    const bool idle = s == core::LoopState::Idle;
    m_start->setEnabled(idle);
    m_pause->setEnabled(s == core::LoopState::Running || s == core::LoopState::Paused);
    m_stop->setEnabled(!idle);
    for (QWidget* w :
         std::initializer_list<QWidget*>{m_preset, m_controller, m_delay, m_machine, m_output, m_gauge, m_pauseOnScrap})
        w->setEnabled(idle);
    m_pause->setText(s == core::LoopState::Paused ? tr("Continue") : tr("Pause"));
    // While a run goes, the page shows its machine; otherwise the one chosen.
    const std::optional<runtime::MachineOffer> offer = shownOffer();
    const runtime::MachineCapabilities can = offer ? offer->can : runtime::MachineCapabilities{};
    // Devices are chosen while idle; during a run the operator's part cycle takes their place.
    m_devicePicker->setVisible(can.usesDevices && idle);
    m_lathePanel->setVisible(can.partsConfirmedByOperator && !idle);
    const bool adjustable = idle ? can.adjustableSpeed : m_layout.adjustableSpeed;
    m_speedLabel->setVisible(adjustable);
    m_speed->setVisible(adjustable);
    updateLathePanel();
}

void ShaftRunPanel::updateLathePanel() {
    LathePanel::View v;
    const bool cycleRun = m_haveRun && m_layout.partsConfirmedByOperator;
    v.runGoing =
        cycleRun && (m_snapshot.state == core::LoopState::Running || m_snapshot.state == core::LoopState::Paused);
    if (cycleRun) {
        const runtime::DeviceHub* hub = m_context.devices;
        const runtime::DeviceView* output = hub ? hub->view(m_running.cncOutput) : nullptr;
        const runtime::DeviceView* gauge = hub && !m_running.gauge.isEmpty() ? hub->view(m_running.gauge) : nullptr;
        v.partOnMachine = m_snapshot.partOnMachine;
        v.cncValue = output ? output->liveValue : QString();
        v.awaitingPart = m_snapshot.awaitingPart;
        v.nextPoint = m_snapshot.nextPoint;
        v.pointCount = static_cast<int>(m_layout.pointZMm.size());
        v.nextPointXMm = m_layout.pointZMm.value(m_snapshot.nextPoint);
        v.byHand = m_snapshot.manualEntry;
        v.haveGauge = !m_running.gauge.isEmpty();
        v.gaugeValue = gauge ? gauge->liveValue : QString();
        v.gaugeReady = m_snapshot.gauge.ready();
    }
    m_lathePanel->setView(v);
}

QString ShaftRunPanel::stateText() const {
    switch (m_snapshot.state) {
        case core::LoopState::Idle:
            return m_haveRun ? tr("Stopped") : tr("Ready to start");
        case core::LoopState::Running:
            return tr("Running");
        case core::LoopState::Paused:
            return tr("Paused — the CNC keeps the last correction");
        case core::LoopState::Fault:
            return tr("Fault — the CNC keeps the last correction");
    }
    return {};
}

QString ShaftRunPanel::devicesIdleText() const {
    auto line = [](const QString& what, const QString& name, const core::DeviceHealth& h) {
        return tr("%1: “%2” — %3").arg(what, name, h.ready() ? healthWord(h.state) : healthText(h));
    };
    const runtime::DeviceHub* hub = m_context.devices;
    const runtime::DeviceView* output = hub ? hub->view(m_output->currentData().toString()) : nullptr;
    const QString gaugeId = m_gauge->currentData().toString();
    const runtime::DeviceView* gauge = hub && !gaugeId.isEmpty() ? hub->view(gaugeId) : nullptr;
    const QString cnc = output ? line(tr("CNC"), output->name, output->health)
                               : tr("CNC: none (add a correction output on the Devices page)");
    const QString diameters = gauge ? line(tr("Gauge"), gauge->name, gauge->health) : tr("Diameters: typed in by hand");
    return QStringLiteral("%1\n%2").arg(cnc, diameters);
}

QString ShaftRunPanel::deviceText() const {
    const bool idle = m_snapshot.state == core::LoopState::Idle;
    const std::optional<runtime::MachineOffer> offer = shownOffer();
    if (!offer || !offer->can.usesDevices) {
        if (!m_haveRun || idle)
            return tr("Machine: %1 (its own CNC, gauge and part cycle)").arg(m_machine->currentText());
        const QString gauge = m_snapshot.manualEntry ? tr("Diameters: typed in by hand")
                                                     : tr("Gauge: %1").arg(healthText(m_snapshot.gauge));
        return tr("%1 · CNC: %2").arg(gauge, healthWord(m_snapshot.cnc.state));
    }
    // Devices from the Devices page: which, and their state in a word (with the reason when not ready). While
    // idle the reason of a device that is not ready is shown; during a run the loop's own words and the alarms
    // say what it means for the run.
    if (idle) return devicesIdleText();
    auto line = [](const QString& what, const QString& name, const core::DeviceHealth& h) {
        return tr("%1: “%2” — %3").arg(what, name, healthWord(h.state));
    };
    const runtime::DeviceHub* hub = m_context.devices;
    const runtime::DeviceView* output = hub ? hub->view(m_running.cncOutput) : nullptr;
    const runtime::DeviceView* gauge = hub && !m_running.gauge.isEmpty() ? hub->view(m_running.gauge) : nullptr;
    const QString diameters = m_snapshot.manualEntry || !gauge ? tr("Diameters: typed in by hand")
                                                               : line(tr("Gauge"), gauge->name, m_snapshot.gauge);
    return QStringLiteral("%1\n%2").arg(line(tr("CNC"), output ? output->name : QString(), m_snapshot.cnc), diameters);
}

void ShaftRunPanel::showControllerInUse(const core::Notice& notice) {
    const QString text = controllerInUseText(notice);
    if (text.isEmpty()) return;
    m_controllerInUse->setText(text);
    m_controllerInUse->setStyleSheet(controllerInUseIsFallback(notice)
                                         ? QStringLiteral("color: #9a5b00; font-weight: bold;")
                                         : QStringLiteral("font-weight: bold;"));
    m_controllerInUse->show();
}

void ShaftRunPanel::onPlantStatus(const storage::ForwarderStatus& status) {
    const QString text = plantLinkText(status);
    const bool warns = plantLinkWarns(status);
    m_plantLink->setText(text);
    m_plantLink->setStyleSheet(warns ? QStringLiteral("color: #9a5b00; font-weight: bold;") : QString());
    m_plantLink->setToolTip(status.reason);
    m_plantLink->show();
    if (m_context.state) m_context.state->setPlantLink(text, warns);
}

void ShaftRunPanel::updateTexts() {
    m_state->setText(stateText());
    m_state->setStyleSheet(m_snapshot.state == core::LoopState::Fault     ? QStringLiteral("color: #c62828;")
                           : m_snapshot.state == core::LoopState::Paused  ? QStringLiteral("color: #9a5b00;")
                           : m_snapshot.state == core::LoopState::Running ? QStringLiteral("color: #2e7d32;")
                                                                          : QString());
    const std::optional<runtime::MachineOffer> offer = chosenOffer();
    const QString idleText = offer ? tr("Press Start: %1").arg(offer->description) : tr("Choose a machine.");
    m_detail->setText(m_haveRun ? noticeText(m_snapshot.status) : idleText);
    m_devices->setText(deviceText());
    m_partCounter->setText(m_haveRun ? tr("Parts done: %1").arg(m_snapshot.partsFinished) : QString());
    updateLathePanel();
}

}  // namespace tt::ui
