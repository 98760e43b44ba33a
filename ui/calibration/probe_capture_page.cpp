#include "ui/calibration/probe_capture_page.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include "ui/calibration/chart_ranges.h"
#include "ui/calibration/probe_wizard.h"
#include "ui/plot/chart.h"

namespace tt::ui {

namespace {
constexpr std::size_t kLiveWindow = 50;  ///< codes averaged for a captured point (0.5 s at 100 Hz)
constexpr std::size_t kMinLiveSamples = 10;
constexpr int kPollMs = 100;
}  // namespace

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
      m_codeLabel(new QLabel(this)),
      m_code(new QDoubleSpinBox(this)),
      m_capture(new QPushButton(this)),
      m_typed(new QPushButton(this)),
      m_remove(new QPushButton(this)),
      m_table(new QTableWidget(0, 3, this)),
      m_chart(new Chart(this)),
      m_message(new QLabel(this)) {
    m_live->setObjectName(QStringLiteral("liveCode"));
    m_live->setStyleSheet(QStringLiteral("font-size: 18pt; font-weight: bold;"));
    m_jack->setObjectName(QStringLiteral("jackSpin"));
    m_reference->setObjectName(QStringLiteral("referenceSpin"));
    m_code->setObjectName(QStringLiteral("typedCodeSpin"));
    m_capture->setObjectName(QStringLiteral("capturePoint"));
    m_capture->setProperty("role", QStringLiteral("primary"));
    m_typed->setObjectName(QStringLiteral("addTypedPoint"));
    m_remove->setObjectName(QStringLiteral("removePoint"));
    m_table->setObjectName(QStringLiteral("capturedPoints"));
    m_message->setObjectName(QStringLiteral("captureMessage"));
    m_message->setWordWrap(true);
    for (QDoubleSpinBox* s : {m_jack, m_reference}) {
        s->setRange(-5000.0, 5000.0);
        s->setDecimals(1);
        s->setMinimumWidth(170);
    }
    m_jack->setSingleStep(50.0);
    m_code->setRange(0.0, 65535.0);
    m_code->setDecimals(1);
    m_code->setMinimumWidth(170);
    m_table->verticalHeader()->setDefaultSectionSize(40);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setVisible(false);
    m_table->setMinimumWidth(420);
    m_chart->setMinimumSize(480, 320);

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
    layOutCapturePage(this, left, m_table, m_remove, m_chart, m_message);

    m_timer->setInterval(kPollMs);
    connect(m_timer, &QTimer::timeout, this, [this] { pollProbe(kPollMs / 1000.0); });
    connect(m_setJack, &QPushButton::clicked, this, [this] { setJack(m_jack->value()); });
    connect(m_capture, &QPushButton::clicked, this, &ProbeCapturePage::capturePoint);
    connect(m_typed, &QPushButton::clicked, this, &ProbeCapturePage::addTypedPoint);
    connect(m_remove, &QPushButton::clicked, this, &ProbeCapturePage::removePoint);
}

void ProbeCapturePage::initializePage() {
    CalibrationProbe* p = m_ctx.probe();
    const bool jack = p && p->hasJack();
    m_jackLabel->setVisible(jack);
    m_jack->setVisible(jack);
    m_setJack->setVisible(jack);
    m_reference->setSingleStep(m_ctx.session->resolutionUm);
    m_code->setMaximum(std::ldexp(1.0, m_ctx.session->adcBits) - 1.0);
    m_codes.clear();
    refreshPoints();
    retranslate();
    m_timer->start();
}

void ProbeCapturePage::cleanupPage() {
    m_timer->stop();  // Back: the points stay in the session
}

bool ProbeCapturePage::isComplete() const {
    return static_cast<int>(m_ctx.session->points.size()) >= kMinPoints;
}

void ProbeCapturePage::pollProbe(double seconds) {
    CalibrationProbe* p = m_ctx.probe();
    if (!p) return;
    p->poll(seconds);
    const std::size_t plane = static_cast<std::size_t>(m_ctx.session->plane);
    while (const std::optional<core::ProbeSample> s = p->port().takeSample()) {
        m_codes.push_back(s->adcCode[plane]);
        if (m_codes.size() > kLiveWindow) m_codes.pop_front();
    }
    const core::DeviceHealth h = p->port().health();
    const std::optional<double> code = liveCode();
    if (!h.ready())
        m_live->setText(tr("Probe: %1").arg(QString::fromStdString(h.message)));
    else if (code)
        m_live->setText(tr("Live ADC code %1 (mean of %2)").arg(*code, 0, 'f', 1).arg(m_codes.size()));
    else
        m_live->setText(tr("Waiting for probe samples…"));
    if (code)
        m_chart->setSeries(QStringLiteral("live"), tr("now"), {m_reference->value()}, {*code}, QColor(0xf0, 0xa0, 0x30),
                           Chart::Style::Points);
    m_chart->refresh();
}

std::optional<double> ProbeCapturePage::liveCode() const {
    if (m_codes.size() < kMinLiveSamples) return std::nullopt;
    double sum = 0.0;
    for (double c : m_codes)
        sum += c;
    return sum / static_cast<double>(m_codes.size());
}

void ProbeCapturePage::showMessage(const QString& text, bool problem) {
    m_messageIsProblem = problem;
    m_message->setText(text);
    markProblem(m_message, problem);
}

QString ProbeCapturePage::message() const {
    return m_message->text();
}

void ProbeCapturePage::setJack(double um) {
    CalibrationProbe* p = m_ctx.probe();
    if (!p || !p->hasJack()) return;
    m_jack->setValue(um);
    p->setJackDeflectionMm(m_ctx.session->plane, um / 1000.0);
    // The dial indicator shows the deflection to its division.
    const double division = m_ctx.session->resolutionUm;
    m_reference->setValue(std::round(um / division) * division);
    m_codes.clear();  // the average restarts at the new load
    showMessage(
        tr("The jack bends the bar to %1 µm; wait for the live code to settle, then capture.").arg(um, 0, 'f', 1),
        false);
}

void ProbeCapturePage::setReferenceUm(double um) {
    m_reference->setValue(um);
}

void ProbeCapturePage::setTypedCode(double code) {
    m_code->setValue(code);
}

bool ProbeCapturePage::capturePoint() {
    CalibrationProbe* p = m_ctx.probe();
    if (!p || !p->port().health().ready()) {
        showMessage(tr("The probe is not ready: type the point instead."), true);
        return false;
    }
    const std::optional<double> code = liveCode();
    if (!code) {
        showMessage(tr("Too few live samples yet (%1 of %2): wait a moment.").arg(m_codes.size()).arg(kMinLiveSamples),
                    true);
        return false;
    }
    m_ctx.session->points.push_back({m_reference->value(), *code, static_cast<int>(m_codes.size())});
    refreshPoints();
    showMessage(tr("Point %1: %2 µm at ADC code %3.")
                    .arg(m_ctx.session->points.size())
                    .arg(m_reference->value(), 0, 'f', 1)
                    .arg(*code, 0, 'f', 1),
                false);
    return true;
}

bool ProbeCapturePage::addTypedPoint() {
    m_ctx.session->points.push_back({m_reference->value(), m_code->value(), 0});
    refreshPoints();
    showMessage(tr("Typed point %1 added.").arg(m_ctx.session->points.size()), false);
    return true;
}

void ProbeCapturePage::removePoint() {
    auto& points = m_ctx.session->points;
    if (points.empty()) return;
    int row = m_table->currentRow();
    if (row < 0 || row >= static_cast<int>(points.size())) row = static_cast<int>(points.size()) - 1;
    points.erase(points.begin() + row);
    refreshPoints();
    showMessage(tr("Point removed."), false);
}

void ProbeCapturePage::refreshPoints() {
    const auto& points = m_ctx.session->points;
    m_table->setRowCount(static_cast<int>(points.size()));
    std::vector<double> xs, ys;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const CapturedPoint& p = points[i];
        const int row = static_cast<int>(i);
        m_table->setItem(row, 0, new QTableWidgetItem(QString::number(p.referenceUm, 'f', 1)));
        m_table->setItem(row, 1, new QTableWidgetItem(QString::number(p.adcCode, 'f', 1)));
        m_table->setItem(row, 2,
                         new QTableWidgetItem(p.samples > 0 ? tr("live, %1 samples").arg(p.samples) : tr("typed")));
        m_table->item(row, 0)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_table->item(row, 1)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        xs.push_back(p.referenceUm);
        ys.push_back(p.adcCode);
    }
    m_chart->setSeries(QStringLiteral("points"), tr("captured"), xs, ys, QColor(0x1f, 0x5f, 0xa8),
                       Chart::Style::Points);
    showAllWithMargin(*m_chart, xs, ys, false, 0.3);
    m_table->resizeColumnsToContents();
    m_chart->refresh();
    emit completeChanged();
}

void ProbeCapturePage::retranslate() {
    setTitle(tr("Capture points"));
    setSubTitle(tr("Load the bar, read the instrument, capture. At least %1 points; both directions.").arg(kMinPoints));
    m_jackLabel->setText(tr("Simulator jack"));
    m_setJack->setText(tr("Bend the bar"));
    m_referenceLabel->setText(tr("Reference reading"));
    for (QDoubleSpinBox* s : {m_jack, m_reference})
        s->setSuffix(tr(" µm"));
    m_capture->setText(tr("Capture point"));
    m_codeLabel->setText(tr("ADC code (typed)"));
    m_typed->setText(tr("Add typed point"));
    m_remove->setText(tr("Remove point"));
    m_table->setHorizontalHeaderLabels({tr("Reference, µm"), tr("ADC code"), tr("Source")});
    m_chart->setTitle(tr("ADC code against the reference deflection"));
    m_chart->setAxisTitles(tr("Reference deflection, µm"), tr("ADC code"));
    if (m_message->text().isEmpty()) showMessage(tr("Captured points stay here when you go back or cancel."), false);
}

}  // namespace tt::ui
