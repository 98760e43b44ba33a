#include "ui/process/deformation_model_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

namespace tt::ui {

namespace {

QString number(double v, int precision) {
    return std::isfinite(v) ? QLocale().toString(v, 'g', precision) : QStringLiteral("∞");
}

QString fixed(double v, int decimals) {
    return QLocale().toString(v, 'f', decimals);
}

}  // namespace

DeformationModelPanel::DeformationModelPanel(QWidget* parent)
    : QWidget(parent),
      m_termsLabel(new QLabel(this)),
      m_terms(new QComboBox(this)),
      m_stepwise(new QCheckBox(this)),
      m_summary(new QLabel(this)),
      m_table(new QTableWidget(this)),
      m_removed(new QLabel(this)) {
    m_terms->setObjectName(QStringLiteral("feedModelTerms"));
    m_stepwise->setObjectName(QStringLiteral("feedModelStepwise"));
    m_summary->setObjectName(QStringLiteral("feedModelStatistics"));
    m_table->setObjectName(QStringLiteral("feedModelTable"));
    for (core::DeformationTermSet s : {core::DeformationTermSet::CubicZ, core::DeformationTermSet::Quadratic,
                                       core::DeformationTermSet::Interactions, core::DeformationTermSet::Linear})
        m_terms->addItem(QString(), static_cast<int>(s));
    m_stepwise->setChecked(true);
    m_summary->setWordWrap(true);
    m_summary->setTextFormat(Qt::RichText);
    m_removed->setWordWrap(true);
    m_removed->setStyleSheet(QStringLiteral("color: #56616d; font-size: 11pt;"));
    m_table->setColumnCount(4);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);

    m_terms->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_terms->setMinimumContentsLength(14);
    auto* choice = new QHBoxLayout;
    choice->addWidget(m_termsLabel);
    choice->addWidget(m_terms, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addLayout(choice);
    layout->addWidget(m_stepwise);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_removed);
    retranslate();
}

core::DeformationTermSet DeformationModelPanel::termSet() const {
    return static_cast<core::DeformationTermSet>(m_terms->currentData().toInt());
}

bool DeformationModelPanel::stepwise() const {
    return m_stepwise->isChecked();
}

void DeformationModelPanel::showModel(const config::DeformationModelFile* file) {
    m_file = file;
    retranslate();
}

void DeformationModelPanel::fillTable() {
    const int rows = m_file ? static_cast<int>(m_file->statistics.terms.size()) : 0;
    m_table->setRowCount(rows);
    for (int r = 0; r < rows; ++r) {
        const config::DeformationTermReport& t = m_file->statistics.terms[static_cast<std::size_t>(r)];
        const QString cells[4] = {QString::fromStdString(t.name), fixed(t.coefficient, 3), fixed(t.stdError, 3),
                                  number(t.tValue, 4)};
        for (int c = 0; c < 4; ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            item->setTextAlignment(c == 0 ? Qt::AlignLeft | Qt::AlignVCenter : Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(r, c, item);
        }
    }
}

void DeformationModelPanel::retranslate() {
    m_termsLabel->setText(tr("Terms of the next fit"));
    m_terms->setItemText(0, tr("cubic in z (a, f quadratic)"));
    m_terms->setItemText(1, tr("full quadratic"));
    m_terms->setItemText(2, tr("linear with interactions"));
    m_terms->setItemText(3, tr("linear"));
    m_stepwise->setText(tr("Remove insignificant terms"));
    m_table->setHorizontalHeaderLabels(
        {tr("Term (coded)"), tr("Coefficient, µm"), tr("Std. error, µm"), tr("t-value")});
    fillTable();
    if (!m_file) {
        m_summary->setText(tr("No model yet."));
        m_removed->clear();
        return;
    }
    const config::DeformationModelStatistics& s = m_file->statistics;
    const QString verdict = s.significant() ? tr("significant at 95 %") : tr("NOT significant at 95 %");
    m_summary->setText(
        tr("<b>%1 points, %2 terms.</b> R² %3, adjusted R² %4. F %5 against the table value F(0.95; %6, %7) = %8: "
           "%9. Residual 2σ %10 µm. t-values below %11 are not significant.")
            .arg(s.pointCount)
            .arg(s.termCount)
            .arg(fixed(s.r2, 5), fixed(s.r2Adjusted, 5), number(s.fStatistic, 5))
            .arg(s.termCount - 1)
            .arg(s.residualDof)
            .arg(number(s.fCritical95, 4), verdict, fixed(s.twoSigmaUm(), 2), number(s.tCritical95, 4)));
    QStringList removed;
    for (const auto& [name, t] : s.removed)
        removed << QStringLiteral("%1 (|t| %2)").arg(QString::fromStdString(name), number(t, 3));
    m_removed->setText(removed.isEmpty() ? QString()
                                         : tr("Removed as insignificant: %1").arg(removed.join(QStringLiteral(", "))));
}

}  // namespace tt::ui
