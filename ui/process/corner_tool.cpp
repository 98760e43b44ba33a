#include "ui/process/corner_tool.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>
#include <cmath>

#include "config/corner_config.h"
#include "plot/chart.h"
#include "ui/process/corner_job.h"
#include "ui/process/corner_move_editor.h"
#include "ui/process/corner_plots.h"

namespace tt::ui {

namespace {

constexpr int kSampleCorners = 12;
constexpr unsigned long long kRunSeed = 3;  ///< the run's moves: neither training (1) nor the samples (2)

QString number(double v, int decimals) {
    return QLocale().toString(v, 'f', decimals);
}

/// Whether the controller's model is the nominal drives (no factor off 1 by more than 0.1 %).
bool nominalFactors(const core::FeedDrivesFactors& f) {
    for (const core::DriveFactors& a : {f.x, f.z})
        for (double v : {a.friction, a.inertia, a.velocityGain})
            if (std::abs(v - 1.0) > 1e-3) return false;
    return true;
}

/// The corner preset `name`; one that cannot be read gives the engine's defaults and says why in `problem`.
core::CornerScenario readScenario(const QString& name, QString& problem) {
    try {
        return config::loadCornerScenario(name);
    } catch (const std::exception& e) {
        problem = QString::fromStdString(e.what());
        return {};
    }
}

QLabel* wrapped(QWidget* parent) {
    auto* label = new QLabel(parent);
    label->setWordWrap(true);
    label->setStyleSheet(QStringLiteral("color: #38434f; font-size: 12pt;"));
    return label;
}

}  // namespace

CornerTool::CornerTool(AppContext& context, QWidget* parent)
    : ProcessTool(parent),
      m_curve(std::make_shared<LiveCurve>()),
      m_job(new CornerJob(this)),
      m_machineLabel(new QLabel(this)),
      m_machine(new QComboBox(this)),
      m_editor(new CornerMoveEditor(this)),
      m_simulate(new QPushButton(this)),
      m_summary(new QLabel(this)),
      m_status(wrapped(this)),
      m_statusText(m_status),
      m_progress(new QProgressBar(this)),
      m_cancel(new QPushButton(this)),
      m_views(new QTabWidget(this)),
      m_zoom(new QCheckBox(this)),
      m_pathChart(new plot::Chart(this)),
      m_errorChart(new plot::Chart(this)),
      m_pulseChart(new plot::Chart(this)),
      m_trainingMovesLabel(new QLabel(this)),
      m_trainingMoves(new QSpinBox(this)),
      m_train(new QPushButton(this)),
      m_networkText(wrapped(this)),
      m_trainingChart(new plot::Chart(this)),
      m_driftLabel(new QLabel(this)),
      m_driftKind(new QComboBox(this)),
      m_driftAxisLabel(new QLabel(this)),
      m_driftAxis(new QComboBox(this)),
      m_driftFactor(new QDoubleSpinBox(this)),
      m_cornersLabel(new QLabel(this)),
      m_corners(new QSpinBox(this)),
      m_run(new QPushButton(this)),
      m_retrain(new QPushButton(this)),
      m_driftText(wrapped(this)),
      m_driftChart(new plot::Chart(this)) {
    (void)context;  // the tool needs no device and no history: it works on the simulator
    m_scenario = readScenario(config::kDefaultCornerPreset, m_scenarioProblem);
    buildLayout();
    m_editor->setPulse(m_scenario.pulse);
    m_editor->setSamples(
        core::drawCornerMoves(m_scenario.xSpeeds, m_scenario.zSpeeds, kSampleCorners, m_scenario.training.seed + 1));
    connect(m_machine, &QComboBox::activated, this,
            [this](int index) { setMachine(m_machine->itemData(index).toString()); });
    connect(m_simulate, &QPushButton::clicked, this, &CornerTool::simulate);
    connect(m_editor, &CornerMoveEditor::changed, this, &CornerTool::simulate);
    connect(m_zoom, &QCheckBox::toggled, this, [this] {
        if (m_shownWithout && m_shownWith)
            corner_plots::showPaths(*m_pathChart, *m_shownWithout, *m_shownWith, m_zoom->isChecked());
    });
    connect(m_train, &QPushButton::clicked, this, &CornerTool::train);
    connect(m_run, &QPushButton::clicked, this, &CornerTool::runCorners);
    connect(m_retrain, &QPushButton::clicked, this, &CornerTool::retrainNow);
    connect(m_cancel, &QPushButton::clicked, this, &CornerTool::cancel);
    connect(m_job, &CornerJob::progress, this, &CornerTool::showProgress);
    connect(m_job, &CornerJob::finished, this, &CornerTool::finishJob);
    retranslate();
    simulate();
}

CornerTool::~CornerTool() = default;

bool CornerTool::setMachine(const QString& name) {
    const int index = m_machine->findData(name);
    std::optional<core::CornerScenario> scenario;
    if (!busy() && index >= 0) {
        try {
            scenario = config::loadCornerScenario(name);
        } catch (const std::exception& e) {
            m_summary->setText(tr("The corner preset cannot be read: %1").arg(QString::fromStdString(e.what())));
        }
    }
    if (!scenario) {  // the machine of before stays
        m_machine->setCurrentIndex(m_machine->findData(QString::fromStdString(m_scenario.name)));
        return false;
    }
    m_scenario = std::move(*scenario);
    m_scenarioProblem.clear();
    m_machine->setCurrentIndex(index);
    m_net.reset();
    m_lastRun.reset();
    m_statusText.clear();
    m_trainingChart->clear();
    m_driftChart->clear();
    m_trainingMoves->setValue(m_scenario.training.moves);
    m_editor->setPulse(m_scenario.pulse);
    m_editor->setSamples(
        core::drawCornerMoves(m_scenario.xSpeeds, m_scenario.zSpeeds, kSampleCorners, m_scenario.training.seed + 1));
    retranslate();
    return true;
}

QString CornerTool::title() const {
    return tr("Corner pulse");
}

QWidget* CornerTool::buildCornerView() {
    auto* view = new QWidget(this);
    m_zoom->setObjectName(QStringLiteral("cornerZoom"));
    m_zoom->setChecked(true);
    m_pathChart->setObjectName(QStringLiteral("cornerPathChart"));
    m_errorChart->setObjectName(QStringLiteral("cornerErrorChart"));
    m_pulseChart->setObjectName(QStringLiteral("cornerPulseChart"));
    m_pulseChart->setMinimumHeight(160);
    auto* right = new QVBoxLayout;
    right->addWidget(m_errorChart, 3);
    right->addWidget(m_pulseChart, 2);
    auto* left = new QVBoxLayout;
    left->addWidget(m_pathChart, 1);
    left->addWidget(m_zoom);
    auto* layout = new QHBoxLayout(view);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(left, 1);
    layout->addLayout(right, 1);
    return view;
}

QWidget* CornerTool::buildNetworkView() {
    auto* view = new QWidget(this);
    m_trainingMoves->setObjectName(QStringLiteral("cornerTrainingMoves"));
    m_trainingMoves->setRange(20, 2000);
    m_trainingMoves->setSingleStep(20);
    m_trainingMoves->setValue(m_scenario.training.moves);
    m_train->setObjectName(QStringLiteral("cornerTrain"));
    m_train->setProperty("role", QStringLiteral("primary"));
    m_networkText->setObjectName(QStringLiteral("cornerNetworkText"));
    m_trainingChart->setObjectName(QStringLiteral("cornerTrainingChart"));
    auto* row = new QHBoxLayout;
    row->addWidget(m_trainingMovesLabel);
    row->addWidget(m_trainingMoves);
    row->addWidget(m_train);
    row->addStretch(1);
    auto* layout = new QVBoxLayout(view);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(row);
    layout->addWidget(m_networkText);
    layout->addWidget(m_trainingChart, 1);
    return view;
}

QWidget* CornerTool::buildDriftView() {
    auto* view = new QWidget(this);
    m_driftKind->setObjectName(QStringLiteral("cornerDriftKind"));
    for (core::DriveDriftKind kind :
         {core::DriveDriftKind::Friction, core::DriveDriftKind::Gain, core::DriveDriftKind::Inertia})
        m_driftKind->addItem(QString(), QString::fromLatin1(core::toString(kind)));
    m_driftAxis->setObjectName(QStringLiteral("cornerDriftAxis"));
    m_driftAxis->addItem(QStringLiteral("X"), QStringLiteral("x"));
    m_driftAxis->addItem(QStringLiteral("Z"), QStringLiteral("z"));
    m_driftAxis->setCurrentIndex(1);
    m_driftFactor->setObjectName(QStringLiteral("cornerDriftFactor"));
    m_driftFactor->setRange(core::kMinDriveDriftFactor, core::kMaxDriveDriftFactor);
    m_driftFactor->setDecimals(2);
    m_driftFactor->setSingleStep(0.05);
    m_driftFactor->setValue(1.3);
    m_driftFactor->setPrefix(QStringLiteral("× "));
    m_corners->setObjectName(QStringLiteral("cornerRunCorners"));
    m_corners->setRange(20, 400);
    m_corners->setSingleStep(10);
    m_corners->setValue(60);
    m_run->setObjectName(QStringLiteral("cornerRun"));
    m_run->setProperty("role", QStringLiteral("primary"));
    m_retrain->setObjectName(QStringLiteral("cornerRetrain"));
    m_driftText->setObjectName(QStringLiteral("cornerDriftText"));
    m_driftChart->setObjectName(QStringLiteral("cornerDriftChart"));
    auto* row = new QGridLayout;
    row->addWidget(m_driftLabel, 0, 0);
    row->addWidget(m_driftKind, 0, 1);
    row->addWidget(m_driftFactor, 0, 2);
    row->addWidget(m_run, 0, 4);
    row->addWidget(m_driftAxisLabel, 1, 0);
    row->addWidget(m_driftAxis, 1, 1);
    row->addWidget(m_retrain, 1, 4);
    row->addWidget(m_cornersLabel, 2, 0);
    row->addWidget(m_corners, 2, 1);
    row->setColumnStretch(3, 1);
    auto* layout = new QVBoxLayout(view);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(row);
    layout->addWidget(m_driftText);
    layout->addWidget(m_driftChart, 1);
    return view;
}

void CornerTool::buildLayout() {
    m_simulate->setObjectName(QStringLiteral("cornerSimulate"));
    m_summary->setObjectName(QStringLiteral("cornerSummary"));
    m_summary->setWordWrap(true);
    m_summary->setStyleSheet(QStringLiteral("font-size: 13pt; font-weight: bold; color: #1f2a36;"));
    m_status->setObjectName(QStringLiteral("cornerStatus"));
    m_cancel->setObjectName(QStringLiteral("cornerCancel"));
    m_cancel->setProperty("role", QStringLiteral("danger"));
    m_progress->setObjectName(QStringLiteral("cornerProgress"));
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(14);
    auto* jobRow = new QHBoxLayout;
    jobRow->addWidget(m_progress, 1);
    jobRow->addWidget(m_cancel);
    m_machine->setObjectName(QStringLiteral("cornerMachine"));
    m_machine->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_machine->addItem(QString(), config::kDefaultCornerPreset);
    m_machine->addItem(QString(), config::kSoftDrivesCornerPreset);
    auto* machineBox = new QWidget(this);
    auto* machineRow = new QHBoxLayout(machineBox);
    machineRow->setContentsMargins(8, 0, 4, 0);
    machineRow->addWidget(m_machineLabel);
    machineRow->addWidget(m_machine);
    auto* left = new QVBoxLayout;
    left->setSpacing(4);
    left->addWidget(m_editor);
    left->addWidget(m_simulate);
    left->addWidget(m_summary);
    left->addStretch(1);
    left->addWidget(m_status);
    left->addLayout(jobRow);
    auto* leftBox = new QWidget(this);
    leftBox->setLayout(left);
    leftBox->setFixedWidth(330);
    left->setContentsMargins(0, 0, 0, 0);
    m_views->setObjectName(QStringLiteral("cornerViews"));
    m_views->addTab(buildCornerView(), QString());
    m_views->addTab(buildNetworkView(), QString());
    m_views->addTab(buildDriftView(), QString());
    m_views->setCornerWidget(machineBox, Qt::TopRightCorner);
    machineBox->setMinimumHeight(machineBox->sizeHint().height());  // the tab bar grows to the whole box
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(leftBox);
    layout->addWidget(m_views, 1);
}

void CornerTool::retranslate() {
    m_editor->retranslate();
    m_machineLabel->setText(tr("Machine"));
    m_machine->setItemText(0, tr("Paper's drives"));
    m_machine->setItemText(1, tr("Soft drives"));
    m_machine->setToolTip(
        tr("Paper's drives: the 1V340F30 lathe of paper 002 (Kv 16.7 1/s), where drifts of the "
           "inertia hardly move the best pulse. Soft drives: the same lathe with half the position "
           "loop gain (Kv 8.35 1/s) and a slow cross slide (50 ms), where they do."));
    m_simulate->setText(tr("Simulate"));
    m_cancel->setText(tr("Cancel"));
    m_views->setTabText(0, tr("Paths"));
    m_views->setTabText(1, tr("Network"));
    m_views->setTabText(2, tr("Drift monitor"));
    m_zoom->setText(tr("Zoom on the corner"));
    m_trainingMovesLabel->setText(tr("Training moves"));
    m_train->setText(tr("Train network"));
    m_driftLabel->setText(tr("Drift"));
    m_driftKind->setItemText(0, tr("Friction"));
    m_driftKind->setItemText(1, tr("Velocity gain"));
    m_driftKind->setItemText(2, tr("Inertia"));
    m_driftAxisLabel->setText(tr("Drive"));
    m_cornersLabel->setText(tr("Corners"));
    m_run->setText(tr("Run corners"));
    m_retrain->setText(tr("Retrain now"));
    if (!m_job->running()) {
        if (!m_statusText.isSet()) m_statusText.set([] { return tr("Nothing running."); });
        m_statusText.retranslate();
        showTrainingChart();  // while training, the live curve is drawn at each epoch
    }
    showDriftChart();
    showNetworkText();
    showDriftText();
    simulate();
    updateEnabled();
}

bool CornerTool::netFitsPulse(const core::PulseSettings& p) const {
    return m_net && m_net->pulse.axis == p.axis && m_net->pulse.durationS == p.durationS &&
           m_net->pulse.leadS == p.leadS && m_net->pulse.limitV == p.limitV;
}

void CornerTool::simulate() {
    if (!m_scenarioProblem.isEmpty()) {
        m_summary->setText(tr("The corner preset cannot be read: %1").arg(m_scenarioProblem));
        return;
    }
    const core::CornerMove move = m_editor->move();
    const core::PulseSettings pulse = m_editor->pulse(m_scenario.pulse);
    const bool network = netFitsPulse(pulse);
    // The corner on the drives as the controller knows them: identified after a drift, else nominal.
    const bool identified = m_net && !nominalFactors(m_net->model);
    const core::FeedDrivesConfig drives =
        identified ? core::scaledDrives(m_scenario.drives, m_net->model) : m_scenario.drives;
    // The best pulse takes about 30 simulated corners (some 10 ms); the network's one.
    const double amplitude =
        network ? core::pulseAmplitudeV(m_net->net, pulse, move)
                : core::findBestPulse(drives, m_scenario.cost, move, pulse, m_scenario.training.search).amplitudeV;
    core::CornerSimulationOptions options;
    options.keepTrace = true;
    options.traceEvery = 5;
    m_shownWithout = core::simulateCorner(drives, m_scenario.cost, move, pulse, 0.0, options);
    m_shownWith = core::simulateCorner(drives, m_scenario.cost, move, pulse, amplitude, options);
    corner_plots::showPaths(*m_pathChart, *m_shownWithout, *m_shownWith, m_zoom->isChecked());
    corner_plots::showErrors(*m_errorChart, *m_shownWithout, *m_shownWith);
    corner_plots::showPulse(*m_pulseChart, *m_shownWith, pulse.axis);
    const double without = m_shownWithout->cost.meanErrorMm * 1e3;
    const double with = m_shownWith->cost.meanErrorMm * 1e3;
    const QString errors =
        tr("Error %1 → %2 µm, −%3 %")
            .arg(number(without, 1), number(with, 1), number(without > 0.0 ? 100.0 * (1.0 - with / without) : 0.0, 0));
    const QString source = network ? tr("Network's pulse %1 V").arg(number(amplitude, 3))
                                   : tr("Best pulse %1 V; no network for this pulse yet").arg(number(amplitude, 3));
    m_summary->setText(
        errors + QLatin1Char('\n') + source +
        (identified ? QLatin1Char('\n') + tr("On the drives as identified after the drift.") : QString()));
}

bool CornerTool::train() {
    if (busy() || !m_scenarioProblem.isEmpty()) return false;
    core::CornerScenario scenario = m_scenario;
    scenario.pulse = m_editor->pulse(m_scenario.pulse);
    const int moves = m_trainingMoves->value();
    {
        const std::lock_guard<std::mutex> lock(m_curve->mutex);
        m_curve->training.clear();
        m_curve->validation.clear();
    }
    auto result = std::make_shared<std::optional<core::CornerNetTraining>>();
    const std::shared_ptr<LiveCurve> curve = m_curve;
    m_apply = [this, result, scenario] {
        const core::AxisPulseSummary best = core::summarisePulses(scenario.pulse.axis, (*result)->examples);
        m_net = CornerNetState{
            (*result)->net, scenario.pulse, core::toNetSamples((*result)->examples), {}, best.reductionPct};
        m_statusText.set([] { return tr("Network trained."); });
        showTrainingChart();
        showNetworkText();
        simulate();
    };
    if (!m_job->start([scenario, moves, result, curve](const core::CornerProgress& progress) {
            const std::vector<core::CornerMove> drawn =
                core::drawCornerMoves(scenario.xSpeeds, scenario.zSpeeds, moves, scenario.training.seed);
            std::vector<core::CornerExample> examples = core::findPulseTargets(
                scenario.drives, scenario.cost, scenario.pulse, scenario.training.search, drawn, progress);
            const std::vector<core::NetSample> samples = core::toNetSamples(examples);
            curve->outputScaleV = core::normalisationFor(samples).outputScale;
            const core::NetTrainingSettings& settings = scenario.training.network;
            core::CorrectiveNet net = core::trainCorrectiveNet(samples, settings, [&](int epoch, double tl, double vl) {
                {
                    const std::lock_guard<std::mutex> lock(curve->mutex);
                    curve->training.push_back(tl);
                    curve->validation.push_back(vl);
                }
                return progress("network", epoch, settings.maxEpochs);
            });
            *result = core::CornerNetTraining{std::move(net), std::move(examples)};
        }))
        return false;
    updateEnabled();
    return true;
}

bool CornerTool::runCorners() {
    if (busy() || !m_net) return false;
    core::CornerScenario scenario = m_scenario;
    scenario.pulse = m_net->pulse;
    const CornerNetState state = *m_net;
    const int corners = m_corners->value();
    core::CornerDrift drift;
    drift.kind = core::driveDriftKindFromString(m_driftKind->currentData().toString().toStdString());
    drift.axis = core::feedAxisFromString(m_driftAxis->currentData().toString().toStdString().c_str());
    drift.factor = m_driftFactor->value();
    auto result = std::make_shared<std::optional<core::CornerWorkResult>>();
    auto net = std::make_shared<core::CorrectiveNet>(state.net);
    m_apply = [this, result, net] {
        m_lastRun = std::move(*result);
        m_net->net = *net;
        m_net->model = m_lastRun->model;
        m_net->samples = m_lastRun->samples;
        m_statusText.set([] { return tr("Run finished."); });
        showDriftChart();
        showTrainingChart();  // a retraining replaced the curve with its own
        showDriftText();
        showNetworkText();
        simulate();
    };
    if (!m_job->start([scenario, state, corners, drift, result, net](const core::CornerProgress& progress) {
            const std::vector<core::CornerMove> moves =
                core::drawCornerMoves(scenario.xSpeeds, scenario.zSpeeds, corners, kRunSeed);
            *result = core::runCornerWork(scenario, *net, state.samples, moves, drift, true, progress);
        }))
        return false;
    updateEnabled();
    return true;
}

bool CornerTool::retrainNow() {
    if (busy() || !m_net || !m_lastRun || m_lastRun->recent.empty()) return false;
    core::CornerScenario scenario = m_scenario;
    scenario.pulse = m_net->pulse;
    auto state = std::make_shared<CornerNetState>(*m_net);
    auto event = std::make_shared<core::CornerRetrainEvent>();
    const std::vector<core::RecordedCorner> corners = m_lastRun->recent;
    const int move = static_cast<int>(m_lastRun->moves.size()) - 1;
    m_apply = [this, state, event] {
        m_net = *state;
        m_statusText.set([this, event] {
            return event->verdict.accepted
                       ? tr("Retrained on demand on %n corner(s); identified %1.", nullptr, event->corners)
                             .arg(factorsText(event->identified.factors))
                       : tr("Retraining on demand refused: %1. The network in use is kept.")
                             .arg(QString::fromStdString(event->verdict.failure));
        });
        showTrainingChart();
        showNetworkText();
        simulate();
    };
    if (!m_job->start([scenario, state, event, corners, move](const core::CornerProgress& progress) {
            *event = core::retrainOnCorners(scenario, state->model, state->net, state->samples, corners, move,
                                            "retraining asked for", progress);
        }))
        return false;
    updateEnabled();
    return true;
}

void CornerTool::cancel() {
    m_job->cancel();
}

bool CornerTool::busy() const {
    return m_job->running();
}

void CornerTool::showProgress(const QString& stage, int done, int total) {
    m_progress->setRange(0, std::max(1, total));
    m_progress->setValue(done);
    if (stage == QLatin1String("targets"))
        m_status->setText(tr("Finding the best pulse of training move %1 of %2").arg(done).arg(total));
    else if (stage == QLatin1String("network"))
        m_status->setText(tr("Training the network: epoch %1 of at most %2").arg(done).arg(total));
    else if (stage == QLatin1String("work"))
        m_status->setText(tr("Running corner %1 of %2").arg(done).arg(total));
    else if (stage == QLatin1String("identification"))
        m_status->setText(tr("Identifying the drives from the recorded corners"));
    else if (stage == QLatin1String("retargeting"))
        m_status->setText(tr("Finding the best pulse of move %1 of %2 on the identified drives").arg(done).arg(total));
    else
        m_status->setText(tr("Retraining the network: epoch %1 of at most %2").arg(done).arg(total));
    if (stage == QLatin1String("network")) {
        const std::lock_guard<std::mutex> lock(m_curve->mutex);
        corner_plots::showTraining(*m_trainingChart, m_curve->training, m_curve->validation, m_curve->outputScaleV);
    }
}

void CornerTool::finishJob(bool cancelled, const QString& error) {
    if (cancelled)
        m_statusText.set([] { return tr("Cancelled: the network of before is kept."); });
    else if (!error.isEmpty())
        m_statusText.set([error] { return tr("Failed: %1").arg(error); });
    else if (m_apply)
        m_apply();
    m_apply = nullptr;
    m_statusText.retranslate();
    m_progress->setRange(0, 1);
    m_progress->setValue(cancelled || !error.isEmpty() ? 0 : 1);
    updateEnabled();
    emit jobFinished();
}

void CornerTool::updateEnabled() {
    const bool idle = !busy();
    const bool ok = m_scenarioProblem.isEmpty();
    m_simulate->setEnabled(ok);
    m_train->setEnabled(idle && ok);
    m_trainingMoves->setEnabled(idle);
    m_machine->setEnabled(idle);
    m_run->setEnabled(idle && m_net.has_value());
    m_retrain->setEnabled(idle && m_net && m_lastRun && !m_lastRun->recent.empty());
    m_driftKind->setEnabled(idle);
    m_driftAxis->setEnabled(idle);
    m_driftFactor->setEnabled(idle);
    m_corners->setEnabled(idle);
    m_cancel->setEnabled(!idle);
}

void CornerTool::showTrainingChart() {
    if (!m_net) return;
    const core::NetTrainingRecord& r = m_net->net.record();
    corner_plots::showTraining(*m_trainingChart, r.trainingLoss, r.validationLoss,
                               m_net->net.normalisation().outputScale);
}

void CornerTool::showDriftChart() {
    if (!m_lastRun) return;
    corner_plots::showDrift(*m_driftChart, *m_lastRun, m_scenario.retraining.monitor.thresholdFraction,
                            m_scenario.retraining.monitor.windowCorners);
}

void CornerTool::showNetworkText() {
    if (!m_net) {
        m_networkText->setText(
            tr("No network yet. Training finds the best pulse of each training move on the "
               "simulator (a bracketed search of U = k1·e_max + k2·e_mean), then the 4-10-1 "
               "network learns it from the four motor speeds."));
        return;
    }
    const core::NetTrainingRecord& r = m_net->net.record();
    QString text = tr("Network 4-%1-1 for a %2 ms pulse on %3: %4 epochs (best %5), RMS amplitude error %6 mV on "
                      "the training moves, %7 mV on the validation moves. The best pulses cut the training moves' "
                      "error by %8 %.")
                       .arg(m_net->net.weights().hiddenCount())
                       .arg(number(m_net->pulse.durationS * 1e3, 0),
                            m_net->pulse.axis == core::FeedAxis::X ? QStringLiteral("X") : QStringLiteral("Z"))
                       .arg(r.epochs)
                       .arg(r.bestEpoch)
                       .arg(number(r.trainingRmsV * 1e3, 1), number(r.validationRmsV * 1e3, 1),
                            number(m_net->bestReductionPct, 0));
    if (r.retrainings > 0) text += QLatin1Char(' ') + tr("Retrained %n time(s) since.", nullptr, r.retrainings);
    m_networkText->setText(text);
}

QString CornerTool::factorsText(const core::FeedDrivesFactors& f) const {
    return tr("X: friction × %1, inertia × %2, gain × %3; Z: friction × %4, inertia × %5, gain × %6")
        .arg(number(f.x.friction, 2), number(f.x.inertia, 2), number(f.x.velocityGain, 2), number(f.z.friction, 2),
             number(f.z.inertia, 2), number(f.z.velocityGain, 2));
}

QString CornerTool::retrainText(const core::CornerRetrainEvent& e) const {
    const double difference = 100.0 * m_lastRun->checks[static_cast<std::size_t>(e.move)].differenceFraction;
    const QString found = tr("Measured cost %1 % off the prediction after corner %2; identified %3.")
                              .arg(number(difference, 1))
                              .arg(e.move + 1)
                              .arg(factorsText(e.identified.factors));
    if (e.verdict.accepted)
        return found + QLatin1Char(' ') +
               tr("Retrained: validation cost %1 → %2 µm.")
                   .arg(number(e.verdict.keptCostMm * 1e3, 1), number(e.verdict.candidateCostMm * 1e3, 1));
    return found + QLatin1Char(' ') +
           tr("The retrained network was refused (%1); the network in use is kept.")
               .arg(QString::fromStdString(e.verdict.failure));
}

void CornerTool::showDriftText() {
    const core::DriftMonitorSettings& monitor = m_scenario.retraining.monitor;
    if (!m_lastRun) {
        m_driftText->setText(tr("Runs corners with the network's pulse on the simulated machine; from the middle "
                                "corner on, the chosen property of the chosen drive is multiplied by the factor. "
                                "After each corner the monitor compares the measured cost with the predicted one "
                                "over the last %1 corners (misses removed) and retrains above %2 %; a retrained "
                                "network is taken only when it does better on held-out moves.")
                                 .arg(monitor.windowCorners)
                                 .arg(number(100.0 * monitor.thresholdFraction, 1)));
        return;
    }
    const core::CornerWorkResult& r = *m_lastRun;
    QString text = tr("%n corner(s): mean error %1 → %2 µm (−%3 %).", nullptr, static_cast<int>(r.moves.size()))
                       .arg(number(r.meanWithoutMm * 1e3, 1), number(r.meanWithMm * 1e3, 1), number(r.reductionPct, 0));
    if (r.retrains.empty()) {
        text += QLatin1Char(' ') + tr("No retraining was needed.");
    } else {
        text += QLatin1Char(' ') + retrainText(r.retrains.front());
        if (r.retrains.size() > 1)
            text +=
                QLatin1Char(' ') + tr("%n more retraining(s) later.", nullptr, static_cast<int>(r.retrains.size() - 1));
        if (r.reductionAfterRetrainPct)
            text += QLatin1Char(' ') + tr("After it: −%1 %.").arg(number(*r.reductionAfterRetrainPct, 0));
        const core::DriftCheck& last = r.checks.back();
        if (last.corners >= monitor.windowCorners)
            text += QLatin1Char(' ') +
                    tr("Last difference of the monitor: %1 % (threshold %2 %).")
                        .arg(number(100.0 * last.differenceFraction, 1), number(100.0 * monitor.thresholdFraction, 1));
    }
    m_driftText->setText(text);
}

}  // namespace tt::ui
