#include "ui/process/hydraulic_feed_tool.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>

#include "config/hydraulic_feed_config.h"
#include "config/hydraulic_feed_csv.h"
#include "ui/process/feed_block_diagram.h"
#include "ui/process/feed_chart_tabs.h"
#include "ui/process/feed_parameter_form.h"
#include "ui/prompt.h"

namespace tt::ui {

namespace {

constexpr int kMaxPointsPerCurve = 4000;  ///< the charts stay quick; the engine's step control is not affected

QString g(double v, int precision = 4) {
    return QString::number(v, 'g', precision);
}

}  // namespace

HydraulicFeedTool::HydraulicFeedTool(AppContext& context, QWidget* parent)
    : ProcessTool(parent),
      m_context(context),
      m_worker(new FeedStudyWorker(this)),
      m_diagram(new FeedBlockDiagram(this)),
      m_form(new FeedParameterForm(this)),
      m_scenarioBox(new QWidget(this)),
      m_loadLabel(new QLabel(this)),
      m_load(new QDoubleSpinBox(this)),
      m_atLabel(new QLabel(this)),
      m_stepTime(new QDoubleSpinBox(this)),
      m_durationLabel(new QLabel(this)),
      m_duration(new QDoubleSpinBox(this)),
      m_regulatorLabel(new QLabel(this)),
      m_regulator(new QComboBox(this)),
      m_reset(new QPushButton(this)),
      m_simulate(new QPushButton(this)),
      m_sweepXi(new QPushButton(this)),
      m_sweepGain(new QPushButton(this)),
      m_cancel(new QPushButton(this)),
      m_charts(new FeedChartTabs(this)),
      m_summary(new QLabel(this)),
      m_status(new QLabel(this)),
      m_exportLabel(new QLabel(this)),
      m_exportPng(new QPushButton(this)),
      m_exportCsv(new QPushButton(this)),
      m_progress(new QProgressBar(this)) {
    buildLayout();
    loadPreset();
    connect(m_diagram, &FeedBlockDiagram::blockSelected, m_form, &FeedParameterForm::showBlock);
    connect(m_form, &FeedParameterForm::changed, this, &HydraulicFeedTool::refreshDiagram);
    connect(m_charts, &QTabWidget::currentChanged, this, [this] {
        updateEnabled();
        showSummary();
    });
    connect(m_form, &FeedParameterForm::designRequested, this, &HydraulicFeedTool::designGain);
    connect(m_reset, &QPushButton::clicked, this, [this] {
        loadPreset();
        retranslate();
    });
    connect(m_simulate, &QPushButton::clicked, this, &HydraulicFeedTool::simulate);
    connect(m_sweepXi, &QPushButton::clicked, this, [this] { sweep(core::FeedSweepKind::DampingRatio); });
    connect(m_sweepGain, &QPushButton::clicked, this, [this] { sweep(core::FeedSweepKind::AmplifierGain); });
    connect(m_cancel, &QPushButton::clicked, this, &HydraulicFeedTool::cancel);
    connect(m_exportPng, &QPushButton::clicked, this, &HydraulicFeedTool::exportPng);
    connect(m_exportCsv, &QPushButton::clicked, this, &HydraulicFeedTool::exportCsv);
    connect(m_worker, &FeedStudyWorker::progress, this, [this](int done, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(done);
    });
    connect(m_worker, &FeedStudyWorker::finished, this, &HydraulicFeedTool::finishJob);
    m_form->showBlock(m_diagram->selected());
    retranslate();
    updateEnabled();
}

HydraulicFeedTool::~HydraulicFeedTool() = default;

void HydraulicFeedTool::buildLayout() {
    m_simulate->setObjectName(QStringLiteral("feedSimulate"));
    m_sweepXi->setObjectName(QStringLiteral("feedSweepXi"));
    m_sweepGain->setObjectName(QStringLiteral("feedSweepGain"));
    m_cancel->setObjectName(QStringLiteral("feedCancel"));
    m_reset->setObjectName(QStringLiteral("feedReset"));
    m_exportPng->setObjectName(QStringLiteral("feedExportPng"));
    m_exportCsv->setObjectName(QStringLiteral("feedExportCsv"));
    m_summary->setObjectName(QStringLiteral("feedSummary"));
    m_status->setObjectName(QStringLiteral("feedStatus"));
    m_load->setObjectName(QStringLiteral("feedLoad"));
    m_stepTime->setObjectName(QStringLiteral("feedStepTime"));
    m_duration->setObjectName(QStringLiteral("feedDuration"));
    m_diagram->setObjectName(QStringLiteral("feedDiagram"));
    m_regulator->setObjectName(QStringLiteral("feedRegulator"));
    m_regulator->addItem(QString(), static_cast<int>(core::FeedRegulator::Feedback));
    m_regulator->addItem(QString(), static_cast<int>(core::FeedRegulator::FeedForward));
    m_regulator->setMinimumHeight(32);
    m_simulate->setProperty("role", QStringLiteral("primary"));

    // Limits: the engine's (core::FeedLoadProfile, core::FeedRunOptions).
    m_load->setRange(0.0, core::FeedLoadProfile::kMaxForceN);
    m_load->setDecimals(2);
    m_load->setSingleStep(0.5);
    m_stepTime->setRange(0.0, core::FeedLoadProfile::kMaxTimeS);
    m_stepTime->setDecimals(3);
    m_stepTime->setSingleStep(0.01);
    m_duration->setRange(0.05, core::FeedLoadProfile::kMaxTimeS);
    m_duration->setDecimals(2);
    m_duration->setSingleStep(0.1);
    for (QDoubleSpinBox* spin : {m_load, m_stepTime, m_duration}) {
        spin->setMinimumWidth(120);
        spin->setKeyboardTracking(false);
    }
    auto* scenario = new QGridLayout(m_scenarioBox);
    scenario->setContentsMargins(0, 0, 0, 0);
    scenario->setVerticalSpacing(4);
    scenario->addWidget(m_loadLabel, 0, 0, Qt::AlignRight);
    scenario->addWidget(m_load, 0, 1);
    scenario->addWidget(m_atLabel, 0, 2, Qt::AlignRight);
    scenario->addWidget(m_stepTime, 0, 3);
    scenario->addWidget(m_durationLabel, 1, 0, Qt::AlignRight);
    scenario->addWidget(m_duration, 1, 1);
    scenario->addWidget(m_reset, 1, 2, 1, 2);

    m_summary->setWordWrap(true);
    m_summary->setStyleSheet(QStringLiteral("font-size: 12pt; color: #1f2a36;"));
    m_status->setWordWrap(true);
    m_progress->setTextVisible(true);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    auto* exports = new QHBoxLayout;
    exports->addWidget(m_exportLabel);
    exports->addWidget(m_exportPng);
    exports->addWidget(m_exportCsv);
    exports->addWidget(m_progress, 1);
    auto* left = new QVBoxLayout;
    left->addWidget(m_form);
    left->addWidget(m_scenarioBox);
    left->addStretch(1);
    left->addLayout(exports);
    auto* leftWidget = new QWidget(this);
    leftWidget->setLayout(left);
    left->setContentsMargins(0, 0, 0, 0);
    leftWidget->setFixedWidth(410);

    auto* actions = new QHBoxLayout;
    for (QPushButton* b : {m_simulate, m_sweepXi, m_sweepGain, m_cancel})
        actions->addWidget(b);
    actions->addStretch(1);
    // The regulator above the actions it applies to (the left column is full at 800 px).
    auto* regulatorRow = new QHBoxLayout;
    regulatorRow->addWidget(m_regulatorLabel);
    regulatorRow->addWidget(m_regulator, 1);
    auto* right = new QVBoxLayout;
    right->setContentsMargins(0, 0, 0, 0);
    right->addLayout(regulatorRow);
    right->addLayout(actions);
    right->addWidget(m_charts, 1);
    right->addWidget(m_summary);
    right->addWidget(m_status);

    auto* body = new QHBoxLayout;
    body->addWidget(leftWidget);
    body->addSpacing(6);
    body->addLayout(right, 1);
    auto* root = new QVBoxLayout(this);
    root->setContentsMargins(4, 4, 4, 4);
    root->setSpacing(4);
    root->addWidget(m_diagram);
    root->addLayout(body, 1);
}

void HydraulicFeedTool::loadPreset() {
    try {
        m_preset = config::loadHydraulicFeedScenario(key());
        m_presetProblem.clear();
    } catch (const std::exception& e) {
        m_preset = core::FeedScenario{};
        m_preset.load = core::FeedLoadProfile::step(0.02, 3.23);
        m_presetProblem = QString::fromStdString(e.what());
    }
    m_form->setParams(m_preset.params);
    const std::vector<core::FeedLoadEvent>& events = m_preset.load.events();
    m_load->setValue(m_preset.finalLoadN());
    m_stepTime->setValue(events.empty() ? 0.02 : events.back().timeS);
    m_duration->setValue(m_preset.run.durationS);
    if (!m_presetProblem.isEmpty()) setStatus(m_presetProblem, true);
}

QString HydraulicFeedTool::title() const {
    return tr("Hydraulic feed");
}

void HydraulicFeedTool::refreshDiagram() {
    const core::HydraulicFeedParams p = m_form->params();
    m_diagram->setBlockText(FeedBlock::Sensor, tr("Sensor"), QStringLiteral("U_d = k_d P_y\nP_y = P (v/S)^y"));
    m_diagram->setBlockText(FeedBlock::Amplifier, tr("Amplifier"), QStringLiteral("U = U₀ + K_a U_d"));
    m_diagram->setBlockText(FeedBlock::Magnet, tr("Electromagnet"), QStringLiteral("L i′ + r i = U\nF = K_e i²"));
    m_diagram->setBlockText(FeedBlock::Spool, tr("Spool"), QStringLiteral("T_z²h″+2ξT_z h′+h\n= K_z F"));
    m_diagram->setBlockText(FeedBlock::Slot, tr("Slot"), QStringLiteral("Q = k_s m\nm = h − lap"));
    m_diagram->setBlockText(FeedBlock::Cylinder, tr("Cylinder"), QStringLiteral("T_c v′ + v =\nk₀(Q_y+Q−α₀)"));
    const bool loop = p.feedExponent > 0.0;
    m_diagram->setSignalTexts(tr("load P: leakage α₀ = k_y P/F"), QStringLiteral("v"),
                              loop ? tr("chip thickness: P_y = P (v/S)^%1").arg(g(p.feedExponent, 2))
                                   : tr("no loop: the force does not follow the feed (y = 0)"),
                              loop);
}

void HydraulicFeedTool::retranslate() {
    refreshDiagram();
    m_form->retranslate();
    m_loadLabel->setText(tr("Load step"));
    m_load->setSuffix(tr(" N"));
    m_atLabel->setText(tr("at"));
    m_stepTime->setSuffix(tr(" s"));
    m_durationLabel->setText(tr("Simulate"));
    m_duration->setSuffix(tr(" s"));
    m_reset->setText(tr("Preset values"));
    m_regulatorLabel->setText(tr("Regulator"));
    m_regulator->setItemText(0, tr("Feedback of the feed"));
    m_regulator->setItemText(1, tr("Feed-forward of the force (paper)"));
    m_simulate->setText(tr("Simulate"));
    m_sweepXi->setText(tr("Sweep ξ"));
    m_sweepGain->setText(tr("Sweep gain"));
    m_cancel->setText(tr("Cancel"));
    m_exportLabel->setText(tr("Export"));
    m_exportPng->setText(tr("PNG…"));
    m_exportCsv->setText(tr("CSV…"));
    m_charts->retranslate();
    showSummary();
}

std::optional<core::FeedScenario> HydraulicFeedTool::scenarioFromForm() {
    core::FeedScenario s;
    s.params = m_form->params();
    s.run.durationS = m_duration->value();
    s.run.sampleS = std::max(5e-4, s.run.durationS / kMaxPointsPerCurve);
    if (m_stepTime->value() >= s.run.durationS) {
        setStatus(tr("The load step at %1 s comes after the end of the simulation (%2 s).")
                      .arg(g(m_stepTime->value()), g(s.run.durationS)),
                  true);
        return std::nullopt;
    }
    try {
        core::validate(s.params);
        if (m_load->value() > 0.0) s.load.addStep(m_stepTime->value(), m_load->value());
    } catch (const std::invalid_argument& e) {
        setStatus(QString::fromStdString(e.what()), true);
        return std::nullopt;
    }
    return s;
}

bool HydraulicFeedTool::simulate() {
    return startJob(FeedStudyResult::Job::Simulate);
}

bool HydraulicFeedTool::sweep(core::FeedSweepKind kind) {
    return startJob(kind == core::FeedSweepKind::DampingRatio ? FeedStudyResult::Job::SweepXi
                                                              : FeedStudyResult::Job::SweepGain);
}

bool HydraulicFeedTool::startJob(FeedStudyResult::Job job) {
    if (m_worker->busy()) return false;
    const std::optional<core::FeedScenario> scenario = scenarioFromForm();
    if (!scenario) return false;
    if (job == FeedStudyResult::Job::SweepGain && regulator() == core::FeedRegulator::FeedForward &&
        !(scenario->finalLoadN() > 0.0)) {
        setStatus(tr("A gain sweep needs a load: the gains are multiples of the one that makes up its leakage."), true);
        return false;
    }
    if (!m_worker->start(job, *scenario, regulator())) return false;
    m_progress->setRange(0, 0);  // busy until the first run reports
    setStatus(job == FeedStudyResult::Job::Simulate  ? tr("Simulating with and without the regulator…")
              : job == FeedStudyResult::Job::SweepXi ? tr("Sweeping ξ…")
                                                     : tr("Sweeping the gain…"),
              false);
    updateEnabled();
    return true;
}

core::FeedRegulator HydraulicFeedTool::regulator() const {
    return static_cast<core::FeedRegulator>(m_regulator->currentData().toInt());
}

void HydraulicFeedTool::setRegulator(core::FeedRegulator regulator) {
    m_regulator->setCurrentIndex(m_regulator->findData(static_cast<int>(regulator)));
}

void HydraulicFeedTool::cancel() {
    m_worker->cancel();
}

bool HydraulicFeedTool::busy() const {
    return m_worker->busy();
}

void HydraulicFeedTool::finishJob(const std::shared_ptr<const FeedStudyResult>& result) {
    m_progress->setRange(0, 1);
    m_progress->setValue(result->cancelled || !result->problem.isEmpty() ? 0 : 1);
    if (result->cancelled) {
        setStatus(tr("Cancelled; the curves shown are from the last finished run."), false);
    } else if (!result->problem.isEmpty()) {
        setStatus(result->problem, true);
    } else if (result->job == FeedStudyResult::Job::Simulate) {
        m_run = result;
        m_charts->showRuns(*result);
        const QString warnings = warningsText(*result);
        setStatus(warnings.isEmpty() ? result->stabilityProblem : warnings,
                  !warnings.isEmpty() || !result->stabilityProblem.isEmpty());
    } else {
        m_sweep = result;
        m_charts->showSweep(*result);
        setStatus(QString(), false);
    }
    showSummary();
    updateEnabled();
}

void HydraulicFeedTool::designGain() {
    core::HydraulicFeedParams p = m_form->params();
    if (!(m_load->value() > 0.0)) {
        setStatus(tr("Set a load first: the gain is designed to make up its leakage."), true);
        return;
    }
    try {
        p.spoolLapM = core::matchedSpoolLap(p);
        p.amplifierGain = core::designAmplifierGain(p, m_load->value());
        core::validate(p);
    } catch (const std::invalid_argument& e) {
        setStatus(QString::fromStdString(e.what()), true);
        return;
    }
    m_form->setParams(p);
    setStatus(tr("Gain %1 V/V and lap %2 mm: the slot opens by just the leakage of %3 N at the set feed.")
                  .arg(g(p.amplifierGain, 5), g(p.spoolLapM * 1e3), g(m_load->value())),
              false);
    retranslate();
}

QString HydraulicFeedTool::sweepSummary() const {
    int oscillating = 0;
    int unstable = 0;
    for (const core::FeedSweepPoint& p : m_sweep->sweep) {
        oscillating += p.oscillates ? 1 : 0;
        unstable += p.stable ? 0 : 1;
    }
    QString text = tr("%n run(s) swept; settling times and overshoots are on the Sweep table tab.", nullptr,
                      static_cast<int>(m_sweep->sweep.size())) +
                   QLatin1Char(' ') +
                   tr("The spool swings past its final opening in %n of them.", nullptr, oscillating);
    if (unstable > 0) text += QLatin1Char(' ') + tr("%n run(s) beyond the stability boundary.", nullptr, unstable);
    return text;
}

void HydraulicFeedTool::showSummary() {
    if (m_sweep && m_charts->currentIndex() >= FeedChartTabs::SweepTab) {
        m_summary->setText(sweepSummary());
        return;
    }
    if (!m_run) {
        m_summary->setText(tr("Choose a block on the diagram to edit its parameters, then Simulate."));
        return;
    }
    const FeedStudyResult& r = *m_run;
    const QString name = r.regulator == core::FeedRegulator::Feedback ? tr("the feedback") : tr("the feed-forward");
    QString text =
        tr("Steady feed %1 mm/s with %7, %2 mm/s without (set %3). Settling (5 %): %4 s with, %5 s "
           "without; overshoot %6 %.")
            .arg(QString::number(r.with.feed.finalValue * 1e3, 'f', 4),
                 QString::number(std::abs(r.without.feed.finalValue) < 1e-12 ? 0.0 : r.without.feed.finalValue * 1e3,
                                 'f', 4),
                 QString::number(r.scenario.params.setFeedMPerS * 1e3, 'f', 3),
                 QString::number(r.with.feed.settlingS, 'f', 3), QString::number(r.without.feed.settlingS, 'f', 3),
                 QString::number(r.with.feed.overshootPct, 'f', 1), name);
    const bool stalls =
        std::any_of(r.without.warnings.begin(), r.without.warnings.end(),
                    [](const core::FeedWarning& w) { return w.kind == core::FeedWarningKind::CarriageStalled; });
    if (stalls)
        text += QLatin1Char(' ') +
                tr("Without the regulator the carriage stalls: the pump's flow cannot make up the leakage.");
    const QString regulatorText = regulatorSummary(r);
    if (!regulatorText.isEmpty()) text += QLatin1Char('\n') + regulatorText;
    m_summary->setText(text);
}

QString HydraulicFeedTool::regulatorSummary(const FeedStudyResult& r) const {
    if (r.feedback) {
        const core::ContinuousMargins& m = r.feedback->margins;
        const QString gain =
            m.gainMargin ? tr("%1 (%2 dB) at %3 rad/s")
                               .arg(g(*m.gainMargin, 3), g(*m.gainMarginDb(), 3), g(*m.phaseCrossoverRadPerS, 3))
                         : tr("unlimited");
        const QString phase = m.phaseMarginDeg
                                  ? tr("%1° at %2 rad/s").arg(g(*m.phaseMarginDeg, 3), g(*m.gainCrossoverRadPerS, 3))
                                  : tr("unlimited");
        return tr("Margins of the feedback loop: gain %1, phase %2; closed loop %3.")
            .arg(gain, phase, m.closedLoopStable ? tr("stable") : tr("UNSTABLE"));
    }
    if (!r.stability) return {};
    const core::FeedStability& st = *r.stability;
    if (st.gainLimit)
        return tr("Stability boundary: K_a = %1 (%2 × the design gain %3); simulated at ±5 %: %4.")
            .arg(g(*st.gainLimit, 5), g(*st.gainLimit / st.designGain, 4), g(st.designGain, 5))
            .arg(r.check && r.check->belowSettles && r.check->aboveRunsAway ? tr("confirmed") : tr("not confirmed"));
    if (st.fullOpeningGain)
        return tr("No gain destabilises the chain; the slot opens fully above K_a = %1 (%2 × the design gain %3).")
            .arg(g(*st.fullOpeningGain, 5), g(*st.fullOpeningGain / st.designGain, 4), g(st.designGain, 5));
    return tr("No gain up to 1e5 destabilises the chain (design gain %1).").arg(g(st.designGain, 5));
}

QString HydraulicFeedTool::warningsText(const FeedStudyResult& r) const {
    QStringList out;
    for (const core::FeedWarning& w : r.with.warnings) {
        switch (w.kind) {
            case core::FeedWarningKind::CarriageStalled:
                out << tr("The carriage stalled from %1 s to %2 s: the flow cannot make up the load's leakage.")
                           .arg(g(w.fromS, 3), g(w.toS, 3));
                break;
            case core::FeedWarningKind::SlotFullyOpen:
                out << tr("The slot was fully open from %1 s to %2 s: the regulator could give no more flow.")
                           .arg(g(w.fromS, 3), g(w.toS, 3));
                break;
            case core::FeedWarningKind::SlotShut:
                out << tr("The feedback asked for less than a shut slot from %1 s to %2 s.")
                           .arg(g(w.fromS, 3), g(w.toS, 3));
                break;
            case core::FeedWarningKind::FeedOffSet:
                out << tr("The feed ends %1 % off the set feed (band ±%2 %).")
                           .arg(QString::number(w.value, 'f', 1), g(r.scenario.run.bandPct));
                break;
        }
    }
    return out.join(QLatin1Char(' '));
}

void HydraulicFeedTool::updateEnabled() {
    const bool running = m_worker->busy();
    for (QPushButton* b : {m_simulate, m_sweepXi, m_sweepGain, m_reset, m_form->designButton()})
        b->setEnabled(!running);
    m_cancel->setEnabled(running);
    const bool sweepShown = m_charts->currentIndex() >= FeedChartTabs::SweepTab;
    m_exportCsv->setEnabled(!running && (sweepShown ? m_sweep != nullptr : m_run != nullptr));
    m_exportPng->setEnabled(!running);
}

void HydraulicFeedTool::setStatus(const QString& text, bool problem) {
    m_status->setText(text);
    m_status->setStyleSheet(problem ? QStringLiteral("color: #c62828; font-size: 12pt; font-weight: bold;")
                                    : QStringLiteral("color: #38434f; font-size: 12pt;"));
}

QString HydraulicFeedTool::summary() const {
    return m_summary->text();
}

QString HydraulicFeedTool::status() const {
    return m_status->text();
}

bool HydraulicFeedTool::exportPng() {
    if (!m_context.prompt) return false;
    const QString path = m_context.prompt->saveFileName(this, tr("Export the chart"),
                                                        QStringLiteral("hydraulic-feed.png"), tr("PNG images (*.png)"));
    if (path.isEmpty()) return false;
    if (!m_charts->currentWidget()->grab().save(path, "PNG")) {
        m_context.prompt->warn(this, tr("Export the chart"), tr("Cannot write %1.").arg(path));
        return false;
    }
    setStatus(tr("Chart written to %1.").arg(path), false);
    return true;
}

bool HydraulicFeedTool::exportCsv() {
    if (!m_context.prompt) return false;
    const bool sweepShown = m_charts->currentIndex() >= FeedChartTabs::SweepTab;
    const std::shared_ptr<const FeedStudyResult> result = sweepShown ? m_sweep : m_run;
    if (!result) return false;
    QStringList labels;
    std::vector<const core::FeedRun*> runs;
    if (sweepShown) {
        const QString name =
            result->job == FeedStudyResult::Job::SweepXi ? QStringLiteral("xi") : QStringLiteral("gain");
        for (const core::FeedSweepPoint& p : result->sweep) {
            labels << QStringLiteral("%1=%2").arg(name, g(p.value, 6));
            runs.push_back(&p.run);
        }
    } else {
        labels << QStringLiteral("with regulator") << QStringLiteral("without regulator");
        runs = {&result->with, &result->without};
    }
    const QString path = m_context.prompt->saveFileName(this, tr("Export the curves"),
                                                        QStringLiteral("hydraulic-feed.csv"), tr("CSV files (*.csv)"));
    if (path.isEmpty()) return false;
    QFile file(path);
    const QByteArray csv = config::feedRunsCsv(labels, runs);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(csv) != csv.size()) {
        m_context.prompt->warn(this, tr("Export the curves"), tr("Cannot write %1: %2").arg(path, file.errorString()));
        return false;
    }
    setStatus(tr("Curves written to %1.").arg(path), false);
    return true;
}

}  // namespace tt::ui
