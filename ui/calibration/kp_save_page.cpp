#include "ui/calibration/kp_save_page.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "core/model/tool_table.h"
#include "core/storage/calibration_store.h"
#include "core/storage/tool_store.h"
#include "ui/calibration/kp_wizard_context.h"
#include "ui/prompt.h"

namespace tt::ui {

KpSavePage::KpSavePage(KpWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_summary(wrappedLabel(this)),
      m_save(new QPushButton(this)),
      m_result(wrappedLabel(this)) {
    m_save->setObjectName(QStringLiteral("saveKp"));
    m_save->setProperty("role", QStringLiteral("primary"));
    m_result->setObjectName(QStringLiteral("kpSaveResult"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    auto* row = new QHBoxLayout;
    row->addWidget(m_save);
    row->addStretch(1);
    layout->addLayout(row);
    layout->addWidget(m_result);
    layout->addStretch(1);
    connect(m_save, &QPushButton::clicked, this, &KpSavePage::save);
}

void KpSavePage::initializePage() {
    m_save->setEnabled(!m_ctx.session->saved);
    retranslate();
}

void KpSavePage::cleanupPage() {
    m_ctx.procedure().withdrawAcceptance();  // Back to the fit
}

bool KpSavePage::isComplete() const {
    return m_ctx.session->saved;
}

bool KpSavePage::save() {
    if (m_ctx.session->saved || !m_ctx.procedure().accepted()) return m_ctx.session->saved;
    const QString who = m_ctx.operatorName();
    if (who.isEmpty()) {
        if (m_ctx.app && m_ctx.app->prompt)
            m_ctx.app->prompt->warn(this, tr("Save k_p"), tr("Enter your name on the Settings page first."));
        m_result->setText(tr("Not saved: no operator name (Settings)."));
        markProblem(m_result, true);
        return false;
    }
    if (!m_ctx.calibrations || !m_ctx.tools) {
        m_result->setText(tr("The calibration database is not open."));
        markProblem(m_result, true);
        return false;
    }
    const core::KpFit& f = *m_ctx.procedure().fitOutcome().fit;
    try {
        std::vector<storage::ToolEdit> edits;
        for (core::ToolRecord t : m_ctx.tools->tools()) {
            if (!m_ctx.session->toolIds.contains(QString::fromStdString(t.id))) continue;
            const std::string id = t.id;
            t.currentToForceGainNPerA = f.kpNPerA;
            edits.push_back({id, t});
        }
        if (!edits.empty()) m_ctx.tools->apply(edits, who);
        storage::KpCalibrationRecord r;
        r.createdBy = who;
        DeviceKpDrive* d = m_ctx.drive();
        r.drive = d ? d->name() : QString();
        r.kpNPerA = f.kpNPerA;
        r.offsetN = f.offsetN;
        r.r2 = f.r2;
        QString csv = QStringLiteral("load_n,current_difference_a\n");
        for (const core::KpLoadPoint& c : m_ctx.procedure().points())
            csv += QStringLiteral("%1,%2\n").arg(c.loadN, 0, 'g', 10).arg(c.currentDifferenceA, 0, 'g', 10);
        r.pointsCsv = csv;
        r.appliedTo = m_ctx.session->toolIds.join(QLatin1Char(','));
        m_ctx.calibrations->saveKp(r);
    } catch (const std::exception& e) {
        m_result->setText(tr("Not saved: %1").arg(QString::fromStdString(e.what())));
        markProblem(m_result, true);
        return false;
    }
    m_ctx.session->saved = true;
    m_save->setEnabled(false);
    m_result->setText(m_ctx.session->toolIds.isEmpty()
                          ? tr("Saved. No tool was chosen, so the tool table is unchanged.")
                          : tr("Saved; k_p %1 N/A written into %2 (recorded in the tool audit).")
                                .arg(f.kpNPerA, 0, 'f', 2)
                                .arg(m_ctx.session->toolIds.join(QStringLiteral(", "))));
    markProblem(m_result, false);
    emit completeChanged();
    return true;
}

void KpSavePage::retranslate() {
    setTitle(tr("Save k_p"));
    setSubTitle(tr("The calibration is kept with your name; the chosen tools get the new k_p."));
    m_save->setText(tr("Save and write into the tools"));
    if (m_ctx.procedure().fitOutcome().fit)
        m_summary->setText(tr("k_p = %1 N/A, to be written into: %2.")
                               .arg(m_ctx.procedure().fitOutcome().fit->kpNPerA, 0, 'f', 2)
                               .arg(m_ctx.session->toolIds.isEmpty()
                                        ? tr("no tool (only the calibration is kept)")
                                        : m_ctx.session->toolIds.join(QStringLiteral(", "))));
}

}  // namespace tt::ui
