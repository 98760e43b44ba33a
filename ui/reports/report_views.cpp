#include "ui/reports/report_views.h"

#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QScrollArea>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <set>

#include "plot/chart.h"
#include "reports/report_charts.h"

namespace tt::ui {

namespace {

constexpr int kMultipleColumns = 3;

QWidget* tab(QWidget* parent, QLayout* layout) {
    auto* page = new QWidget(parent);
    page->setLayout(layout);
    return page;
}

}  // namespace

ReportViews::ReportViews(QWidget* parent)
    : QWidget(parent),
      m_tabs(new QTabWidget(this)),
      m_pointLabel(new QLabel(this)),
      m_point(new QComboBox(this)),
      m_summary(new QLabel(this)),
      m_location(new plot::Chart(this)),
      m_spread(new plot::Chart(this)),
      m_violations(new QLabel(this)),
      m_histogram(new plot::Chart(this)),
      m_capability(new QTableWidget(this)),
      m_partLabel(new QLabel(this)),
      m_part(new QSpinBox(this)),
      m_partName(new QLabel(this)),
      m_profile(new plot::Chart(this)),
      m_multiplesHost(new QWidget(this)),
      m_multiplesGrid(new QGridLayout(m_multiplesHost)) {
    setUpWidgets();
    buildLayout();
    connect(m_point, &QComboBox::activated, this, [this](int index) { showPoint(index); });
    connect(m_part, &QSpinBox::valueChanged, this, &ReportViews::showPart);
    retranslate();
}

void ReportViews::setUpWidgets() {
    m_tabs->setObjectName(QStringLiteral("reportTabs"));
    m_point->setObjectName(QStringLiteral("reportPoint"));
    m_summary->setObjectName(QStringLiteral("reportPointSummary"));
    m_summary->setWordWrap(true);
    m_location->setObjectName(QStringLiteral("reportLocationChart"));
    m_spread->setObjectName(QStringLiteral("reportSpreadChart"));
    m_histogram->setObjectName(QStringLiteral("reportHistogram"));
    m_capability->setObjectName(QStringLiteral("reportCapability"));
    m_profile->setObjectName(QStringLiteral("reportProfile"));
    m_part->setObjectName(QStringLiteral("reportPart"));
    m_violations->setObjectName(QStringLiteral("reportViolations"));
    m_violations->setWordWrap(true);
    m_violations->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    // Explicit minimum widths: a chart's legend must not widen the window beyond 1280 px.
    m_spread->setMinimumSize(400, 150);
    m_location->setMinimumSize(400, 200);
    m_histogram->setMinimumSize(380, 220);
    m_profile->setMinimumSize(400, 220);
    setUpCapabilityTable();
}

void ReportViews::setUpCapabilityTable() {
    m_capability->setColumnCount(3);
    m_capability->verticalHeader()->setVisible(false);
    m_capability->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_capability->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_capability->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Fixed);
    m_capability->horizontalHeader()->setSectionResizeMode(2, QHeaderView::Fixed);
    m_capability->setColumnWidth(1, 120);
    m_capability->setColumnWidth(2, 150);
    m_capability->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_capability->setMinimumWidth(480);
}

void ReportViews::buildLayout() {
    auto* pointBar = new QHBoxLayout;
    pointBar->addWidget(m_pointLabel);
    pointBar->addWidget(m_point);
    pointBar->addWidget(m_summary, 1);

    auto* chartCharts = new QVBoxLayout;
    chartCharts->addWidget(m_location, 3);
    chartCharts->addWidget(m_spread, 2);
    auto* chartTab = new QHBoxLayout;
    chartTab->addLayout(chartCharts, 1);
    // The controller's changes and the rule violations scroll when they are longer than the charts are high.
    auto* notes = new QScrollArea(this);
    notes->setObjectName(QStringLiteral("reportNotes"));
    notes->setWidget(m_violations);
    notes->setWidgetResizable(true);
    notes->setFrameShape(QFrame::NoFrame);
    notes->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    notes->setFixedWidth(226);
    notes->viewport()->setAutoFillBackground(false);  // the tab's own background, as the charts'
    m_violations->setAutoFillBackground(false);       // (setWidget turned it on)
    chartTab->addWidget(notes);

    auto* distributionTab = new QHBoxLayout;
    distributionTab->addWidget(m_histogram, 1);
    distributionTab->addWidget(m_capability);

    auto* partBar = new QHBoxLayout;
    partBar->addWidget(m_partLabel);
    partBar->addWidget(m_part);
    partBar->addWidget(m_partName, 1);
    auto* profileTab = new QVBoxLayout;
    profileTab->addLayout(partBar);
    profileTab->addWidget(m_profile, 1);

    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setWidget(m_multiplesHost);
    auto* multiplesTab = new QVBoxLayout;
    multiplesTab->addWidget(scroll);

    m_tabs->addTab(tab(m_tabs, chartTab), QString());
    m_tabs->addTab(tab(m_tabs, distributionTab), QString());
    m_tabs->addTab(tab(m_tabs, profileTab), QString());
    m_tabs->addTab(tab(m_tabs, multiplesTab), QString());

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(pointBar);
    layout->addWidget(m_tabs, 1);
}

void ReportViews::show(std::vector<storage::MeasurementRow> rows, std::vector<runtime::PointReport> points,
                       QString adaptationsError) {
    m_rows = std::move(rows);
    m_points = std::move(points);
    m_adaptationsError = std::move(adaptationsError);
    m_parts.clear();
    std::set<std::pair<std::int64_t, std::int64_t>> seen;
    for (const storage::MeasurementRow& r : m_rows)
        if (seen.insert({r.runId, r.partNumber}).second) m_parts.emplace_back(r.runId, r.partNumber);
    const int chosen = std::max(m_point->currentIndex(), 0);
    fillPointChoice();
    m_point->setCurrentIndex(std::min(chosen, m_point->count() - 1));
    showPoint(m_point->currentIndex());
    m_part->blockSignals(true);
    m_part->setRange(m_parts.empty() ? 0 : 1, static_cast<int>(m_parts.size()));
    m_part->blockSignals(false);
    showPart(m_part->value());
    showMultiples();
}

void ReportViews::fillPointChoice() {
    m_point->clear();
    for (const runtime::PointReport& p : m_points)
        m_point->addItem(reports::ReportCharts::pointTitle(p));
}

void ReportViews::showPoint(int index) {
    if (index < 0 || index >= static_cast<int>(m_points.size())) return;
    const runtime::PointReport& p = m_points[static_cast<std::size_t>(index)];
    m_summary->setText(QStringLiteral("%1 · %2").arg(reports::ReportCharts::chartDescription(p),
                                                     reports::ReportCharts::verdictText(p.verdicts)));
    reports::ReportCharts::showLocation(*m_location, p);
    reports::ReportCharts::showSpread(*m_spread, p);
    reports::ReportCharts::showHistogram(*m_histogram, p);
    // The controller's changes first (a few lines), then the rule violations in the room left.
    QStringList lines;
    if (!p.adaptations.empty())
        lines << tr("Controller changes (marked): %n", nullptr, static_cast<int>(p.adaptations.size()))
              << reports::ReportCharts::adaptationLines(p, 3);
    if (!m_adaptationsError.isEmpty())
        lines << tr("The controller changes of these runs could not be read: %1").arg(m_adaptationsError);
    lines << tr("Rule violations (Western Electric): %n", nullptr, static_cast<int>(p.analysis.violations.size()))
          << reports::ReportCharts::violationLines(p, lines.isEmpty() ? 8 : 4);
    m_violations->setText(lines.join(QLatin1Char('\n')));
    const std::vector<reports::CapabilityLine> table = reports::ReportCharts::capabilityLines(p);
    m_capability->clearSpans();
    m_capability->setRowCount(static_cast<int>(table.size()));
    for (int row = 0; row < static_cast<int>(table.size()); ++row) {
        const reports::CapabilityLine& line = table[static_cast<std::size_t>(row)];
        m_capability->setItem(row, 0, new QTableWidgetItem(line.name));
        auto* value = new QTableWidgetItem(line.value);
        value->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_capability->setItem(row, 1, value);
        m_capability->setItem(row, 2, new QTableWidgetItem(line.interval));
        if (line.interval.isEmpty()) m_capability->setSpan(row, 1, 1, 2);  // the method, the p-value, sigmas
    }
}

void ReportViews::showPart(int number) {
    if (number < 1 || number > static_cast<int>(m_parts.size())) {
        m_profile->clear();
        m_partName->clear();
        return;
    }
    const auto [run, part] = m_parts[static_cast<std::size_t>(number - 1)];
    const QString name = tr("run %1, part %2").arg(run).arg(part);
    m_partName->setText(name);
    reports::ReportCharts::showProfile(*m_profile, reports::partProfileOf(m_rows, run, part),
                                       tr("Profile of %1").arg(name));
}

void ReportViews::showMultiples() {
    for (plot::Chart* chart : m_multiples)
        delete chart;
    m_multiples.clear();
    for (std::size_t i = 0; i < m_points.size(); ++i) {
        auto* chart = new plot::Chart(m_multiplesHost);
        chart->setObjectName(QStringLiteral("reportMultiple%1").arg(i + 1));
        chart->setFontPointSize(9);
        chart->setMinimumHeight(200);
        reports::ReportCharts::showLocation(*chart, m_points[i], true);
        chart->setFontPointSize(9);
        m_multiplesGrid->addWidget(chart, static_cast<int>(i) / kMultipleColumns,
                                   static_cast<int>(i) % kMultipleColumns);
        m_multiples.push_back(chart);
    }
}

void ReportViews::retranslate() {
    m_tabs->setTabText(0, tr("Control chart"));
    m_tabs->setTabText(1, tr("Distribution and capability"));
    m_tabs->setTabText(2, tr("Part profile"));
    m_tabs->setTabText(3, tr("All points"));
    m_pointLabel->setText(tr("Point"));
    m_partLabel->setText(tr("Part in order"));
    m_capability->setHorizontalHeaderLabels({tr("Index"), tr("Value"), tr("95 % interval")});
    if (!m_points.empty()) {  // the charts' and tables' texts in the new language
        const int point = m_point->currentIndex();
        fillPointChoice();
        m_point->setCurrentIndex(point);
        showPoint(point);
        showPart(m_part->value());
        showMultiples();
    }
}

}  // namespace tt::ui
