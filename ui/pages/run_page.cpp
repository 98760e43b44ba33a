#include "ui/pages/run_page.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QRandomGenerator>
#include <QSpinBox>
#include <QVBoxLayout>

#include "ui/app_state.h"
#include "ui/pages/planned_page.h"
#include "ui/plot/chart.h"
#include "ui/run/manual_entry_panel.h"
#include "ui/run/profile_panel.h"
#include "ui/run/run_session.h"

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

}  // namespace

RunPage::RunPage(AppContext& context, QWidget* parent)
    : Page(PageId::Run, context, parent),
      m_session(new RunSession(this)),
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
      m_partCounter(new QLabel(this)),
      m_profile(new ProfilePanel(this)),
      m_stateTitle(new QLabel(this)),
      m_state(new QLabel(this)),
      m_detail(new QLabel(this)),
      m_devices(new QLabel(this)),
      m_manualMode(new QCheckBox(this)),
      m_manual(new ManualEntryPanel(this)),
      m_skip(new QPushButton(this)),
      m_alarmsTitle(new QLabel(this)),
      m_alarms(new QListWidget(this)) {
    // Left: the profile, the diameters by hand (in manual mode), the history strip. Right: the loop,
    // the devices, the alarms.
    auto* left = new QVBoxLayout;
    left->addWidget(m_profile, 1);
    left->addWidget(m_manual);
    auto* body = new QHBoxLayout;
    body->addLayout(left, 5);
    body->addWidget(buildSide(), 3);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(16, 12, 16, 12);
    layout->addWidget(buildControls());
    layout->addLayout(body, 1);

    connect(m_start, &QPushButton::clicked, this, &RunPage::onStart);
    connect(m_pause, &QPushButton::clicked, this, &RunPage::onPauseContinue);
    connect(m_stop, &QPushButton::clicked, this, &RunPage::onStop);
    connect(m_speed, &QComboBox::activated, this,
            [this](int index) { m_session->setSpeed(kSpeeds[std::clamp(index, 0, 3)]); });
    connect(m_manualMode, &QCheckBox::toggled, this, [this](bool manual) {
        m_session->setManualEntry(manual);
        m_manual->setVisible(manual);
        m_skip->setVisible(manual);
    });
    connect(m_skip, &QPushButton::clicked, m_session, &RunSession::skipMeasurement);
    connect(m_manual, &ManualEntryPanel::diametersEntered, m_session, &RunSession::submitDiameters);
    connect(m_manual, &ManualEntryPanel::valueRefused, this, [this](const QString& text) { addAlarm(text, true); });
    connect(m_session, &RunSession::started, this, &RunPage::onStarted);
    connect(m_session, &RunSession::startFailed, this, &RunPage::onStartFailed);
    connect(m_session, &RunSession::snapshotChanged, this, &RunPage::onSnapshot);
    connect(m_session, &RunSession::loopEvent, this, &RunPage::onLoopEvent);
    connect(m_session, &RunSession::partProfile, m_profile, &ProfilePanel::onPartProfile);
    connect(m_session, &RunSession::notice, this, [this](const QString& text) { addAlarm(text, false); });

    m_manual->setVisible(false);
    m_skip->setVisible(false);
    retranslate();
    updateControls();
}

RunPage::~RunPage() = default;

QWidget* RunPage::buildControls() {
    auto* bar = new QWidget(this);
    auto* row = new QHBoxLayout(bar);
    row->setContentsMargins(0, 0, 0, 8);
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
    m_delay->setMinimumWidth(90);
    QFont counter = m_partCounter->font();
    counter.setPointSize(20);
    counter.setBold(true);
    m_partCounter->setFont(counter);
    row->addWidget(m_start);
    row->addWidget(m_pause);
    row->addWidget(m_stop);
    row->addSpacing(16);
    for (auto [label, field] : {std::pair<QLabel*, QWidget*>{m_presetLabel, m_preset},
                                {m_controllerLabel, m_controller},
                                {m_delayLabel, m_delay},
                                {m_speedLabel, m_speed}}) {
        auto* box = new QVBoxLayout;
        box->setSpacing(2);
        box->addWidget(label);
        box->addWidget(field);
        row->addLayout(box);
    }
    row->addStretch(1);
    return bar;
}

QWidget* RunPage::buildSide() {
    auto* side = new QWidget(this);
    auto* column = new QVBoxLayout(side);
    column->setContentsMargins(12, 0, 0, 0);
    m_stateTitle->setObjectName(QStringLiteral("SectionTitle"));
    m_state->setObjectName(QStringLiteral("loopStateText"));
    QFont big = m_state->font();
    big.setPointSize(20);
    big.setBold(true);
    m_state->setFont(big);
    m_detail->setObjectName(QStringLiteral("loopDetail"));
    m_detail->setWordWrap(true);
    m_devices->setObjectName(QStringLiteral("deviceText"));
    m_devices->setWordWrap(true);
    m_manualMode->setObjectName(QStringLiteral("manualEntryCheck"));
    m_skip->setObjectName(QStringLiteral("skipButton"));
    m_alarmsTitle->setObjectName(QStringLiteral("SectionTitle"));
    m_alarms->setObjectName(QStringLiteral("alarmList"));
    m_alarms->setWordWrap(true);
    m_alarms->setMinimumHeight(100);
    column->addWidget(m_stateTitle);
    column->addWidget(m_partCounter);
    column->addWidget(m_state);
    column->addWidget(m_detail);
    column->addWidget(m_devices);
    column->addSpacing(8);
    column->addWidget(m_manualMode);
    column->addWidget(m_skip);
    column->addWidget(m_profile->historyChart(), 3);
    column->addWidget(m_alarmsTitle);
    column->addWidget(m_alarms, 2);
    return side;
}

QString RunPage::title() const {
    return pageTitle(PageId::Run);
}

void RunPage::retranslate() {
    m_start->setText(tr("Start"));
    m_stop->setText(tr("Stop"));
    m_presetLabel->setText(tr("Set-up"));
    m_controllerLabel->setText(tr("Controller"));
    m_delayLabel->setText(tr("Delay z, parts"));
    m_speedLabel->setText(tr("Speed"));
    m_controller->setItemText(0, tr("LQG"));
    m_controller->setItemText(1, tr("EWMA"));
    m_controller->setItemText(2, tr("Open loop"));
    m_speed->setItemText(0, tr("×1 (6 min a part)"));
    m_speed->setItemText(1, tr("×60 (6 s a part)"));
    m_speed->setItemText(2, tr("×360 (1 s a part)"));
    m_speed->setItemText(3, tr("×3600 (fastest)"));
    m_stateTitle->setText(tr("Loop"));
    m_manualMode->setText(tr("Enter diameters by hand"));
    m_skip->setText(tr("Part not measured"));
    m_alarmsTitle->setText(tr("Alarms"));
    m_profile->retranslate();
    m_manual->retranslate();
    updateTexts();
}

RunSettings RunPage::settings() const {
    RunSettings s;
    s.preset = m_preset->currentData().toString();
    s.controller = m_controller->currentData().toString();
    s.delay = m_delay->value();
    s.speed = kSpeeds[std::clamp(m_speed->currentIndex(), 0, 3)];
    s.manualEntry = m_manualMode->isChecked();
    s.databasePath = const_cast<RunPage*>(this)->context().databasePath;
    s.seed = QRandomGenerator::global()->generate64() >> 12;
    return s;
}

void RunPage::onStart() {
    m_session->start(settings());
    m_start->setEnabled(false);
}

void RunPage::onPauseContinue() {
    if (m_snapshot.state == core::LoopState::Paused)
        m_session->continueRun();
    else
        m_session->pause();
}

void RunPage::onStop() {
    m_session->stop();
}

void RunPage::onStarted(const RunLayout& layout) {
    m_layout = layout;
    m_haveRun = true;
    m_profile->setRun(layout);
    m_manual->setPoints(layout.pointZMm, layout.nominalDiameterMm, layout.plausibleRangeMm);
    addAlarm(tr("Run started: %1, %2, z = %3").arg(layout.preset, layout.controller.toUpper()).arg(layout.delay),
             false);
}

void RunPage::onStartFailed(const QString& reason) {
    addAlarm(reason, true);
    updateControls();
}

void RunPage::onSnapshot(const LoopSnapshot& snapshot) {
    m_snapshot = snapshot;
    m_manual->setAwaitingPart(snapshot.manualEntry ? snapshot.awaitingPart : std::nullopt);
    if (context().state) context().state->setLoop(toAppLoop(snapshot.state), QString(snapshot.detail));
    updateControls();
    updateTexts();
}

void RunPage::onLoopEvent(const core::LoopEvent& event) {
    m_profile->onLoopEvent(event);
    if (event.kind == core::LoopEvent::Kind::Alarm)
        addAlarm(QString::fromStdString(event.message), event.alarmKind != "correction-limited");
}

void RunPage::addAlarm(const QString& text, bool severe) {
    auto* item = new QListWidgetItem(
        QStringLiteral("%1  %2").arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")), text));
    if (severe) item->setForeground(QColor(198, 40, 40));
    m_alarms->insertItem(0, item);
    while (m_alarms->count() > kMaxAlarms)
        delete m_alarms->takeItem(m_alarms->count() - 1);
}

void RunPage::updateControls() {
    const core::LoopState s = m_snapshot.state;
    const bool idle = s == core::LoopState::Idle;
    m_start->setEnabled(idle);
    m_pause->setEnabled(s == core::LoopState::Running || s == core::LoopState::Paused);
    m_stop->setEnabled(!idle);
    for (QWidget* w : std::initializer_list<QWidget*>{m_preset, m_controller, m_delay})
        w->setEnabled(idle);
    m_pause->setText(s == core::LoopState::Paused ? tr("Continue") : tr("Pause"));
}

QString RunPage::stateText() const {
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

QString RunPage::deviceText() const {
    auto word = [](const core::DeviceHealth& h) {
        switch (h.state) {
            case core::DeviceState::Ready:
                return tr("ready");
            case core::DeviceState::Connecting:
                return tr("connecting");
            case core::DeviceState::Disconnected:
                return tr("not answering");
            case core::DeviceState::Error:
                return tr("error");
        }
        return QString();
    };
    if (!m_haveRun) return tr("Devices: the built-in lathe simulator, not started");
    return tr("Gauge: %1 (%2) · CNC: %3")
        .arg(word(m_snapshot.gauge), QString::fromStdString(m_snapshot.gauge.message), word(m_snapshot.cnc));
}

void RunPage::updateTexts() {
    m_state->setText(stateText());
    m_state->setStyleSheet(m_snapshot.state == core::LoopState::Fault     ? QStringLiteral("color: #c62828;")
                           : m_snapshot.state == core::LoopState::Paused  ? QStringLiteral("color: #b26a00;")
                           : m_snapshot.state == core::LoopState::Running ? QStringLiteral("color: #2e7d32;")
                                                                          : QString());
    m_detail->setText(m_haveRun ? QString(m_snapshot.detail)
                                : tr("Press Start: parts of 325 mm shafts are turned on the simulated lathe, measured "
                                     "at the control points and the next part is corrected."));
    m_devices->setText(deviceText());
    m_partCounter->setText(m_haveRun ? tr("Parts done: %1").arg(m_snapshot.partsFinished) : QString());
}

}  // namespace tt::ui
