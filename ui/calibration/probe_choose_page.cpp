#include "ui/calibration/probe_choose_page.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <algorithm>

#include "ui/calibration/probe_wizard_context.h"

namespace tt::ui {

ProbeChoosePage::ProbeChoosePage(ProbeWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_probeLabel(new QLabel(this)),
      m_probe(new QComboBox(this)),
      m_planeLabel(new QLabel(this)),
      m_plane(new QComboBox(this)),
      m_bitsLabel(new QLabel(this)),
      m_bits(new QSpinBox(this)),
      m_health(wrappedLabel(this)) {
    m_probe->setObjectName(QStringLiteral("probeCombo"));
    m_plane->setObjectName(QStringLiteral("planeCombo"));
    m_bits->setObjectName(QStringLiteral("adcBitsSpin"));
    m_bits->setRange(core::kMinAdcBits, core::kMaxAdcBits);
    m_plane->addItem(QString(), 0);
    m_plane->addItem(QString(), 1);
    auto* form = new QFormLayout(this);
    form->setVerticalSpacing(16);
    form->addRow(m_probeLabel, m_probe);
    form->addRow(m_planeLabel, m_plane);
    form->addRow(m_bitsLabel, m_bits);
    form->addRow(m_health);
    connect(m_probe, &QComboBox::currentIndexChanged, this, [this] {
        m_ctx.session->probeIndex = std::max(0, m_probe->currentIndex());
        if (DeviceCalibrationProbe* p = m_ctx.probe(); p && p->adcBits()) m_bits->setValue(*p->adcBits());
        store();
        initializePage();
    });
    connect(m_plane, &QComboBox::currentIndexChanged, this, [this] { store(); });
    connect(m_bits, &QSpinBox::valueChanged, this, [this] { store(); });
}

void ProbeChoosePage::store() {
    m_ctx.session->probeIndex = std::max(0, m_probe->currentIndex());
    m_ctx.setUp(m_plane->currentData().toInt(), m_bits->value(), m_ctx.procedure().config().referenceDivisionUm);
}

void ProbeChoosePage::initializePage() {
    const QSignalBlocker a(m_probe), b(m_plane), c(m_bits);
    m_probe->clear();
    for (DeviceCalibrationProbe* p : m_ctx.probes)
        m_probe->addItem(p->name());
    m_probe->setCurrentIndex(std::clamp(m_ctx.session->probeIndex, 0, std::max(0, m_probe->count() - 1)));
    m_plane->setCurrentIndex(m_ctx.procedure().config().plane);
    m_bits->setValue(m_ctx.procedure().config().adcBits);
    DeviceCalibrationProbe* p = m_ctx.probe();
    m_bits->setEnabled(!p || !p->adcBits());
    if (p && p->adcBits()) {
        m_bits->setValue(*p->adcBits());  // what the mandrel says it has
        store();
    }
    if (!p) {
        m_health->setText(tr("No probe mandrel is configured: add one on the Devices page, or type the points."));
        return;
    }
    const core::DeviceHealth h = p->port().health();
    m_health->setText(
        h.ready()
            ? tr("%1 is ready.").arg(p->name())
            : tr("%1: %2 — you can still type the points by hand.").arg(p->name(), QString::fromStdString(h.message)));
}

bool ProbeChoosePage::validatePage() {
    store();
    return true;
}

void ProbeChoosePage::retranslate() {
    setTitle(tr("Probe and bending plane"));
    setSubTitle(tr("Which probe mandrel is calibrated, in which plane, and its ADC resolution."));
    m_probeLabel->setText(tr("Probe mandrel"));
    m_planeLabel->setText(tr("Bending plane"));
    m_bitsLabel->setText(tr("ADC resolution"));
    m_bits->setSuffix(tr(" bit"));
    m_plane->setItemText(0, tr("X — radial (bore diameter)"));
    m_plane->setItemText(1, tr("Y — tangential"));
}

}  // namespace tt::ui
