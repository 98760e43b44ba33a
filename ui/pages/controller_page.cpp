#include "ui/pages/controller_page.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>

#include "config/plant_config.h"
#include "core/control/adaptive_design.h"
#include "core/model/disturbance_model.h"
#include "core/storage/data_stores.h"
#include "plot/chart.h"
#include "ui/auth/audit_trail.h"
#include "ui/controller/controller_apply.h"
#include "ui/controller/controller_tuning.h"
#include "ui/controller/tuning_worker.h"
#include "ui/controller/weight_row.h"
#include "ui/prompt.h"

namespace tt::ui {

namespace {

const QString kPreset = QStringLiteral("paper-2012");
const QColor kLqgColour(0x1f, 0x6f, 0xb4);
const QColor kEwmaColour(0xd2, 0x6a, 0x1e);
const QColor kOpenColour(0x80, 0x80, 0x80);

QDoubleSpinBox* numberField(double lo, double hi, int decimals, double step, const QString& suffix) {
    auto* f = new QDoubleSpinBox;
    f->setRange(lo, hi);
    f->setDecimals(decimals);
    f->setSingleStep(step);
    f->setSuffix(suffix);
    f->setKeyboardTracking(false);
    f->setMaximumWidth(150);
    return f;
}

QLabel* valueLabel() {
    auto* l = new QLabel;
    l->setMinimumWidth(48);
    l->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    l->setStyleSheet(QStringLiteral("font-weight: bold; color: #1f2a36;"));
    return l;
}

QString fixed(double v, int decimals) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("—");
}

/// The shaping filter the fields describe: W(z) = (z + b)/(z - a) scaled to variance sigma^2 (paper 000).
core::DisturbanceModel typedFilter(double pole, double zero, double varianceMm2) {
    return core::DisturbanceModel({core::DisturbanceComponent::shapingFilterWithVariance(
        core::ShapingFilter::fromRoots({1.0, zero}, {{pole, 0.0}}), varianceMm2)});
}

}  // namespace

ControllerPage::ControllerPage(AppContext& context, QWidget* parent)
    : Page(PageId::Controller, context, parent), m_worker(std::make_unique<TuningWorker>()) {
    m_applied = config::loadRunToRunSetup(kPreset);
    auto* layout = new QHBoxLayout(this);
    auto* left = new QVBoxLayout;
    left->setSpacing(3);
    left->addWidget(buildSettings());
    left->addWidget(buildPoints(), 1);
    m_status = new QLabel;
    m_status->setWordWrap(true);
    left->addWidget(m_status);
    auto* buttons = new QHBoxLayout;
    m_timing = new QLabel;
    m_timing->setStyleSheet(QStringLiteral("color: #56616d;"));
    buttons->addWidget(m_timing, 1);
    m_revert = new QPushButton;
    m_apply = new QPushButton;
    m_apply->setObjectName(QStringLiteral("applyTuning"));
    buttons->addWidget(m_revert);
    buttons->addWidget(m_apply);
    left->addLayout(buttons);
    layout->addLayout(left, 5);
    layout->addWidget(buildCharts(), 3);

    connect(m_worker.get(), &TuningWorker::finished, this, &ControllerPage::showResult);
    connect(m_apply, &QPushButton::clicked, this, &ControllerPage::apply);
    connect(m_revert, &QPushButton::clicked, this, &ControllerPage::revert);
    loadSetup(m_applied);
    retranslate();
    requestPreview();
}

ControllerPage::~ControllerPage() = default;

QWidget* ControllerPage::buildSettings() {
    auto* box = new QGroupBox;
    auto* grid = new QGridLayout(box);
    grid->setVerticalSpacing(2);  // five rows within the 800 px terminal with the points below
    grid->setContentsMargins(9, 4, 9, 4);
    m_settingsTitle = new QLabel;
    m_settingsTitle->setStyleSheet(QStringLiteral("font-weight: bold;"));
    m_delayLabel = new QLabel;
    m_delay = new QSpinBox;
    m_delay->setRange(1, core::kMaxDelay);
    m_maxAbsLabel = new QLabel;
    m_maxAbs = numberField(0.001, 5.0, 3, 0.01, QString());
    m_maxStepLabel = new QLabel;
    m_maxStep = numberField(0.001, 5.0, 3, 0.01, QString());
    m_deadBandLabel = new QLabel;
    m_deadBand = numberField(0.0, 0.5, 4, 0.001, QString());
    m_filterLabel = new QLabel;
    m_poleLabel = new QLabel(QStringLiteral("a"));
    m_pole = numberField(-0.99, 0.999, 4, 0.005, QString());
    m_zeroLabel = new QLabel(QStringLiteral("b"));
    m_zero = numberField(-0.99, 0.99, 3, 0.01, QString());
    m_varianceLabel = new QLabel(QStringLiteral("σ²"));
    m_variance = numberField(1e-6, 1.0, 6, 0.0001, QString());
    m_variance->setMaximumWidth(190);
    grid->addWidget(m_delayLabel, 0, 0);
    grid->addWidget(m_delay, 0, 1);
    grid->addWidget(m_deadBandLabel, 0, 2);
    grid->addWidget(m_deadBand, 0, 3);
    grid->addWidget(m_maxAbsLabel, 1, 0);
    grid->addWidget(m_maxAbs, 1, 1);
    grid->addWidget(m_maxStepLabel, 1, 2);
    grid->addWidget(m_maxStep, 1, 3);
    grid->addWidget(m_filterLabel, 2, 0);
    auto* filter = new QHBoxLayout;
    for (QWidget* w :
         std::initializer_list<QWidget*>{m_poleLabel, m_pole, m_zeroLabel, m_zero, m_varianceLabel, m_variance})
        filter->addWidget(w);
    filter->addStretch(1);
    grid->addLayout(filter, 2, 1, 1, 3);
    grid->addWidget(buildExtraRow(), 3, 0, 1, 4);
    auto* identifyRow = new QHBoxLayout;
    identifyRow->addWidget(m_identifyRun);
    identifyRow->addWidget(m_identify);
    identifyRow->addWidget(m_takeProposal);
    identifyRow->addStretch(1);
    grid->addLayout(identifyRow, 4, 0, 1, 4);
    grid->addWidget(m_identified, 5, 0, 1, 4);  // the fit in words, on a line of its own: it wraps, never squeezes
    for (QSpinBox* s : {m_delay})
        connect(s, &QSpinBox::valueChanged, this, &ControllerPage::requestPreview);
    for (QDoubleSpinBox* f : {m_maxAbs, m_maxStep, m_deadBand, m_pole, m_zero, m_variance})
        connect(f, &QDoubleSpinBox::valueChanged, this, &ControllerPage::requestPreview);
    return box;
}

QWidget* ControllerPage::buildExtraRow() {
    auto* row = new QWidget;
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    m_integral = new QCheckBox;
    m_integral->setObjectName(QStringLiteral("integralAction"));
    m_integralWeightLabel = new QLabel;
    // The core's range and default (core/control/integral_action.h).
    m_integralWeight = numberField(core::kMinIntegralWeight, core::kMaxIntegralWeight, 6, 0.05, QString());
    m_integralWeight->setValue(core::IntegralAction{}.weight);
    m_identifyRun = new QComboBox;
    m_identifyRun->setMinimumContentsLength(12);
    m_identifyRun->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_identify = new QPushButton;
    m_identify->setObjectName(QStringLiteral("identifyFromHistory"));
    m_identified = new QLabel;
    m_identified->setWordWrap(true);
    m_identified->setObjectName(QStringLiteral("identifiedFit"));
    m_identified->hide();  // its line appears with its words only
    m_takeProposal = new QPushButton;
    m_takeProposal->setObjectName(QStringLiteral("takeProposal"));
    m_takeProposal->setVisible(false);
    m_useIdentified = new QCheckBox;
    m_useIdentified->setObjectName(QStringLiteral("identifiedModel"));
    m_useIdentified->setEnabled(false);
    for (QWidget* w : std::initializer_list<QWidget*>{m_integral, m_integralWeightLabel, m_integralWeight})
        h->addWidget(w);
    h->addSpacing(24);
    h->addWidget(m_useIdentified);
    h->addStretch(1);
    connect(m_useIdentified, &QCheckBox::toggled, this, [this](bool on) {
        for (QDoubleSpinBox* f : {m_pole, m_zero, m_variance})
            f->setEnabled(!on);
        requestPreview();
    });
    connect(m_takeProposal, &QPushButton::clicked, this, &ControllerPage::takeProposal);
    connect(m_identifyRun, &QComboBox::currentIndexChanged, this, &ControllerPage::findProposal);
    connect(m_integral, &QCheckBox::toggled, this, [this](bool on) {
        m_integralWeight->setEnabled(on);
        requestPreview();
    });
    connect(m_integralWeight, &QDoubleSpinBox::valueChanged, this, &ControllerPage::requestPreview);
    connect(m_identify, &QPushButton::clicked, this, &ControllerPage::identify);
    connect(&m_identification, &QFutureWatcher<HistoryIdentification>::finished, this,
            &ControllerPage::showIdentification);
    return row;
}

QWidget* ControllerPage::buildPoints() {
    auto* box = new QGroupBox;
    auto* grid = new QGridLayout(box);
    grid->setHorizontalSpacing(6);  // ten columns within the 1280 px terminal (tests/ui/terminal)
    grid->setVerticalSpacing(2);    // and six rows under the settings within 800 px (Russian status wraps)
    grid->setContentsMargins(6, 2, 6, 2);
    const int columns = 8;
    for (int c = 0; c < columns; ++c) {
        auto* h = new QLabel;
        h->setStyleSheet(QStringLiteral("color: #56616d;"));
        h->setWordWrap(true);
        m_headers.push_back(h);
    }
    grid->addWidget(m_headers[0], 0, 0);
    grid->addWidget(m_headers[1], 0, 1, 1, 2);
    grid->addWidget(m_headers[2], 0, 3, 1, 2);
    for (int c = 3; c < 8; ++c)
        grid->addWidget(m_headers[static_cast<std::size_t>(c)], 0, c + 2);
    const int points = static_cast<int>(m_applied.plant.points.size());
    for (int i = 0; i < points; ++i) {
        auto* name = new QLabel;
        m_pointNames.push_back(name);
        auto* r1 = new WeightEditor(0.01, 100.0, 3, this);
        auto* r2 = new WeightEditor(1e-4, 10.0, 4, this);
        m_r1.push_back(r1);
        m_r2.push_back(r2);
        connect(r1, &WeightEditor::changed, this, &ControllerPage::requestPreview);
        connect(r2, &WeightEditor::changed, this, &ControllerPage::requestPreview);
        const int row = i + 1;
        grid->addWidget(name, row, 0);
        grid->addWidget(r1->slider(), row, 1);
        grid->addWidget(r1->field(), row, 2);
        grid->addWidget(r2->slider(), row, 3);
        grid->addWidget(r2->field(), row, 4);
        for (auto* list : {&m_kEffLqg, &m_kEffEwma, &m_gainMargin, &m_delayMargin, &m_disk})
            list->push_back(valueLabel());
        grid->addWidget(m_kEffLqg.back(), row, 5);
        grid->addWidget(m_kEffEwma.back(), row, 6);
        grid->addWidget(m_gainMargin.back(), row, 7);
        m_delayMargin.back()->setMinimumWidth(84);
        grid->addWidget(m_delayMargin.back(), row, 8);
        grid->addWidget(m_disk.back(), row, 9);
    }
    grid->setRowStretch(points + 1, 1);
    return box;
}

QWidget* ControllerPage::buildCharts() {
    auto* column = new QWidget;
    auto* v = new QVBoxLayout(column);
    v->setContentsMargins(0, 0, 0, 0);
    m_stepChart = new plot::Chart;
    m_sensitivityChart = new plot::Chart;
    for (plot::Chart* c : {m_stepChart, m_sensitivityChart}) {
        c->setMinimumHeight(220);
        c->setMinimumWidth(220);
        c->setLegendBelow(2);
        c->setXTickCount(5);
        c->setYTickCount(5);
        v->addWidget(c, 1);
    }
    return column;
}

QString ControllerPage::title() const {
    return tr("Controller");
}

void ControllerPage::retranslate() {
    m_delayLabel->setText(tr("Delay z, parts"));
    m_maxAbsLabel->setText(tr("Max correction"));
    m_maxStepLabel->setText(tr("Max step per part"));
    m_deadBandLabel->setText(tr("Dead band (EWMA)"));
    for (QDoubleSpinBox* f : {m_maxAbs, m_maxStep, m_deadBand})
        f->setSuffix(tr(" mm"));
    m_variance->setSuffix(tr(" mm²"));
    m_filterLabel->setText(tr("Filter (z + b)/(z − a)"));
    const QStringList headers{tr("Point"),      tr("R1 (error)"), tr("R2 (correction)"), tr("k_eff LQG"),
                              tr("k_eff EWMA"), tr("Gain marg."), tr("Delay, parts"),    tr("Disk α")};
    for (int c = 0; c < headers.size(); ++c)
        m_headers[static_cast<std::size_t>(c)]->setText(headers[c]);
    m_headers[6]->setToolTip(
        tr("Delay margin in parts (phase margin / crossover) / whole extra parts of delay "
           "the loop stays stable with"));
    for (std::size_t i = 0; i < m_pointNames.size(); ++i)
        m_pointNames[i]->setText(tr("%1: %2 mm").arg(i + 1).arg(m_applied.plant.points[i].xMm, 0, 'f', 1));
    m_integral->setText(tr("Integral action"));
    m_integral->setToolTip(
        tr("Adds an integrating disturbance state to the LQG design: a step (tool change, "
           "new blanks) is corrected completely, at some cost in k_eff"));
    m_integralWeightLabel->setText(tr("weight"));
    m_identify->setText(tr("Identify from history"));
    m_identify->setToolTip(
        tr("Identifies the plant of a stored run at every point (gain, plant delay, disturbance as ARMA(p, q) with "
           "standard errors) and designs the controller for it"));
    m_useIdentified->setText(tr("Identified model"));
    m_useIdentified->setToolTip(
        tr("Design on the identified model (per point gain and disturbance, the plant delay) instead of the typed "
           "filter"));
    m_takeProposal->setText(m_proposal ? tr("Use the loop's proposal (part %1)").arg(m_proposal->partNumber)
                                       : QString());
    m_takeProposal->setToolTip(
        tr("The adaptive loop identified the plant and proposes a design for it; take it "
           "into the page, check the predictions and apply it"));
    refreshRuns();
    m_apply->setText(tr("Apply…"));
    m_revert->setText(tr("Revert"));
    m_stepChart->setTitle(tr("Step at point 1"));
    m_stepChart->setAxisTitles(tr("part after the step"), tr("error / step"));
    m_sensitivityChart->setTitle(tr("|S| at point 1"));
    m_sensitivityChart->setAxisTitles(tr("frequency, rad per part"), tr("|S|"));
    if (m_shown) showResult(m_shown);
}

core::RunToRunSetup ControllerPage::editedSetup() const {
    core::RunToRunSetup s = m_applied;
    s.plant.delay = m_delay->value();
    for (std::size_t i = 0; i < m_r1.size(); ++i) {
        const auto k = static_cast<Eigen::Index>(i);
        s.weights.R1(k, k) = m_r1[i]->value();
        s.weights.R2(k, k) = m_r2[i]->value();
    }
    s.limits.maxAbsMm = m_maxAbs->value();
    s.limits.maxStepMm = m_maxStep->value();
    s.ewma.deadBandMm = m_deadBand->value();
    s.integral.enabled = m_integral->isChecked();
    s.integral.weight = m_integralWeight->value();
    const core::DisturbanceModel filter = typedFilter(m_pole->value(), m_zero->value(), m_variance->value());
    for (core::ControlPointSpec& p : s.plant.points)
        p.disturbance = filter;
    s.model.reset();
    if (m_identifiedModel && m_useIdentified->isChecked()) s.model = m_identifiedModel;
    return s;
}

void ControllerPage::loadSetup(const core::RunToRunSetup& setup) {
    m_loading = true;
    m_delay->setValue(setup.plant.delay);
    for (std::size_t i = 0; i < m_r1.size(); ++i) {
        const auto k = static_cast<Eigen::Index>(i);
        m_r1[i]->setValue(setup.weights.R1(k, k));
        m_r2[i]->setValue(setup.weights.R2(k, k));
    }
    m_maxAbs->setValue(std::isfinite(setup.limits.maxAbsMm) ? setup.limits.maxAbsMm : m_maxAbs->maximum());
    m_maxStep->setValue(std::isfinite(setup.limits.maxStepMm) ? setup.limits.maxStepMm : m_maxStep->maximum());
    m_deadBand->setValue(setup.ewma.deadBandMm);
    m_integral->setChecked(setup.integral.enabled);
    m_integralWeight->setValue(setup.integral.weight);
    m_integralWeight->setEnabled(setup.integral.enabled);
    m_identifiedModel = setup.model;
    m_useIdentified->setEnabled(setup.model.has_value());
    m_useIdentified->setChecked(setup.model.has_value());
    for (QDoubleSpinBox* f : {m_pole, m_zero, m_variance})
        f->setEnabled(!setup.model);
    // The typed filter starts from the first point's model when it is one first-order shaping filter
    // (paper-2012: (z + 0.246)/(z - 0.9215), 0.0013 mm^2).
    const core::DisturbanceModel& d = setup.plant.points.front().disturbance;
    if (d.components().size() == 1 && d.components().front().filter()) {
        const core::ShapingFilter& f = *d.components().front().filter();
        if (f.poles().size() == 1 && f.numerator().size() == 2) {
            m_pole->setValue(f.poles().front().real());
            m_zero->setValue(f.numerator()[1] / f.numerator()[0]);
            m_variance->setValue(d.stationaryVarianceMm2());
        }
    }
    m_loading = false;
}

void ControllerPage::requestPreview() {
    if (m_loading) return;
    m_worker->request(editedSetup());
}

void ControllerPage::showResult(std::shared_ptr<const TuningResult> result) {
    m_shown = std::move(result);
    const bool newest = m_shown->generation == m_worker->latestGeneration();
    if (!m_shown->problem.isEmpty()) {
        m_status->setText(tr("The design is refused: %1").arg(m_shown->problem));
        m_status->setStyleSheet(QStringLiteral("color: #b00020; font-weight: bold;"));
        m_apply->setEnabled(false);
        return;
    }
    showPredictions(*m_shown);
    showCharts(*m_shown);
    m_timing->setText(tr("Re-synthesis %1 ms").arg(m_shown->computeMs, 0, 'f', 1));
    m_apply->setEnabled(newest);
}

QString ControllerPage::phaseAndPeakText(const core::LoopMargins& margins) const {
    std::optional<double> phase;
    double peak = 0.0;
    for (const core::ChannelMargins& m : margins.channels) {
        if (m.phaseDeg) phase = phase ? std::min(*phase, *m.phaseDeg) : *m.phaseDeg;
        peak = std::max(peak, m.sensitivityPeak);
    }
    return tr("Phase margin %1, sensitivity peak |S| %2.")
        .arg(phase ? QStringLiteral("%1°").arg(*phase, 0, 'f', 0) : QStringLiteral("∞"))
        .arg(peak, 0, 'f', 2);
}

void ControllerPage::showPredictions(const TuningResult& r) {
    const core::TuningPreview& p = *r.preview;
    for (std::size_t i = 0; i < m_kEffLqg.size(); ++i) {
        const auto k = static_cast<Eigen::Index>(i);
        const core::ChannelMargins& m = p.lqgMargins.channels[i];
        m_kEffLqg[i]->setText(p.varianceAvailable ? fixed(p.lqgKEff(k), 2) : QStringLiteral("—"));
        m_kEffEwma[i]->setText(p.varianceAvailable ? fixed(p.ewmaKEff(k), 2) : QStringLiteral("—"));
        m_gainMargin[i]->setText(m.gain ? fixed(*m.gain, 2) : QStringLiteral("∞"));
        m_delayMargin[i]->setText(QStringLiteral("%1 / %2")
                                      .arg(m.delayParts ? fixed(*m.delayParts, 2) : QStringLiteral("∞"))
                                      .arg(m.extraPartsTolerated));
        m_disk[i]->setText(fixed(m.disk, 2));
        const bool weak = (m.delayParts && *m.delayParts < 1.0) || m.extraPartsTolerated < 1;
        m_delayMargin[i]->setStyleSheet(weak ? QStringLiteral("font-weight: bold; color: #b00020;")
                                             : QStringLiteral("font-weight: bold; color: #1f2a36;"));
    }
    if (p.lqgMargins.delayMarginBelowOnePart) {
        m_status->setText(tr("Warning: a plant one part slower than the model destabilises this design "
                             "(delay margin under one part). Best EWMA weight %1.")
                              .arg(p.ewmaWeight, 0, 'f', 2) +
                          QLatin1Char(' ') + phaseAndPeakText(p.lqgMargins));
        m_status->setStyleSheet(QStringLiteral("color: #b00020; font-weight: bold;"));
    } else {
        m_status->setText(
            tr("The design tolerates one more part of delay. Best EWMA weight %1.").arg(p.ewmaWeight, 0, 'f', 2) +
            QLatin1Char(' ') + phaseAndPeakText(p.lqgMargins));
        m_status->setStyleSheet(QStringLiteral("color: #1b5e20; font-weight: bold;"));
    }
}

void ControllerPage::showCharts(const TuningResult& r) {
    const core::TuningPreview& p = *r.preview;
    std::vector<double> parts(p.stepLqg.size());
    for (std::size_t k = 0; k < parts.size(); ++k)
        parts[k] = static_cast<double>(k);
    m_stepChart->setSeries(QStringLiteral("open"), tr("open"), parts, p.stepOpen, kOpenColour,
                           plot::Chart::Style::Steps);
    m_stepChart->setSeries(QStringLiteral("ewma"), tr("EWMA"), parts, p.stepEwma, kEwmaColour,
                           plot::Chart::Style::Steps);
    m_stepChart->setSeries(QStringLiteral("lqg"), tr("LQG"), parts, p.stepLqg, kLqgColour, plot::Chart::Style::Steps);
    m_stepChart->rescale(true);
    m_sensitivityChart->setSeries(QStringLiteral("ewma"), tr("EWMA"), p.frequencyRadPerPart, p.sensitivityEwma,
                                  kEwmaColour);
    m_sensitivityChart->setSeries(QStringLiteral("lqg"), tr("LQG"), p.frequencyRadPerPart, p.sensitivityLqg,
                                  kLqgColour);
    m_sensitivityChart->rescale(true);
    m_stepChart->refresh();
    m_sensitivityChart->refresh();
}

QString ControllerPage::shownLqgKEff(int point) const {
    return m_kEffLqg[static_cast<std::size_t>(point)]->text();
}

void ControllerPage::apply() {
    if (!m_shown || !m_shown->preview || !context().prompt) return;
    const core::RunToRunSetup next = m_shown->setup;
    const QString change = describeTuningChange(m_applied, next);
    if (change.isEmpty()) return;
    try {
        AuditTrail(context()).require(core::auth::Permission::EditControllerTuning);
    } catch (const core::auth::PermissionDenied& refused) {
        context().prompt->warn(this, tr("Apply tuning"), QString::fromStdString(refused.what()));
        return;
    }
    QString question = tr("Apply the new controller tuning from the next part?");
    if (m_shown->preview->lqgMargins.delayMarginBelowOnePart)
        question += QStringLiteral("\n\n") + tr("Warning: its delay margin is under one part: a plant one part "
                                                "slower than the model destabilises it.");
    if (context().prompt->ask(this, tr("Apply tuning"), question) != Prompt::Answer::Yes) return;
    m_lastRecord = recordTuningChange(context(), m_applied, next);
    m_applied = next;
    showWhereApplied();
}

void ControllerPage::showWhereApplied() {
    ControllerTuning* tuning = context().tuning;
    if (!tuning) return;
    const bool running = tuning->loopTakesTuning();
    tuning->apply(m_applied);
    m_status->setText(running ? tr("Applied to the running loop: the new tuning takes over at the next part, "
                                   "without a jump in the correction.")
                              : tr("Applied: no run is going; the next Start on the Run page uses this tuning."));
    m_status->setStyleSheet(QStringLiteral("color: #1b5e20; font-weight: bold;"));
}

QString ControllerPage::statusText() const {
    return m_status->text();
}

void ControllerPage::revert() {
    loadSetup(m_applied);
    requestPreview();
}

void ControllerPage::showEvent(QShowEvent* event) {
    Page::showEvent(event);
    refreshRuns();
}

void ControllerPage::refreshRuns() {
    const QVariant chosen = m_identifyRun->currentData();
    m_identifyRun->clear();
    m_identifyRun->addItem(tr("Newest run"), QVariant());
    try {
        if (core::HistoryStore* history = context().data().history())
            for (const core::RunSummary& run : history->runs()) {
                m_identifyRun->addItem(tr("Run %1").arg(run.runId), QVariant::fromValue<qint64>(run.runId));
                m_identifyRun->setItemData(m_identifyRun->count() - 1,
                                           tr("%n parts, started %1", nullptr, static_cast<int>(run.partCount))
                                               .arg(QString::fromStdString(run.startedAt)),
                                           Qt::ToolTipRole);
            }
    } catch (const std::exception&) {
        // No database yet: only "newest run" (identify then says why nothing is there).
    }
    const int index = chosen.isValid() ? m_identifyRun->findData(chosen) : 0;
    m_identifyRun->setCurrentIndex(index < 0 ? 0 : index);
    findProposal();
}

void ControllerPage::identify() {
    if (m_identifying) return;
    std::optional<std::int64_t> runId;
    if (const QVariant chosen = m_identifyRun->currentData(); chosen.isValid()) runId = chosen.toLongLong();
    storage::DatabaseConfig config;
    try {
        config = storage::DataStores(context().databasePath).config();
    } catch (const std::exception& e) {
        sayIdentified(tr("Identification failed: %1").arg(QString::fromStdString(e.what())));
        return;
    }
    core::RunToRunSetup setup = editedSetup();
    setup.model = m_applied.model;  // the prior: the model the loop runs on
    m_identify->setEnabled(false);
    m_identifying = true;
    m_identified->setStyleSheet(QStringLiteral("color: #56616d;"));
    sayIdentified(tr("Identifying the plant of the stored run…"));
    m_identification.setFuture(QtConcurrent::run(identifyFromHistory, config, runId, setup));
}

void ControllerPage::showIdentification() {
    m_identify->setEnabled(true);
    m_identifying = false;
    const HistoryIdentification result = m_identification.result();
    if (!result.tuning) {
        m_identified->setStyleSheet(QStringLiteral("color: #b00020; font-weight: bold;"));
        sayIdentified(tr("Identification failed: %1").arg(result.problem));
        return;
    }
    const core::StoredRunTuning& t = *result.tuning;
    auto list = [](const std::vector<double>& values, const std::vector<double>& errors) {
        QStringList parts;  // a kept disturbance has no standard errors of its own
        for (std::size_t i = 0; i < values.size(); ++i)
            parts << (i < errors.size() ? QStringLiteral("%1 ± %2").arg(fixed(values[i], 3), fixed(errors[i], 3))
                                        : fixed(values[i], 3));
        return parts.join(QStringLiteral(", "));
    };
    QStringList lines;
    for (const core::PointPlantFit& p : t.identification.points)
        lines << tr("Point %1: gain %2 ± %3, ARMA(%4, %5) AR [%6] MA [%7], σ² %8 mm², Ljung–Box p %9")
                     .arg(p.point + 1)
                     .arg(fixed(p.fit.gain, 3), fixed(p.fit.gainStdErr, 3))
                     .arg(p.orders.ar)
                     .arg(p.orders.ma)
                     .arg(list(p.fit.noise.ar, p.fit.noise.arStdErr), list(p.fit.noise.ma, p.fit.noise.maStdErr))
                     .arg(QString::number(p.fit.noise.noiseVarianceMm2, 'g', 3), fixed(p.fit.noise.ljungBoxP, 2));
    const core::PointPlantFit& first = t.identification.points.front();
    const QString design = t.design.passes
                               ? tr("the design's margins hold (gain margin %1)").arg(fixed(t.design.worst.gain, 2))
                               : tr("the design fails its margins: %1").arg(QString::fromStdString(t.design.why));
    const QString text = tr("Run %1, parts %2 .. %3: plant delay %4 parts; point 1 gain %5 ± %6 (every point in the "
                            "tooltip); %7")
                             .arg(t.runId)
                             .arg(t.firstPart)
                             .arg(t.lastPart)
                             .arg(t.identification.delayParts())
                             .arg(fixed(first.fit.gain, 3), fixed(first.fit.gainStdErr, 3), design);
    // The typed filter (z + b)/(z - a) shows point 1's fit when it has that form.
    const core::ArmaFit& f = first.fit.noise;
    if (f.ar.size() == 1 && f.ma.size() <= 1) {
        m_loading = true;
        m_pole->setValue(f.ar.front());
        m_zero->setValue(f.ma.empty() ? 0.0 : f.ma.front());
        m_variance->setValue(f.disturbanceModel().stationaryVarianceMm2());
        m_loading = false;
    }
    m_loading = true;
    m_delay->setValue(t.identification.loopDelay);  // the run's z: the identified lag is counted from it
    m_loading = false;
    if (t.design.passes && t.design.r2Factor > 1.0) {
        m_loading = true;
        for (std::size_t i = 0; i < m_r2.size(); ++i)
            m_r2[i]->setValue(t.design.setup.weights.R2(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i)));
        m_loading = false;
    }
    useModel(*t.design.setup.model, text, lines.join(QLatin1Char('\n')));
    m_identified->setStyleSheet(t.design.passes ? QStringLiteral("color: #1f2a36;")
                                                : QStringLiteral("color: #b00020; font-weight: bold;"));
}

void ControllerPage::useModel(const core::ControllerModel& model, const QString& text, const QString& details) {
    m_identifiedModel = model;
    m_identified->setStyleSheet(QStringLiteral("color: #1f2a36;"));
    sayIdentified(text);
    m_identified->setToolTip(details);
    m_useIdentified->setEnabled(true);
    const bool wasChecked = m_useIdentified->isChecked();
    m_useIdentified->setChecked(true);
    if (wasChecked) requestPreview();  // toggled() asks for it otherwise
}

void ControllerPage::sayIdentified(const QString& text) {
    m_identified->setText(text);
    m_identified->setVisible(!text.isEmpty());
}

void ControllerPage::findProposal() {
    m_proposal.reset();
    try {
        core::HistoryStore* history = context().data().history();
        std::optional<std::int64_t> runId;
        if (const QVariant chosen = m_identifyRun->currentData(); chosen.isValid()) runId = chosen.toLongLong();
        if (history && !runId)
            for (const core::RunSummary& run : history->runs())
                runId = std::max(runId.value_or(run.runId), run.runId);
        if (history && runId) {
            const std::vector<core::AdaptationRecord> records = history->adaptations(*runId);
            if (!records.empty() && records.back().kind == core::adaptation_kind::kProposed &&
                records.back().modelAfter)
                m_proposal = records.back();
        }
    } catch (const std::exception&) {
        // No database yet: no proposal.
    }
    m_takeProposal->setVisible(m_proposal.has_value());
    if (m_proposal) m_takeProposal->setText(tr("Use the loop's proposal (part %1)").arg(m_proposal->partNumber));
}

void ControllerPage::takeProposal() {
    if (!m_proposal || !m_proposal->modelAfter) return;
    try {
        core::ControllerModel model = core::controllerModelFrom(*m_proposal->modelAfter, m_applied);
        m_loading = true;
        m_delay->setValue(m_proposal->modelAfter->delayParts - m_proposal->modelAfter->lagParts);
        m_loading = false;
        QStringList details;
        for (std::size_t i = 0; i < m_proposal->modelAfter->points.size(); ++i) {
            const core::PointModelRecord& p = m_proposal->modelAfter->points[i];
            details << tr("Point %1: gain %2 ± %3, σ² %4 mm²")
                           .arg(i + 1)
                           .arg(fixed(p.gain, 3), fixed(p.gainStdErr, 3))
                           .arg(QString::number(p.noiseVarianceMm2, 'g', 3));
        }
        useModel(model,
                 tr("The loop's proposal of part %1: plant delay %2 parts, identified from %3")
                     .arg(m_proposal->partNumber)
                     .arg(m_proposal->modelAfter->delayParts)
                     .arg(QString::fromStdString(m_proposal->modelAfter->source)),
                 details.join(QLatin1Char('\n')));
    } catch (const std::invalid_argument& e) {
        m_identified->setStyleSheet(QStringLiteral("color: #b00020; font-weight: bold;"));
        sayIdentified(tr("The proposal cannot be used: %1").arg(QString::fromStdString(e.what())));
    }
}

QString ControllerPage::identifiedText() const {
    return m_identified->text();
}

bool ControllerPage::identifying() const {
    return m_identifying;
}

double ControllerPage::typedPole() const {
    return m_pole->value();
}

double ControllerPage::typedZero() const {
    return m_zero->value();
}

double ControllerPage::typedVarianceMm2() const {
    return m_variance->value();
}

}  // namespace tt::ui
