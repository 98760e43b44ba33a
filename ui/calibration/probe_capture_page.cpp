#include "ui/calibration/probe_capture_page.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include "ui/calibration/chart_ranges.h"
#include "ui/calibration/probe_wizard_context.h"
#include "ui/calibration/procedure_words.h"
#include "plot/chart.h"

namespace tt::ui {

namespace {
const QColor kProblemColour(0xb7, 0x1c, 0x1c);
}

ProbeCapturePage::ProbeCapturePage(ProbeWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_timer(new QTimer(this)),
      m_live(new QLabel(this)),
      m_jackLabel(new QLabel(this)),
      m_jack(new QDoubleSpinBox(this)),
      m_setJack(new QPushButton(this)),
      m_referenceLabel(new QLabel(this)),
      m_reference(new QDoubleSpinBox(this)),
      m_capture(new QPushButton(this)),
      m_repeat(new QPushButton(this)),
      m_codeLabel(new QLabel(this)),
      m_code(new QDoubleSpinBox(this)),
      m_typed(new QPushButton(this)),
      m_progress(new QProgressBar(this)),
      m_remove(new QPushButton(this)),
      m_table(new QTableWidget(0, 3, this)),
      m_chart(new plot::Chart(this)),
      m_message(wrappedLabel(this)) {
    setUpControls();
    buildLayout();

    m_timer->setInterval(kPollMs);
    connect(m_timer, &QTimer::timeout, this, [this] {
        if (isShown()) pollProbe();
    });
    connect(m_setJack, &QPushButton::clicked, this, [this] { setJack(m_jack->value()); });
    connect(m_capture, &QPushButton::clicked, this, [this] {
        if (capturing())
            abortCapture();
        else
            capturePoint();
    });
    connect(m_repeat, &QPushButton::clicked, this, &ProbeCapturePage::repeatPoint);
    connect(m_typed, &QPushButton::clicked, this, &ProbeCapturePage::addTypedPoint);
    connect(m_remove, &QPushButton::clicked, this, &ProbeCapturePage::removePoint);
}

void ProbeCapturePage::setUpControls() {
    m_live->setObjectName(QStringLiteral("liveCode"));
    m_live->setStyleSheet(QStringLiteral("font-size: 18pt; font-weight: bold;"));
    m_jack->setObjectName(QStringLiteral("jackSpin"));
    m_reference->setObjectName(QStringLiteral("referenceSpin"));
    m_code->setObjectName(QStringLiteral("typedCodeSpin"));
    m_capture->setObjectName(QStringLiteral("capturePoint"));
    m_capture->setProperty("role", QStringLiteral("primary"));
    m_repeat->setObjectName(QStringLiteral("repeatPoint"));
    m_typed->setObjectName(QStringLiteral("addTypedPoint"));
    m_remove->setObjectName(QStringLiteral("removePoint"));
    m_progress->setObjectName(QStringLiteral("captureProgress"));
    m_table->setObjectName(QStringLiteral("capturedPoints"));
    m_message->setObjectName(QStringLiteral("captureMessage"));
    for (QDoubleSpinBox* s : {m_jack, m_reference}) {
        s->setRange(-2000.0, 2000.0);
        s->setDecimals(1);
        s->setMinimumWidth(150);
    }
    m_jack->setSingleStep(50.0);
    m_code->setRange(0.0, 65535.0);
    m_code->setDecimals(1);
    m_code->setMinimumWidth(150);
    m_progress->setRange(0, 100);
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(14);
    m_table->verticalHeader()->setDefaultSectionSize(40);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setVisible(false);
    m_table->setMinimumWidth(420);
    m_chart->setMinimumSize(340, 300);
    m_chart->setLegendCorner(Qt::AlignTop | Qt::AlignLeft);  // the curve rises to the top right
}

void ProbeCapturePage::buildLayout() {
    auto* entry = new QGridLayout;
    entry->addWidget(m_jackLabel, 0, 0);
    entry->addWidget(m_jack, 0, 1);
    entry->addWidget(m_setJack, 0, 2);
    entry->addWidget(m_referenceLabel, 1, 0);
    entry->addWidget(m_reference, 1, 1);
    entry->addWidget(m_capture, 1, 2);
    entry->addWidget(m_codeLabel, 2, 0);
    entry->addWidget(m_code, 2, 1);
    entry->addWidget(m_typed, 2, 2);
    auto* left = new QVBoxLayout;
    left->addWidget(m_live);
    left->addLayout(entry);
    left->addWidget(m_progress);
    layOutCapturePage(this, left, m_table, {m_repeat, m_remove}, m_chart, m_message);
}

void ProbeCapturePage::initializePage() {
    m_ctx.procedure().returnToCapture();
    DeviceCalibrationProbe* p = m_ctx.probe();
    const bool jack = p && p->hasJack();
    m_jackLabel->setVisible(jack);
    m_jack->setVisible(jack);
    m_setJack->setVisible(jack);
    const core::ProbeProcedureConfig& c = m_ctx.procedure().config();
    m_reference->setSingleStep(c.referenceDivisionUm);
    m_code->setMaximum(std::ldexp(1.0, c.adcBits) - 1.0);
    refreshPoints();
    retranslate();
    m_timer->start();
}

void ProbeCapturePage::cleanupPage() {
    m_timer->stop();  // Back: the points stay in the session
    m_ctx.procedure().abort();
    m_ctx.procedure().takeEvents();
}

bool ProbeCapturePage::isComplete() const {
    return m_ctx.procedure().canFit();
}

bool ProbeCapturePage::capturing() const {
    return m_ctx.procedure().capturing();
}

std::optional<double> ProbeCapturePage::liveCode() const {
    return m_ctx.procedure().sampling().liveCode();
}

void ProbeCapturePage::pollProbe(double elapsedS) {
    m_ctx.pumpProbe(elapsedS);
    handleEvents();
    refreshState();
}

void ProbeCapturePage::refreshState() {
    const core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    const core::ProbeCapture& sampling = proc.sampling();
    DeviceCalibrationProbe* p = m_ctx.probe();
    const core::DeviceHealth h = p ? p->port().health() : core::DeviceHealth{};
    const std::optional<double> code = sampling.liveCode();
    if (!p)
        m_live->setText(tr("No probe: type the points"));
    else if (!h.ready())
        m_live->setText(tr("Probe: %1").arg(QString::fromStdString(h.message)));
    else if (code)
        m_live->setText((sampling.liveSaturated() ? tr("Live ADC code %1 (mean of %2) — at the ADC's limit")
                                                  : tr("Live ADC code %1 (mean of %2)"))
                            .arg(*code, 0, 'f', 1)
                            .arg(sampling.liveSamples()));
    else
        m_live->setText(tr("Waiting for probe samples…"));
    markProblem(m_live, p && (!h.ready() || sampling.liveSaturated()));
    if (proc.capturing()) {
        m_progress->setValue(static_cast<int>(std::lround(100.0 * sampling.progress())));
        showMessage(sampling.phase() == core::ProbeCapture::Phase::HoldStill
                        ? tr("Hold still: the bar settles…")
                        : tr("Averaging the live codes at %1 µm…").arg(sampling.referenceUm(), 0, 'f', 1),
                    false);
    }
    m_capture->setText(proc.capturing() ? tr("Stop") : tr("Capture point"));
    m_capture->setEnabled(p != nullptr);
    for (QWidget* w : std::initializer_list<QWidget*>{m_repeat, m_typed, m_remove, m_setJack})
        w->setEnabled(!proc.capturing());
    m_repeat->setEnabled(p && !proc.capturing() && !proc.points().empty());
    if (code)
        m_chart->setSeries(QStringLiteral("live"), tr("now"), {m_reference->value()}, {*code}, QColor(0xf0, 0xa0, 0x30),
                           plot::Chart::Style::Points);
    else
        m_chart->removeSeries(QStringLiteral("live"));  // no stale "now" while the probe is silent
    m_chart->refresh();
}

void ProbeCapturePage::handleEvents() {
    const core::ProbeProcedureConfig& c = m_ctx.procedure().config();
    bool changed = false;
    for (const core::ProbeEvent& e : m_ctx.procedure().takeEvents()) {
        const bool problem = e.kind == core::ProbeEvent::Kind::CaptureFailed || e.value.saturated;
        const QString text = ProcedureWords::probeEvent(e, c.adcBits, c.capture.noSampleTimeoutS);
        if (!text.isEmpty()) showMessage(text, problem);
        changed = true;
    }
    if (!changed) return;
    m_progress->setValue(0);
    refreshPoints();
}

void ProbeCapturePage::showMessage(const QString& text, bool problem) {
    m_message->setText(text);
    markProblem(m_message, problem);
}

QString ProbeCapturePage::message() const {
    return m_message->text();
}

void ProbeCapturePage::setJack(double um) {
    DeviceCalibrationProbe* p = m_ctx.probe();
    if (!p || !p->hasJack() || capturing()) return;
    m_jack->setValue(um);
    pollProbe(0.0);  // the samples queued so far were read under the old load
    try {
        p->bendBar(m_ctx.procedure().config().plane, um / 1000.0);
    } catch (const std::invalid_argument&) {
        showMessage(tr("The jack bends the bar by at most ±2000 µm."), true);
        return;
    }
    // The dial indicator shows the deflection to its division.
    const double division = m_ctx.procedure().config().referenceDivisionUm;
    m_reference->setValue(std::round(um / division) * division);
    m_ctx.procedure().loadChanged();  // the live mean restarts at the new load
    handleEvents();
    showMessage(tr("The jack bends the bar to %1 µm; capture when the live code is steady.").arg(um, 0, 'f', 1), false);
}

void ProbeCapturePage::setReferenceUm(double um) {
    m_reference->setValue(um);
}

void ProbeCapturePage::setTypedCode(double code) {
    m_code->setValue(code);
}

void ProbeCapturePage::selectPoint(int row) {
    m_table->selectRow(row);
}

bool ProbeCapturePage::capturePoint() {
    if (!m_ctx.probe() || capturing()) {
        showMessage(tr("No probe mandrel to read: type the point instead."), true);
        return false;
    }
    pollProbe(0.0);  // samples queued before the press are not the point's
    m_ctx.procedure().capture(m_reference->value());
    refreshState();
    emit completeChanged();
    return true;
}

bool ProbeCapturePage::repeatPoint() {
    const int row = selectedRowOrLast(m_table, static_cast<int>(m_ctx.procedure().points().size()));
    if (!m_ctx.probe() || capturing() || row < 0) return false;
    pollProbe(0.0);
    m_ctx.procedure().repeatPoint(row, m_reference->value());
    refreshState();
    emit completeChanged();
    return true;
}

void ProbeCapturePage::abortCapture() {
    m_ctx.procedure().abort();
    handleEvents();
    refreshState();
    emit completeChanged();
}

bool ProbeCapturePage::addTypedPoint() {
    if (capturing()) return false;
    try {
        m_ctx.procedure().typePoint(m_reference->value(), m_code->value());
    } catch (const std::invalid_argument&) {
        showMessage(tr("The typed code is outside the ADC's range."), true);
        return false;
    }
    handleEvents();
    return true;
}

void ProbeCapturePage::removePoint() {
    const int row = selectedRowOrLast(m_table, static_cast<int>(m_ctx.procedure().points().size()));
    if (capturing() || row < 0) return;
    m_ctx.procedure().removePoint(row);
    handleEvents();
}

void ProbeCapturePage::refreshPoints() {
    const std::vector<core::ProbePoint>& points = m_ctx.procedure().points();
    const int adcBits = m_ctx.procedure().config().adcBits;
    m_table->setRowCount(static_cast<int>(points.size()));
    std::vector<double> xs, ys, sx, sy;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const core::ProbePoint& p = points[i];
        const int row = static_cast<int>(i);
        QString source = p.samples > 0 ? tr("live, %1 samples").arg(p.samples) : tr("typed");
        if (p.saturated)
            source = tr("%1 — ADC saturated (%2 to %3 of 0 to %4), not used")
                         .arg(source)
                         .arg(p.lowestCode)
                         .arg(p.highestCode)
                         .arg(static_cast<long long>(std::ldexp(1.0, adcBits)) - 1);
        m_table->setItem(row, 0, new QTableWidgetItem(QString::number(p.referenceUm, 'f', 1)));
        m_table->setItem(row, 1, new QTableWidgetItem(QString::number(p.adcCode, 'f', 1)));
        m_table->setItem(row, 2, new QTableWidgetItem(source));
        for (int c = 0; c < 3; ++c) {
            if (c < 2) m_table->item(row, c)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            if (p.saturated) m_table->item(row, c)->setForeground(kProblemColour);
        }
        (p.saturated ? sx : xs).push_back(p.referenceUm);
        (p.saturated ? sy : ys).push_back(p.adcCode);
    }
    m_chart->setSeries(QStringLiteral("points"), tr("captured"), xs, ys, QColor(0x1f, 0x5f, 0xa8),
                       plot::Chart::Style::Points);
    if (sx.empty())
        m_chart->removeSeries(QStringLiteral("saturated"));
    else
        m_chart->setSeries(QStringLiteral("saturated"), tr("ADC saturated"), sx, sy, kProblemColour,
                           plot::Chart::Style::Points);
    std::vector<double> allX = xs, allY = ys;
    allX.insert(allX.end(), sx.begin(), sx.end());
    allY.insert(allY.end(), sy.begin(), sy.end());
    showAllWithMargin(*m_chart, allX, allY, false, 0.3);
    m_table->resizeColumnsToContents();
    refreshState();
    emit completeChanged();
}

void ProbeCapturePage::retranslate() {
    setTitle(tr("Capture points"));
    setSubTitle(
        tr("Load the bar, read the instrument, capture: the bar holds still, then the codes are averaged. At least "
           "%1 points; both directions.")
            .arg(m_ctx.procedure().config().minPoints));
    m_jackLabel->setText(tr("Stand's screw jack"));
    m_setJack->setText(tr("Bend the bar"));
    m_referenceLabel->setText(tr("Reference reading"));
    for (QDoubleSpinBox* s : {m_jack, m_reference})
        s->setSuffix(tr(" µm"));
    m_repeat->setText(tr("Repeat point"));
    m_codeLabel->setText(tr("ADC code (typed)"));
    m_typed->setText(tr("Add typed point"));
    m_remove->setText(tr("Remove point"));
    m_table->setHorizontalHeaderLabels({tr("Reference, µm"), tr("ADC code"), tr("Source")});
    m_chart->setTitle(tr("ADC code against the reference deflection"));
    m_chart->setAxisTitles(tr("Reference deflection, µm"), tr("ADC code"));
    if (m_message->text().isEmpty()) showMessage(tr("Captured points stay here when you go back or cancel."), false);
    refreshPoints();
}

}  // namespace tt::ui
