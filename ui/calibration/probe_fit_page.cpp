#include "ui/calibration/probe_fit_page.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <algorithm>

#include "ui/calibration/chart_ranges.h"
#include "ui/calibration/probe_wizard_context.h"
#include "ui/calibration/procedure_words.h"
#include "plot/chart.h"

namespace tt::ui {

ProbeFitPage::ProbeFitPage(ProbeWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_degreeLabel(new QLabel(this)),
      m_degree(new QComboBox(this)),
      m_choice(wrappedLabel(this)),
      m_explanation(wrappedLabel(this)),
      m_characteristic(new plot::Chart(this)),
      m_residuals(new plot::Chart(this)) {
    m_degree->setObjectName(QStringLiteral("degreeCombo"));
    m_explanation->setObjectName(QStringLiteral("fitExplanation"));
    m_explanation->setTextFormat(Qt::RichText);
    m_choice->setObjectName(QStringLiteral("degreeChoice"));
    m_choice->setStyleSheet(QStringLiteral("font-weight: bold;"));
    for (int d : {core::kAutoDegree, 2, 3, 4})
        m_degree->addItem(QString(), d);
    m_characteristic->setMinimumSize(400, 230);
    m_residuals->setMinimumSize(400, 230);
    m_characteristic->setLegendCorner(Qt::AlignTop | Qt::AlignLeft);  // the curve rises to the top right
    auto* top = new QHBoxLayout;
    top->addWidget(m_degreeLabel);
    top->addWidget(m_degree);
    top->addStretch(1);
    auto* charts = new QHBoxLayout;
    charts->addWidget(m_characteristic);
    charts->addWidget(m_residuals);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_choice);
    layout->addWidget(m_explanation);
    layout->addLayout(charts, 1);
    connect(m_degree, &QComboBox::currentIndexChanged, this, [this] {
        m_ctx.procedure().setDegree(m_degree->currentData().toInt());  // refits; a new table needs a new acceptance
        m_ctx.procedure().takeEvents();
        m_ctx.session->saved.reset();
        showFit();
    });
}

void ProbeFitPage::initializePage() {
    core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    proc.returnToCapture();
    proc.next();  // Capture → Fit: the fit is made
    proc.takeEvents();
    m_ctx.session->saved.reset();  // a table saved from an earlier fit is not this one
    const QSignalBlocker block(m_degree);
    m_degree->setCurrentIndex(std::max(0, m_degree->findData(proc.degree())));
    showFit();
}

void ProbeFitPage::cleanupPage() {
    m_ctx.procedure().returnToCapture();  // Back: the points stay
}

void ProbeFitPage::setDegree(int degree) {
    m_degree->setCurrentIndex(std::max(0, m_degree->findData(degree)));
}

QString ProbeFitPage::explanation() const {
    return m_choice->text() + QLatin1Char('\n') + m_explanation->text();
}

bool ProbeFitPage::isComplete() const {
    return m_ctx.procedure().fitOutcome().usable();
}

void ProbeFitPage::showFit() {
    const core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    const core::ProbeFitOutcome& outcome = proc.fitOutcome();
    const int used = static_cast<int>(proc.points().size() - outcome.leftOut.size());
    m_choice->setText(outcome.fit ? ProcedureWords::degreeChoice(*outcome.fit, used) + QLatin1Char('.') : QString());
    m_explanation->setText(fitExplanation());
    m_characteristic->clear();
    m_residuals->clear();
    if (outcome.fit) plotFit(*outcome.fit);
    m_characteristic->refresh();
    m_residuals->refresh();
    emit completeChanged();
}

QString ProbeFitPage::fitExplanation() const {
    const core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    const core::ProbeFitOutcome& outcome = proc.fitOutcome();
    const int adcBits = proc.config().adcBits;
    QString text;
    if (outcome.fit) {
        const core::CharacteristicFit& fit = *outcome.fit;
        QStringList rows;
        for (const core::DegreeScore& s : fit.scores)
            rows << tr("degree %1: leave-one-out %2 µm, in-sample %3 µm%4")
                        .arg(s.degree)
                        .arg(s.cvRmsUm, 0, 'f', 2)
                        .arg(s.rmsResidualUm, 0, 'f', 2)
                        .arg(s.degree == fit.degree ? tr(" — chosen") : QString());
        text += QStringLiteral("<p>") + rows.join(QStringLiteral("<br>")) + QStringLiteral("</p>");
    }
    if (!outcome.leftOut.empty())
        text += QStringLiteral("<p style='color:#b71c1c'>%1</p>")
                    .arg(ProcedureWords::leftOut(outcome.leftOut, adcBits).toHtmlEscaped());
    if (outcome.refusal != core::ProbeFitRefusal::None)
        text += QStringLiteral("<p style='color:#b71c1c'><b>%1</b></p>")
                    .arg(tr("Refused: %1").arg(ProcedureWords::fitRefusal(outcome, adcBits)).toHtmlEscaped());
    else if (outcome.usable())
        text += tr("<p style='color:#1b5e20'><b>Monotonic over the whole ADC range; residual RMS %1 µm.</b></p>")
                    .arg(outcome.linearisation->fit.rmsResidualUm, 0, 'f', 2);
    return text;
}

void ProbeFitPage::plotFit(const core::CharacteristicFit& fit) {
    std::vector<double> xs, ys;
    for (const core::ProbePoint& p : m_ctx.procedure().points()) {
        if (p.saturated) continue;  // the residuals are of the points fitted
        xs.push_back(p.referenceUm);
        ys.push_back(p.adcCode);
    }
    m_characteristic->setSeries(QStringLiteral("points"), tr("captured"), xs, ys, QColor(0x1f, 0x5f, 0xa8),
                                plot::Chart::Style::Points);
    std::vector<double> cx, cy;
    const double lo = fit.calibratedMinUm, hi = fit.calibratedMaxUm;
    for (int i = 0; i <= 100; ++i) {
        const double x = lo + (hi - lo) * i / 100.0;
        cx.push_back(x);
        cy.push_back(fit.codeAt(x));
    }
    m_characteristic->setSeries(QStringLiteral("fit"), tr("fitted, degree %1").arg(fit.degree), cx, cy,
                                QColor(0xc6, 0x28, 0x28), plot::Chart::Style::Line);
    showAllWithMargin(*m_characteristic, xs, ys, false, 0.3);
    m_residuals->setSeries(QStringLiteral("residuals"), tr("residual"), xs, fit.residualsUm, QColor(0x2e, 0x7d, 0x32),
                           plot::Chart::Style::Points);
    m_residuals->setSeries(QStringLiteral("zero"), tr("zero"), {lo, hi}, {0.0, 0.0}, QColor(0x6b, 0x77, 0x85),
                           plot::Chart::Style::Line);
    showAllWithMargin(*m_residuals, xs, fit.residualsUm, true, 0.5);
}

void ProbeFitPage::retranslate() {
    setTitle(tr("Fit the characteristic"));
    setSubTitle(tr("The inductive sensor's characteristic is a polynomial of degree 2 to 4; the table inverts it."));
    m_degreeLabel->setText(tr("Degree"));
    // How the choice works, for whoever points at it (the page has no room for it at 1280 × 800).
    const QString how =
        tr("Each point is predicted from a fit to the others (leave-one-out); a higher degree always "
           "fits the points themselves better, so it is kept only when it predicts them better.");
    for (QWidget* w : std::initializer_list<QWidget*>{m_degree, m_choice, m_explanation})
        w->setToolTip(how);
    m_degree->setItemText(0, tr("Automatic (cross-validation)"));
    m_degree->setItemText(1, tr("2"));
    m_degree->setItemText(2, tr("3"));
    m_degree->setItemText(3, tr("4"));
    m_characteristic->setTitle(tr("Characteristic"));
    m_characteristic->setAxisTitles(tr("Reference deflection, µm"), tr("ADC code"));
    m_residuals->setTitle(tr("Residuals"));
    m_residuals->setAxisTitles(tr("Reference deflection, µm"), tr("Table reading − reference, µm"));
    if (m_ctx.session) showFit();
}

}  // namespace tt::ui
