#include "ui/reports/report_filter_bar.h"

#include <QComboBox>
#include <QDateEdit>
#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>
#include <QTimeZone>
#include <QVBoxLayout>
#include <set>

#include "runtime/reports/point_report.h"

namespace tt::ui {

namespace {

/// The date edits' "any date" value: their minimum, shown as a word.
const QDate kAnyDate(2000, 1, 1);

QDateEdit* dateEdit(QWidget* parent, const QString& name) {
    auto* edit = new QDateEdit(parent);
    edit->setObjectName(name);
    edit->setCalendarPopup(true);
    edit->setDisplayFormat(QStringLiteral("yyyy-MM-dd"));
    edit->setMinimumDate(kAnyDate);
    edit->setMaximumDate(QDate(2100, 12, 31));
    edit->setDate(kAnyDate);
    return edit;
}

std::optional<std::string> utcDay(const QDateEdit* edit, int addDays) {
    if (edit->date() == kAnyDate) return std::nullopt;
    return QDateTime(edit->date().addDays(addDays), QTime(0, 0), QTimeZone::utc())
        .toString(Qt::ISODateWithMs)
        .toStdString();
}

}  // namespace

ReportFilterBar::ReportFilterBar(QWidget* parent)
    : QWidget(parent),
      m_machineLabel(new QLabel(this)),
      m_machine(new QComboBox(this)),
      m_runLabel(new QLabel(this)),
      m_run(new QComboBox(this)),
      m_fromLabel(new QLabel(this)),
      m_from(dateEdit(this, QStringLiteral("reportFrom"))),
      m_toLabel(new QLabel(this)),
      m_to(dateEdit(this, QStringLiteral("reportTo"))),
      m_subgroupLabel(new QLabel(this)),
      m_subgroup(new QSpinBox(this)),
      m_chartLabel(new QLabel(this)),
      m_chart(new QComboBox(this)),
      m_baselineLabel(new QLabel(this)),
      m_baseline(new QSpinBox(this)) {
    m_machine->setObjectName(QStringLiteral("reportMachine"));
    m_run->setObjectName(QStringLiteral("reportRun"));
    m_run->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_run->setMinimumContentsLength(6);
    m_machine->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_machine->setMinimumContentsLength(10);
    m_subgroup->setObjectName(QStringLiteral("reportSubgroup"));
    m_subgroup->setRange(1, 25);
    m_chart->setObjectName(QStringLiteral("reportChart"));
    for (int i = 0; i < 4; ++i)
        m_chart->addItem(QString(), i);
    m_baseline->setObjectName(QStringLiteral("reportBaseline"));
    m_baseline->setRange(0, 100000);

    // Two independent rows (not a grid): the window must fit 1280 px in Russian too.
    auto* first = new QHBoxLayout;
    for (QWidget* w : std::initializer_list<QWidget*>{m_machineLabel, m_machine, m_runLabel, m_run, m_fromLabel, m_from,
                                                      m_toLabel, m_to})
        first->addWidget(w, w == m_run ? 1 : 0);
    auto* second = new QHBoxLayout;
    for (QWidget* w : std::initializer_list<QWidget*>{m_subgroupLabel, m_subgroup, m_chartLabel, m_chart,
                                                      m_baselineLabel, m_baseline})
        second->addWidget(w);
    second->addStretch(1);
    auto* rows = new QVBoxLayout(this);
    rows->setContentsMargins(0, 0, 0, 0);
    rows->addLayout(first);
    rows->addLayout(second);

    connect(m_machine, &QComboBox::activated, this, [this] {
        fillRuns();
        emit changed();
    });
    for (QComboBox* box : {m_run, m_chart})
        connect(box, &QComboBox::activated, this, &ReportFilterBar::changed);
    for (QDateEdit* edit : {m_from, m_to})
        connect(edit, &QDateEdit::dateChanged, this, &ReportFilterBar::changed);
    for (QSpinBox* spin : {m_subgroup, m_baseline})
        connect(spin, &QSpinBox::valueChanged, this, &ReportFilterBar::changed);
    retranslate();
}

void ReportFilterBar::setRuns(const std::vector<core::RunSummary>& runs) {
    m_runs = runs;
    const QString chosen = m_machine->currentData().toString();
    std::set<std::string> machines;
    for (const core::RunSummary& run : runs)
        machines.insert(run.description.machine);
    m_machine->clear();
    m_machine->addItem(tr("all machines"), QString());
    for (const std::string& machine : machines)
        if (!machine.empty()) m_machine->addItem(QString::fromStdString(machine), QString::fromStdString(machine));
    const int index = m_machine->findData(chosen);
    m_machine->setCurrentIndex(std::max(index, 0));
    fillRuns();
}

void ReportFilterBar::selectMachine(const QString& machine) {
    int index = m_machine->findData(machine);
    if (index < 0) {  // not among the stored runs read last: chosen all the same (the page reads them again)
        m_machine->addItem(machine, machine);
        index = m_machine->count() - 1;
    }
    m_machine->setCurrentIndex(index);
    fillRuns();
    m_run->setCurrentIndex(0);
    m_from->setDate(m_from->minimumDate());
    m_to->setDate(m_to->minimumDate());
}

void ReportFilterBar::fillRuns() {
    const qint64 chosen = m_run->currentData().toLongLong();
    const std::string machine = m_machine->currentData().toString().toStdString();
    m_run->clear();
    m_run->addItem(tr("all runs"), QVariant::fromValue<qint64>(0));
    for (const core::RunSummary& run : m_runs) {
        if (!machine.empty() && run.description.machine != machine) continue;
        m_run->addItem(tr("Run %1 · %2 · %n parts", nullptr, static_cast<int>(run.partCount))
                           .arg(run.runId)
                           .arg(QString::fromStdString(run.startedAt).left(10)),
                       QVariant::fromValue<qint64>(run.runId));
    }
    const int index = m_run->findData(QVariant::fromValue<qint64>(chosen));
    m_run->setCurrentIndex(std::max(index, 0));
}

storage::MeasurementFilter ReportFilterBar::filter() const {
    storage::MeasurementFilter f;
    const qint64 run = m_run->currentData().toLongLong();
    if (run > 0) f.runId = run;
    const QString machine = m_machine->currentData().toString();
    if (!machine.isEmpty()) f.machine = machine.toStdString();
    f.fromUtc = utcDay(m_from, 0);
    f.toUtc = utcDay(m_to, 1);  // the whole last day
    return f;
}

core::PointAnalysisSettings ReportFilterBar::settings() const {
    const auto chart = static_cast<runtime::ReportChart>(m_chart->currentData().toInt());
    return runtime::reportSettings(m_subgroup->value(), chart, static_cast<std::size_t>(m_baseline->value()));
}

void ReportFilterBar::retranslate() {
    m_machineLabel->setText(tr("Machine"));
    m_runLabel->setText(tr("Run"));
    m_fromLabel->setText(tr("From"));
    m_toLabel->setText(tr("To"));
    m_subgroupLabel->setText(tr("Subgroup, parts"));
    m_chartLabel->setText(tr("Chart"));
    m_baselineLabel->setText(tr("Limits from first"));
    m_from->setSpecialValueText(tr("any date"));
    m_to->setSpecialValueText(tr("any date"));
    m_baseline->setSpecialValueText(tr("all points"));
    // A spin box sizes itself once: room for the words of its special value in this language.
    for (QAbstractSpinBox* box : std::initializer_list<QAbstractSpinBox*>{m_from, m_to, m_baseline})
        box->setMinimumWidth(box->fontMetrics().horizontalAdvance(box->specialValueText()) + 56);
    m_chart->setItemText(static_cast<int>(runtime::ReportChart::Automatic), tr("by subgroup size"));
    m_chart->setItemText(static_cast<int>(runtime::ReportChart::XbarRange), tr("X̄-R"));
    m_chart->setItemText(static_cast<int>(runtime::ReportChart::XbarStdDev), tr("X̄-s"));
    m_chart->setItemText(static_cast<int>(runtime::ReportChart::IndividualsMR), tr("I-MR"));
    if (m_machine->count() > 0) m_machine->setItemText(0, tr("all machines"));
    fillRuns();  // the run descriptions in the new language
}

}  // namespace tt::ui
