#include "ui/calibration/probe_fit_page.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <algorithm>

#include "ui/calibration/chart_ranges.h"
#include "ui/calibration/probe_wizard.h"
#include "ui/plot/chart.h"

namespace tt::ui {

ProbeFitPage::ProbeFitPage(ProbeWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_degreeLabel(new QLabel(this)),
      m_degree(new QComboBox(this)),
      m_explanation(new QLabel(this)),
      m_characteristic(new Chart(this)),
      m_residuals(new Chart(this)) {
    m_degree->setObjectName(QStringLiteral("degreeCombo"));
    m_explanation->setObjectName(QStringLiteral("fitExplanation"));
    m_explanation->setWordWrap(true);
    m_explanation->setTextFormat(Qt::RichText);
    for (int d : {core::kAutoDegree, 2, 3, 4})
        m_degree->addItem(QString(), d);
    m_characteristic->setMinimumSize(420, 300);
    m_residuals->setMinimumSize(420, 300);
    auto* top = new QHBoxLayout;
    top->addWidget(m_degreeLabel);
    top->addWidget(m_degree);
    top->addStretch(1);
    auto* charts = new QHBoxLayout;
    charts->addWidget(m_characteristic);
    charts->addWidget(m_residuals);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_explanation);
    layout->addLayout(charts, 1);
    connect(m_degree, &QComboBox::currentIndexChanged, this, [this] {
        m_ctx.session->degree = m_degree->currentData().toInt();
        m_ctx.session->accepted = false;  // a different table needs a new acceptance
        refit();
    });
}

void ProbeFitPage::initializePage() {
    const QSignalBlocker block(m_degree);
    m_degree->setCurrentIndex(std::max(0, m_degree->findData(m_ctx.session->degree)));
    refit();
}

void ProbeFitPage::setDegree(int degree) {
    m_degree->setCurrentIndex(std::max(0, m_degree->findData(degree)));
}

QString ProbeFitPage::explanation() const {
    return m_explanation->text();
}

bool ProbeFitPage::isComplete() const {
    return m_ctx.result.has_value();
}

void ProbeFitPage::refit() {
    m_ctx.result.reset();
    m_fit.reset();
    m_problem.clear();
    const std::vector<core::CalibrationPoint> points = m_ctx.session->calibrationPoints();
    try {
        m_fit = core::fitCharacteristic(points, m_ctx.session->adcBits, m_ctx.session->degree);
        if (m_fit->monotonicity.monotonic)
            m_ctx.result = core::linearise(points, m_ctx.session->adcBits, m_ctx.session->degree);
        else
            m_problem = QString::fromStdString(m_fit->monotonicity.message);
    } catch (const std::exception& e) {
        m_problem = QString::fromStdString(e.what());
    }

    QString text;
    if (m_fit) {
        text += tr("<p><b>%1</b>.</p>").arg(QString::fromStdString(m_fit->choiceReason).toHtmlEscaped());
        QStringList rows;
        for (const core::DegreeScore& s : m_fit->scores)
            rows << tr("degree %1: leave-one-out %2 µm, in-sample %3 µm%4")
                        .arg(s.degree)
                        .arg(s.cvRmsUm, 0, 'f', 2)
                        .arg(s.rmsResidualUm, 0, 'f', 2)
                        .arg(s.degree == m_fit->degree ? tr(" — chosen") : QString());
        text += QStringLiteral("<p>") + rows.join(QStringLiteral("<br>")) + QStringLiteral("</p>");
        text +=
            tr("<p>Each point is predicted from a fit to the others (leave-one-out); a higher degree always "
               "fits the points themselves better, so it is kept only when it predicts them better.</p>");
    }
    if (!m_problem.isEmpty())
        text += QStringLiteral("<p style='color:#b71c1c'><b>%1</b></p>")
                    .arg(tr("Refused: %1").arg(m_problem.toHtmlEscaped()));
    else if (m_ctx.result)
        text += tr("<p style='color:#1b5e20'><b>Monotonic over the whole ADC range; residual RMS %1 µm.</b></p>")
                    .arg(m_ctx.result->fit.rmsResidualUm, 0, 'f', 2);
    m_explanation->setText(text);

    m_characteristic->clear();
    m_residuals->clear();
    if (m_fit) {
        std::vector<double> xs, ys;
        for (const core::CalibrationPoint& p : points) {
            xs.push_back(p.referenceUm);
            ys.push_back(p.adcCode);
        }
        m_characteristic->setSeries(QStringLiteral("points"), tr("captured"), xs, ys, QColor(0x1f, 0x5f, 0xa8),
                                    Chart::Style::Points);
        std::vector<double> cx, cy;
        const double lo = m_fit->calibratedMinUm, hi = m_fit->calibratedMaxUm;
        for (int i = 0; i <= 100; ++i) {
            const double x = lo + (hi - lo) * i / 100.0;
            cx.push_back(x);
            cy.push_back(m_fit->codeAt(x));
        }
        m_characteristic->setSeries(QStringLiteral("fit"), tr("fitted, degree %1").arg(m_fit->degree), cx, cy,
                                    QColor(0xc6, 0x28, 0x28), Chart::Style::Line);
        showAllWithMargin(*m_characteristic, xs, ys, false, 0.3);
        m_residuals->setSeries(QStringLiteral("residuals"), tr("residual"), xs, m_fit->residualsUm,
                               QColor(0x2e, 0x7d, 0x32), Chart::Style::Points);
        m_residuals->setSeries(QStringLiteral("zero"), tr("zero"), {lo, hi}, {0.0, 0.0}, QColor(0x6b, 0x77, 0x85),
                               Chart::Style::Line);
        showAllWithMargin(*m_residuals, xs, m_fit->residualsUm, true);
    }
    m_characteristic->refresh();
    m_residuals->refresh();
    emit completeChanged();
}

void ProbeFitPage::retranslate() {
    setTitle(tr("Fit the characteristic"));
    setSubTitle(tr("The inductive sensor's characteristic is a polynomial of degree 2 to 4; the table inverts it."));
    m_degreeLabel->setText(tr("Degree"));
    m_degree->setItemText(0, tr("Automatic (cross-validation)"));
    m_degree->setItemText(1, tr("2"));
    m_degree->setItemText(2, tr("3"));
    m_degree->setItemText(3, tr("4"));
    m_characteristic->setTitle(tr("Characteristic"));
    m_characteristic->setAxisTitles(tr("Reference deflection, µm"), tr("ADC code"));
    m_residuals->setTitle(tr("Residuals"));
    m_residuals->setAxisTitles(tr("Reference deflection, µm"), tr("Table reading − reference, µm"));
    if (m_ctx.session) refit();
}

}  // namespace tt::ui
