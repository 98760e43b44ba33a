#include "ui/process/feed_schedule_tool.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QJsonDocument>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QTabWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "config/preset_library.h"
#include "devices/parsers/gcode_writer.h"
#include "plot/chart.h"
#include "ui/process/deformation_model_panel.h"
#include "ui/process/feed_model_task.h"
#include "ui/process/gcode_view.h"
#include "ui/prompt.h"

namespace tt::ui {

namespace {

const QString kPreset = QStringLiteral("feed-scheduling");
constexpr int kLevelSteps = 1000;  ///< slider positions over [Y1, Y2]
constexpr int kFamily = 4;         ///< curves Y(z) drawn for fmin .. fmax
constexpr int kCurvePoints = 81;
const QColor kLevelColor(198, 40, 40);
const QColor kScheduleColor(46, 125, 50);
const QColor kFeedColor(21, 101, 192);

QString fixed(double v, int decimals) {
    return QLocale().toString(v, 'f', decimals);
}

/// m:ss for a machining time.
QString minutes(double seconds) {
    const auto s = static_cast<long long>(std::lround(seconds));
    return QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
}

QColor familyColor(int i) {
    // From light to dark blue-grey with the feed.
    const int shade = 190 - 30 * i;
    return QColor(shade / 2, shade / 2 + 20, shade + 40);
}

void setBox(QDoubleSpinBox* box, double lo, double hi, int decimals, double step, const QString& suffix) {
    box->setDecimals(decimals);
    box->setRange(lo, hi);
    box->setSingleStep(step);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false);
    box->setMinimumWidth(150);
}

}  // namespace

FeedScheduleTool::FeedScheduleTool(AppContext& context, QWidget* parent)
    : ProcessTool(parent),
      m_context(context),
      m_task(new FeedModelTask(this)),
      m_modelBox(new QGroupBox(this)),
      m_modelSummary(new QLabel(this)),
      m_simulate(new QPushButton(this)),
      m_fitCsv(new QPushButton(this)),
      m_load(new QPushButton(this)),
      m_progress(new QProgressBar(this)),
      m_cancel(new QPushButton(this)),
      m_passBox(new QGroupBox(this)),
      m_depthLabel(new QLabel(this)),
      m_depth(new QDoubleSpinBox(this)),
      m_feedsLabel(new QLabel(this)),
      m_feedMin(new QDoubleSpinBox(this)),
      m_feedMax(new QDoubleSpinBox(this)),
      m_feedStepLabel(new QLabel(this)),
      m_feedStep(new QDoubleSpinBox(this)),
      m_zLabel(new QLabel(this)),
      m_zStart(new QDoubleSpinBox(this)),
      m_zEnd(new QDoubleSpinBox(this)),
      m_minLengthLabel(new QLabel(this)),
      m_minLength(new QDoubleSpinBox(this)),
      m_dialectLabel(new QLabel(this)),
      m_dialect(new QComboBox(this)),
      m_switch(new QComboBox(this)),
      m_checkButton(new QPushButton(this)),
      m_refine(new QPushButton(this)),
      m_save(new QPushButton(this)),
      m_levelTitle(new QLabel(this)),
      m_levelValue(new QLabel(this)),
      m_level(new QSlider(Qt::Horizontal, this)),
      m_levelLow(new QLabel(this)),
      m_levelHigh(new QLabel(this)),
      m_result(new QLabel(this)),
      m_views(new QTabWidget(this)),
      m_curves(new plot::Chart(this)),
      m_feeds(new plot::Chart(this)),
      m_programView(new GCodeView(this)),
      m_modelPanel(new DeformationModelPanel(this)) {
    try {
        m_preset = config::feedSchedulingSetupFromPreset(config::PresetLibrary::load(kPreset));
    } catch (const std::exception& e) {
        m_presetProblem = QString::fromStdString(e.what());
    }
    buildLayout();
    configureBoxes();
    m_save->setEnabled(false);  // until there is a program
    connectControls();
    setBusy(false, QString());
    retranslate();
    // The built-in set-up's experiments and model, so the page shows a schedule at once (worker thread).
    if (m_preset) simulateExperiments();
}

FeedScheduleTool::~FeedScheduleTool() = default;

QString FeedScheduleTool::title() const {
    return tr("Feed schedule");
}

void FeedScheduleTool::connectControls() {
    connect(m_simulate, &QPushButton::clicked, this, &FeedScheduleTool::simulateExperiments);
    connect(m_fitCsv, &QPushButton::clicked, this, &FeedScheduleTool::fitCsvFile);
    connect(m_load, &QPushButton::clicked, this, &FeedScheduleTool::loadModelFile);
    connect(m_checkButton, &QPushButton::clicked, this, &FeedScheduleTool::checkOnSimulator);
    connect(m_refine, &QPushButton::clicked, this, &FeedScheduleTool::refineModel);
    connect(m_task, &FeedModelTask::refineProgress, this, &FeedScheduleTool::showRefineProgress);
    connect(m_save, &QPushButton::clicked, this, &FeedScheduleTool::saveProgram);
    connect(m_cancel, &QPushButton::clicked, m_task, &FeedModelTask::cancel);
    connect(m_task, &FeedModelTask::progress, m_progress, &QProgressBar::setValue);
    connect(m_task, &FeedModelTask::finished, this, &FeedScheduleTool::taskDone);
    connect(m_level, &QSlider::valueChanged, this, [this] { reschedule(); });
    for (QDoubleSpinBox* box : {m_depth, m_feedMin, m_feedMax, m_feedStep, m_zStart, m_zEnd, m_minLength})
        connect(box, &QDoubleSpinBox::valueChanged, this, [this] { reschedule(); });
    connect(m_dialect, &QComboBox::currentIndexChanged, this, [this] { updateProgram(); });
    connect(m_switch, &QComboBox::currentIndexChanged, this, [this] { reschedule(); });
}

void FeedScheduleTool::buildLayout() {
    m_simulate->setObjectName(QStringLiteral("feedSimulate"));
    m_fitCsv->setObjectName(QStringLiteral("feedFitCsv"));
    m_load->setObjectName(QStringLiteral("feedLoadModel"));
    m_cancel->setObjectName(QStringLiteral("feedCancel"));
    m_checkButton->setObjectName(QStringLiteral("feedCheck"));
    m_refine->setObjectName(QStringLiteral("feedRefine"));
    m_switch->setObjectName(QStringLiteral("feedSwitch"));
    m_save->setObjectName(QStringLiteral("feedSave"));
    m_level->setObjectName(QStringLiteral("feedLevel"));
    m_result->setObjectName(QStringLiteral("feedResult"));
    m_modelSummary->setObjectName(QStringLiteral("feedModelSummary"));
    m_views->setObjectName(QStringLiteral("feedViews"));
    m_checkButton->setProperty("role", QStringLiteral("primary"));

    m_modelSummary->setWordWrap(true);
    m_modelSummary->setStyleSheet(QStringLiteral("font-size: 12pt; color: #1f2a36;"));
    m_progress->setRange(0, 100);
    m_progress->setTextVisible(true);
    auto* sources = new QHBoxLayout;
    sources->addWidget(m_simulate, 1);
    sources->addWidget(m_fitCsv, 1);
    sources->addWidget(m_load, 1);
    auto* model = new QVBoxLayout(m_modelBox);
    model->setContentsMargins(8, 4, 8, 6);
    model->addWidget(m_modelSummary);
    model->addLayout(sources);

    auto* feeds = new QHBoxLayout;
    feeds->addWidget(m_feedMin);
    feeds->addWidget(new QLabel(QStringLiteral("–"), this));
    feeds->addWidget(m_feedMax);
    auto* zs = new QHBoxLayout;
    zs->addWidget(m_zStart);
    zs->addWidget(new QLabel(QStringLiteral("→"), this));
    zs->addWidget(m_zEnd);
    auto* form = new QFormLayout(m_passBox);
    form->setContentsMargins(8, 4, 8, 6);
    form->setVerticalSpacing(4);
    form->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
    form->addRow(m_depthLabel, m_depth);
    form->addRow(m_feedsLabel, feeds);
    // The switch rule beside the step it switches (a row of its own would make the page too tall for 800 px).
    auto* step = new QHBoxLayout;
    step->addWidget(m_feedStep);
    step->addWidget(m_switch, 1);
    form->addRow(m_feedStepLabel, step);
    form->addRow(m_zLabel, zs);
    form->addRow(m_minLengthLabel, m_minLength);
    form->addRow(m_dialectLabel, m_dialect);

    auto* left = new QVBoxLayout;
    left->addWidget(m_modelBox);
    left->addWidget(m_passBox);
    auto* check = new QHBoxLayout;
    check->addWidget(m_checkButton, 1);
    check->addWidget(m_refine, 1);
    left->addLayout(check);
    left->addWidget(m_save);
    left->addStretch(1);

    m_levelTitle->setStyleSheet(QStringLiteral("font-size: 14pt; font-weight: bold; color: #1f2a36;"));
    m_levelValue->setStyleSheet(QStringLiteral("font-size: 18pt; font-weight: bold; color: #c62828;"));
    m_level->setRange(0, kLevelSteps);
    m_level->setValue(kLevelSteps / 2);
    m_level->setMinimumHeight(44);
    m_level->setStyleSheet(QStringLiteral(
        "QSlider::groove:horizontal { height: 10px; background: #c9ced6; border-radius: 5px; }"
        "QSlider::handle:horizontal { width: 40px; margin: -16px 0; background: #c62828; border-radius: 8px; }"));
    for (QLabel* end : {m_levelLow, m_levelHigh})
        end->setStyleSheet(QStringLiteral("font-size: 11pt; color: #38434f;"));
    m_levelHigh->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_result->setWordWrap(true);
    m_result->setTextFormat(Qt::RichText);
    m_result->setStyleSheet(QStringLiteral("font-size: 12pt;"));
    auto* levelRow = new QHBoxLayout;
    levelRow->addWidget(m_levelTitle);
    levelRow->addWidget(m_levelValue);
    levelRow->addStretch(1);
    auto* sliderRow = new QHBoxLayout;
    sliderRow->addWidget(m_levelLow);
    sliderRow->addWidget(m_level, 1);
    sliderRow->addWidget(m_levelHigh);

    m_curves->setMinimumHeight(150);
    m_feeds->setMinimumHeight(120);
    m_curves->setLegendBelow(3);
    m_feeds->setLegendBelow(3);
    m_curves->setYTickCount(5);
    m_feeds->setYTickCount(3);
    auto* chartsPage = new QWidget(this);
    auto* charts = new QVBoxLayout(chartsPage);
    charts->setContentsMargins(0, 4, 0, 0);
    charts->addWidget(m_curves, 3);
    charts->addWidget(m_feeds, 2);
    m_views->addTab(chartsPage, QString());
    m_views->addTab(m_programView, QString());
    m_views->addTab(m_modelPanel, QString());

    auto* working = new QHBoxLayout;
    working->addWidget(m_progress, 1);
    working->addWidget(m_cancel);
    auto* right = new QVBoxLayout;
    right->addLayout(levelRow);
    right->addLayout(sliderRow);
    right->addLayout(working);
    right->addWidget(m_result);
    right->addWidget(m_views, 1);

    auto* leftPanel = new QWidget(this);
    leftPanel->setLayout(left);
    leftPanel->setFixedWidth(480);  // the paired spin boxes keep their digits in Russian
    auto* root = new QHBoxLayout(this);
    root->setContentsMargins(6, 6, 6, 6);
    root->addWidget(leftPanel);
    root->addSpacing(6);
    root->addLayout(right, 1);
}

void FeedScheduleTool::configureBoxes() {
    // The units (suffixes of the depth, the feed step and L_min) are set in retranslate().
    setBox(m_depth, 0.01, 20.0, 2, 0.1, QString());
    setBox(m_feedMin, 0.001, 5.0, 3, 0.01, QString());  // the unit is in the row's label
    setBox(m_feedMax, 0.001, 5.0, 3, 0.01, QString());
    setBox(m_feedStep, 0.0001, 1.0, 4, 0.001, QString());
    setBox(m_zStart, -10000.0, 10000.0, 1, 5.0, QString());
    setBox(m_zEnd, -10000.0, 10000.0, 1, 5.0, QString());
    for (QDoubleSpinBox* paired : {m_feedMin, m_feedMax, m_zStart, m_zEnd})
        paired->setMinimumWidth(110);
    m_feedStep->setMinimumWidth(112);
    // The switch rule shares the feed step's row: it yields its width to the label and the step (its full name is
    // in the list and the tool tip).
    m_switch->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_switch->setMinimumContentsLength(6);
    setBox(m_minLength, 0.0, 1000.0, 1, 1.0, QString());
    m_dialect->addItem(QString(), static_cast<int>(devices::GCodeDialect::Fanuc));
    m_dialect->addItem(QString(), static_cast<int>(devices::GCodeDialect::LinuxCnc));
    m_switch->addItem(QString(), static_cast<int>(core::FeedSwitchRule::AtLevel));
    m_switch->addItem(QString(), static_cast<int>(core::FeedSwitchRule::Centred));
    if (!m_preset) return;
    const core::FeedScheduleRequest& r = m_preset->request;
    for (auto [box, value] : {std::pair{m_depth, r.depthMm},
                              {m_feedMin, r.feedMinMmPerRev},
                              {m_feedMax, r.feedMaxMmPerRev},
                              {m_feedStep, r.feedStepMmPerRev},
                              {m_zStart, r.zStartMm},
                              {m_zEnd, r.zEndMm},
                              {m_minLength, r.minLengthMm}}) {
        const QSignalBlocker block(box);
        box->setValue(value);
    }
    const QSignalBlocker block(m_level);
    m_level->setValue(static_cast<int>(std::lround(r.levelFraction.value_or(0.5) * kLevelSteps)));
}

bool FeedScheduleTool::busy() const {
    return m_task->busy();
}

void FeedScheduleTool::setBusy(bool busy, const QString& what) {
    m_taskWhat = what;
    for (QWidget* w : std::initializer_list<QWidget*>{m_simulate, m_fitCsv, m_load, m_checkButton, m_refine})
        w->setEnabled(!busy);
    m_progress->setVisible(busy);
    m_cancel->setVisible(busy);
    if (busy) m_progress->setValue(0);
    m_progress->setFormat(what + QStringLiteral(" %p %"));
    if (!busy) showResult();
}

void FeedScheduleTool::simulateExperiments() {
    if (busy()) return;
    if (!m_preset) {
        m_context.prompt->warn(this, tr("Feed schedule"),
                               tr("The built-in set-up cannot be read: %1").arg(m_presetProblem));
        return;
    }
    m_taskError.clear();
    setBusy(true, tr("Experiments on the simulator"));
    m_task->simulateAndFit(*m_preset, kPreset, m_modelPanel->termSet(), m_modelPanel->stepwise());
}

void FeedScheduleTool::fitCsvFile() {
    if (busy()) return;
    const QString path = m_context.prompt->openFileName(this, tr("Experiment to fit"), tr("CSV files (*.csv)"));
    if (path.isEmpty()) return;
    m_taskError.clear();
    setBusy(true, tr("Fitting"));
    m_task->fitCsv(path, m_modelPanel->termSet(), m_modelPanel->stepwise());
}

void FeedScheduleTool::loadModelFile() {
    if (busy()) return;
    const QString path = m_context.prompt->openFileName(this, tr("Model file"), tr("Model files (*.json)"));
    if (path.isEmpty()) return;
    QFile file(path);
    try {
        if (!file.open(QIODevice::ReadOnly)) throw std::runtime_error(file.errorString().toStdString());
        const QJsonDocument doc = QJsonDocument::fromJson(file.readAll());
        if (!doc.isObject()) throw std::runtime_error("the file is not a JSON object");
        useModel(config::deformationModelFromJson(doc.object()));
    } catch (const std::exception& e) {
        m_context.prompt->warn(
            this, tr("Model file"),
            tr("%1 cannot be used: %2").arg(QFileInfo(path).fileName(), QString::fromStdString(e.what())));
    }
}

void FeedScheduleTool::checkOnSimulator() {
    if (busy() || !m_schedule || !m_modelSetup) return;
    m_taskError.clear();
    setBusy(true, tr("Machining on the simulator"));
    m_task->check(m_modelSetup->lathe, *m_schedule, request());
}

void FeedScheduleTool::refineModel() {
    if (busy() || !m_schedule || !m_modelSetup || !m_model || !checkMisses()) return;
    m_taskError.clear();
    // The fitted model and its measurements at this depth: the refinement starts from them.
    const FeedRefineJob job{m_modelSetup->lathe,
                            *m_model,
                            m_samples.value_or(core::DeformationSamples{}),
                            request(),
                            core::FeedRefinementOptions{},
                            m_model->seed.value_or(1)};
    setBusy(true, tr("Refining the model"));
    m_task->refine(job);
}

void FeedScheduleTool::showRefineProgress(int round, int barsDone, int bars) {
    if (!busy()) return;
    m_progress->setFormat(tr("Refining: round %1, bar %2 of %3").arg(round).arg(barsDone).arg(bars) +
                          QStringLiteral(" (%p %)"));
}

bool FeedScheduleTool::checkMisses() const {
    return m_check && m_check->maxDeviationPct > core::kFeedScheduleTolerancePct;
}

void FeedScheduleTool::taskDone(const FeedTaskResult& result, bool cancelled) {
    m_taskError = cancelled ? tr("Stopped.") : result.error;
    if (result.model) {
        m_samples = result.samples;
        useModel(*result.model);
    }
    if (result.check) m_check = result.check;
    if (result.refinement) {
        m_refinement = result.refinement;
        m_refinedModel = result.refinedModel;
        m_refinedFor = request();
        reschedule();  // on the refined model: the schedule of its last round
        const core::FeedRefinementRound* last = m_refinement->lastScheduled();
        m_check = last ? last->check : m_refinement->initialCheck;
        if (!last) m_refinedFor.reset();
        showSchedule();
    }
    setBusy(false, QString());
    emit taskFinished();
}

const config::DeformationModelFile* FeedScheduleTool::activeModel() const {
    if (m_refinedModel && m_refinedFor) {
        const core::FeedScheduleRequest r = request();
        const core::FeedScheduleRequest& f = *m_refinedFor;
        if (r.depthMm == f.depthMm && r.feedMinMmPerRev == f.feedMinMmPerRev &&
            r.feedMaxMmPerRev == f.feedMaxMmPerRev && r.zStartMm == f.zStartMm && r.zEndMm == f.zEndMm)
            return &*m_refinedModel;
    }
    return m_model ? &*m_model : nullptr;
}

void FeedScheduleTool::useModel(config::DeformationModelFile file) {
    m_model = std::move(file);
    m_refinedModel.reset();
    m_refinedFor.reset();
    m_refinement.reset();
    m_modelSetup.reset();
    if (!m_model->preset.isEmpty()) {
        try {
            m_modelSetup = config::feedSchedulingSetupFromPreset(config::PresetLibrary::load(m_model->preset));
        } catch (const std::exception&) {
            // A set-up that is not a simulator preset: no check on the simulator for this model.
        }
    }
    // The pass must stay inside the model's fitted range (the scheduler refuses anything outside it).
    const core::DeformationModel& m = m_model->model;
    const auto limit = [](QDoubleSpinBox* box, const core::FactorCoding& c) {
        const QSignalBlocker block(box);
        box->setRange(c.min, c.max);
    };
    limit(m_depth, m.coding(core::DeformationFactor::Depth));
    limit(m_feedMin, m.coding(core::DeformationFactor::Feed));
    limit(m_feedMax, m.coding(core::DeformationFactor::Feed));
    limit(m_zStart, m.coding(core::DeformationFactor::Axial));
    limit(m_zEnd, m.coding(core::DeformationFactor::Axial));
    m_modelPanel->showModel(&*m_model);
    showModelSummary();
    reschedule();
}

core::FeedScheduleRequest FeedScheduleTool::request() const {
    core::FeedScheduleRequest r;
    r.depthMm = m_depth->value();
    r.feedMinMmPerRev = m_feedMin->value();
    r.feedMaxMmPerRev = m_feedMax->value();
    r.feedStepMmPerRev = m_feedStep->value();
    r.zStartMm = m_zStart->value();
    r.zEndMm = m_zEnd->value();
    r.levelFraction = static_cast<double>(m_level->value()) / kLevelSteps;
    r.minLengthMm = m_minLength->value();
    r.switchRule = static_cast<core::FeedSwitchRule>(m_switch->currentData().toInt());
    return r;
}

void FeedScheduleTool::setLevelFraction(double fraction) {
    m_level->setValue(static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * kLevelSteps)));
}

void FeedScheduleTool::reschedule() {
    m_schedule.reset();
    m_times.reset();
    m_check.reset();  // a check belongs to the schedule it was made for
    m_problem.clear();
    if (const config::DeformationModelFile* model = activeModel()) {
        m_modelPanel->showModel(model);
        showModelSummary();
        try {
            m_schedule = core::scheduleFeed(model->model, request());
            if (model->job) m_times = core::machiningTimes(*m_schedule, request(), model->job->spindleRpm);
        } catch (const std::exception& e) {
            m_problem = QString::fromStdString(e.what());
        }
    }
    showSchedule();
}

void FeedScheduleTool::showSchedule() {
    plotCurves();
    plotFeeds();
    updateProgram();
    showResult();
}

void FeedScheduleTool::plotCurves() {
    m_curves->clear();
    m_curves->setTitle(
        tr("Deformation Y; the tool travels z %1 → %2 mm").arg(fixed(m_zStart->value(), 0), fixed(m_zEnd->value(), 0)));
    const config::DeformationModelFile* active = activeModel();
    if (!active) return;
    const core::DeformationModel& model = active->model;
    const core::FeedScheduleRequest r = request();
    double lo = std::min(r.zStartMm, r.zEndMm);
    double hi = std::max(r.zStartMm, r.zEndMm);
    if (!(hi > lo)) {  // no pass to draw along: the model's whole range
        lo = model.coding(core::DeformationFactor::Axial).min;
        hi = model.coding(core::DeformationFactor::Axial).max;
    }
    std::vector<double> z(kCurvePoints);
    for (int i = 0; i < kCurvePoints; ++i)
        z[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / (kCurvePoints - 1);
    for (int k = 0; k < kFamily; ++k) {
        const double f = r.feedMinMmPerRev + (r.feedMaxMmPerRev - r.feedMinMmPerRev) * k / (kFamily - 1);
        std::vector<double> y(z.size());
        for (std::size_t i = 0; i < z.size(); ++i)
            y[i] = model.deformationUm(r.depthMm, f, z[i]);
        m_curves->setSeries(QStringLiteral("family%1").arg(k), tr("%1 mm/rev").arg(fixed(f, 3)), z, y, familyColor(k));
    }
    if (m_schedule) {
        m_curves->setSeries(QStringLiteral("level"), tr("Yc"), {lo, hi}, {m_schedule->levelUm, m_schedule->levelUm},
                            kLevelColor);
        std::vector<double> sz;
        std::vector<double> sy;
        for (const core::FeedSegment& s : m_schedule->segments) {
            for (int i = 0; i <= 8; ++i) {
                const double zz = s.zFromMm + (s.zToMm - s.zFromMm) * i / 8.0;
                sz.push_back(zz);
                sy.push_back(model.deformationUm(r.depthMm, s.feedMmPerRev, zz));
            }
        }
        m_curves->setSeries(QStringLiteral("scheduled"), tr("scheduled"), sz, sy, kScheduleColor);
    }
    m_curves->rescale(false);
    if (m_schedule) {
        // Around the level: where the curves cross Yc (the breakpoints) and the scheduled Y below it.
        m_curves->setYRange(0.6 * m_schedule->y1Um, 1.4 * m_schedule->y2Um);
    }
    m_curves->refresh();
}

void FeedScheduleTool::plotFeeds() {
    m_feeds->clear();
    if (!m_schedule) return;
    // The staircase: each segment's feed from its start to its end, a vertical step at each breakpoint.
    std::vector<double> z;
    std::vector<double> f;
    for (const core::FeedSegment& s : m_schedule->segments) {
        z.push_back(s.zFromMm);
        f.push_back(s.feedMmPerRev);
        z.push_back(s.zToMm);
        f.push_back(s.feedMmPerRev);
    }
    m_feeds->setSeries(QStringLiteral("feed"), tr("scheduled feed"), z, f, kFeedColor);
    const core::FeedScheduleRequest r = request();
    const double lo = std::min(r.zStartMm, r.zEndMm);
    const double hi = std::max(r.zStartMm, r.zEndMm);
    m_feeds->setSeries(QStringLiteral("fmin"), tr("fmin"), {lo, hi}, {r.feedMinMmPerRev, r.feedMinMmPerRev},
                       QColor(120, 120, 120));
    m_feeds->setSeries(QStringLiteral("fmax"), tr("fmax"), {lo, hi}, {r.feedMaxMmPerRev, r.feedMaxMmPerRev},
                       QColor(60, 60, 60));
    m_feeds->rescale(true);
    m_feeds->refresh();
}

void FeedScheduleTool::updateProgram() {
    m_program.clear();
    const config::DeformationModelFile* active = activeModel();
    if (m_schedule && active && active->job) {
        devices::FeedPassJob job = *active->job;
        job.depthMm = m_depth->value();
        job.dialect = static_cast<devices::GCodeDialect>(m_dialect->currentData().toInt());
        try {
            m_program = QString::fromStdString(
                devices::writeFeedScheduleGCode(config::feedPassProgram(*m_schedule, request(), *active), job));
        } catch (const std::exception& e) {
            m_problem = QString::fromStdString(e.what());
        }
    }
    m_programView->setProgram(m_program);
    m_save->setEnabled(!m_program.isEmpty());
}

bool FeedScheduleTool::saveProgram() {
    if (m_program.isEmpty()) return false;
    const QString suggested = QStringLiteral("O%1.nc").arg(m_model->job->programNumber, 4, 10, QLatin1Char('0'));
    const QString path =
        m_context.prompt->saveFileName(this, tr("Save the CNC program"), suggested, tr("CNC programs (*.nc *.txt)"));
    if (path.isEmpty()) return false;
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(m_program.toLatin1()) < 0) {
        m_context.prompt->warn(this, tr("Save the CNC program"),
                               tr("%1 cannot be written: %2").arg(path, file.errorString()));
        return false;
    }
    m_context.prompt->inform(this, tr("Save the CNC program"), tr("The program was written to %1.").arg(path));
    return true;
}

void FeedScheduleTool::showModelSummary() {
    if (!m_model) {
        m_modelSummary->setText(m_presetProblem.isEmpty()
                                    ? tr("No model yet.")
                                    : tr("The built-in set-up cannot be read: %1").arg(m_presetProblem));
        return;
    }
    const config::DeformationModelFile* active = activeModel();
    const config::DeformationModelStatistics& s = active->statistics;
    QString source = m_model->sourceFile == QStringLiteral("simulated")
                         ? tr("Simulated experiments (%1)").arg(m_model->preset)
                         : m_model->sourceFile;
    if (active != &*m_model)
        source = tr("Refined at a = %1 mm (%2, test bars added: %3)")
                     .arg(fixed(active->model.coding(core::DeformationFactor::Depth).centre, 2), source)
                     .arg(m_refinement ? m_refinement->barCount() : 0);
    m_modelSummary->setText(tr("%1: %2 points, %3 terms. R² %4, F %5 (table %6), 2σ %7 µm.")
                                .arg(source)
                                .arg(s.pointCount)
                                .arg(s.termCount)
                                .arg(fixed(s.r2, 4), QLocale().toString(s.fStatistic, 'g', 4),
                                     QLocale().toString(s.fCritical95, 'g', 3), fixed(s.twoSigmaUm(), 2)));
}

QString FeedScheduleTool::refinementLine() const {
    const core::FeedRefinement& r = *m_refinement;
    QString line = tr("Refined in %n round(s): test bars %1, gauge points %2; before, the pass was %3 % off Yc.", "",
                      static_cast<int>(r.rounds.size()))
                       .arg(r.barCount())
                       .arg(r.gaugePointCount())
                       .arg(fixed(r.initialCheck.maxDeviationPct, 1));
    if (!r.advice.empty())
        line += QLatin1Char(' ') + tr("The feed step alone leaves the band: try the centred switch.");
    return line;
}

void FeedScheduleTool::showResult() {
    m_checkButton->setEnabled(!busy() && m_schedule && m_modelSetup);
    const bool refinedActive = m_model && activeModel() != &*m_model;
    m_refine->setEnabled(!busy() && m_schedule && m_modelSetup && checkMisses() && !refinedActive);
    if (m_schedule) {
        m_levelValue->setText(tr("%1 µm").arg(fixed(m_schedule->levelUm, 2)));
        m_levelLow->setText(tr("Y1 %1 µm\nquality").arg(fixed(m_schedule->y1Um, 1)));
        m_levelHigh->setText(tr("Y2 %1 µm\noutput").arg(fixed(m_schedule->y2Um, 1)));
    } else {
        m_levelValue->setText(tr("– µm"));
        m_levelLow->setText(tr("Y1\nquality"));
        m_levelHigh->setText(tr("Y2\noutput"));
    }
    QStringList lines;
    if (!m_taskError.isEmpty())
        lines << QStringLiteral("<span style='color:#c62828'>%1</span>").arg(m_taskError.toHtmlEscaped());
    if (!m_problem.isEmpty())
        lines << QStringLiteral("<span style='color:#c62828'>%1</span>").arg(m_problem.toHtmlEscaped());
    if (m_schedule) {
        QString line =
            tr("<b>%n segment(s)</b>, feeds %1 → %2 mm/rev.", "", static_cast<int>(m_schedule->segments.size()))
                .arg(fixed(m_schedule->segments.front().feedMmPerRev, 4),
                     fixed(m_schedule->segments.back().feedMmPerRev, 4));
        if (m_times)
            line += QLatin1Char(' ') + tr("Time %1 min against %2 min at fmin: <b>%3 % saved</b> (fmax %4 min).")
                                           .arg(minutes(m_times->scheduleS), minutes(m_times->feedMinS),
                                                fixed(m_times->savedVsFeedMinPct(), 0), minutes(m_times->feedMaxS));
        else
            line += QLatin1Char(' ') + tr("The model names no machine job (spindle speed): no times, no program.");
        lines << line;
    }
    if (refinedActive && m_refinement) lines << refinementLine();
    if (checkMisses())
        lines << QStringLiteral("<span style='color:#c62828'>%1</span>")
                     .arg(tr("Simulator: <b>%1 %</b> off Yc at z %2 mm, outside ±10 %.")
                              .arg(fixed(m_check->maxDeviationPct, 1), fixed(m_check->worstZMm, 1)));
    else if (m_check)
        lines << tr("Simulator: within <b>%1 %</b> of Yc (worst at z %2 mm); constant fmax exceeds Yc by %3 %.")
                     .arg(fixed(m_check->maxDeviationPct, 1), fixed(m_check->worstZMm, 1),
                          fixed(m_check->feedMaxExcessPct, 0));
    if (checkMisses() && !refinedActive)
        lines << tr("Refine runs a targeted experiment at this depth, refits the model and checks again.");
    else if (m_schedule && !m_modelSetup)
        lines << tr("No simulator for this model's set-up: the check is not available.");
    m_result->setText(lines.join(QStringLiteral("<br>")));
}

void FeedScheduleTool::retranslate() {
    m_modelBox->setTitle(tr("Force-deformation model Y(a, f, z)"));
    m_simulate->setText(tr("Simulate"));
    m_simulate->setToolTip(tr("Run the experiments on the simulator and fit the model"));
    m_fitCsv->setText(tr("Fit CSV…"));
    m_load->setText(tr("Load…"));
    m_load->setToolTip(tr("Load a model file written by 'trueturn fit-deformation --json'"));
    m_cancel->setText(tr("Cancel"));
    m_passBox->setTitle(tr("Pass"));
    m_depthLabel->setText(tr("Depth of cut a"));
    m_depth->setSuffix(tr(" mm"));
    m_minLength->setSuffix(tr(" mm"));
    m_feedsLabel->setText(tr("Feeds, mm/rev"));
    m_feedStepLabel->setText(tr("Feed step, mm/rev"));
    m_zLabel->setText(tr("Pass z, mm"));
    m_minLengthLabel->setText(tr("Shortest segment"));
    m_dialectLabel->setText(tr("CNC dialect"));
    m_dialect->setItemText(0, tr("Fanuc-style"));
    m_dialect->setItemText(1, tr("LinuxCNC"));
    m_checkButton->setText(tr("Check on simulator"));
    m_refine->setText(tr("Refine"));
    m_refine->setToolTip(tr("Machine targeted bars on the simulator, refit the model at this depth and check again"));
    m_switch->setToolTip(
        tr("Where a feed step switches to the next: where the next feed reaches Yc (the paper), "
           "or where the two feeds' mean is Yc (half the deviation)"));
    m_switch->setItemText(0, tr("at Yc (paper)"));
    m_switch->setItemText(1, tr("centred on Yc"));
    m_save->setText(tr("Save program…"));
    m_levelTitle->setText(tr("Level Yc"));
    m_curves->setAxisTitles(tr("z, mm"), tr("Y, µm"));
    m_feeds->setAxisTitles(tr("z, mm"), tr("f, mm/rev"));
    m_views->setTabText(0, tr("Curves"));
    m_views->setTabText(1, tr("CNC program"));
    m_views->setTabText(2, tr("Model statistics"));
    m_modelPanel->retranslate();
    showModelSummary();
    plotCurves();
    plotFeeds();
    showResult();
}

}  // namespace tt::ui
