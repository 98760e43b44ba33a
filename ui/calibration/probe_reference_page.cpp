#include "ui/calibration/probe_reference_page.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>

#include "ui/calibration/probe_wizard_context.h"

namespace tt::ui {

ProbeReferencePage::ProbeReferencePage(ProbeWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_kindLabel(new QLabel(this)),
      m_kind(new QComboBox(this)),
      m_resolutionLabel(new QLabel(this)),
      m_resolution(new QDoubleSpinBox(this)),
      m_instructions(wrappedLabel(this)) {
    m_kind->setObjectName(QStringLiteral("referenceCombo"));
    m_resolution->setObjectName(QStringLiteral("resolutionSpin"));
    m_kind->addItem(QString());
    m_kind->addItem(QString());
    m_resolution->setRange(0.1, 10.0);
    m_resolution->setDecimals(1);
    m_resolution->setSingleStep(0.5);
    auto* form = new QFormLayout(this);
    form->setVerticalSpacing(16);
    form->addRow(m_kindLabel, m_kind);
    form->addRow(m_resolutionLabel, m_resolution);
    form->addRow(m_instructions);
}

void ProbeReferencePage::initializePage() {
    m_kind->setCurrentIndex(m_ctx.session->referenceKind);
    m_resolution->setValue(m_ctx.procedure().config().referenceDivisionUm);
}

bool ProbeReferencePage::validatePage() {
    m_ctx.session->referenceKind = m_kind->currentIndex();
    const core::ProbeProcedureConfig& c = m_ctx.procedure().config();
    m_ctx.setUp(c.plane, c.adcBits, m_resolution->value());
    return true;
}

void ProbeReferencePage::retranslate() {
    setTitle(tr("Set up the reference"));
    setSubTitle(tr("The deflection is read on an instrument at the tool tip while the bar is loaded."));
    m_kindLabel->setText(tr("Reference instrument"));
    m_kind->setItemText(0, tr("Dial indicator"));
    m_kind->setItemText(1, tr("Micrometer"));
    m_resolutionLabel->setText(tr("Division of the instrument"));
    m_resolution->setSuffix(tr(" µm"));
    m_instructions->setText(
        tr("1. Clamp the boring bar as for cutting; mount the instrument on the lathe bed touching the tool tip "
           "in the chosen plane.\n2. With the bar unloaded, set the instrument to zero.\n3. Load the bar in both "
           "directions in steps (a screw jack against the tool block) over the whole travel of the probe; at each "
           "step read the instrument and capture the point. Aim for 15 to 25 points, both signs."));
}

}  // namespace tt::ui
