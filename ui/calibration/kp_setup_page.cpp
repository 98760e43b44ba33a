#include "ui/calibration/kp_setup_page.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QListWidget>
#include <algorithm>

#include "core/model/tool_table.h"
#include "core/storage/tool_store.h"
#include "ui/calibration/kp_wizard_context.h"

namespace tt::ui {

KpSetupPage::KpSetupPage(KpWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_driveLabel(new QLabel(this)),
      m_drive(new QComboBox(this)),
      m_toolsLabel(new QLabel(this)),
      m_tools(new QListWidget(this)),
      m_instructions(wrappedLabel(this)) {
    m_drive->setObjectName(QStringLiteral("driveCombo"));
    m_tools->setObjectName(QStringLiteral("kpTools"));
    m_tools->setMinimumHeight(160);
    m_tools->setStyleSheet(QStringLiteral("QListWidget::indicator { width: 28px; height: 28px; }"));
    auto* form = new QFormLayout(this);
    form->setVerticalSpacing(16);
    form->addRow(m_driveLabel, m_drive);
    form->addRow(m_toolsLabel, m_tools);
    form->addRow(m_instructions);
}

void KpSetupPage::initializePage() {
    const QSignalBlocker block(m_drive);
    m_drive->clear();
    for (DeviceKpDrive* d : m_ctx.drives)
        m_drive->addItem(d->name());
    m_drive->setCurrentIndex(std::clamp(m_ctx.session->driveIndex, 0, std::max(0, m_drive->count() - 1)));
    m_tools->clear();
    if (!m_ctx.tools) return;
    for (const core::ToolRecord& t : m_ctx.tools->tools()) {
        const QString id = QString::fromStdString(t.id);
        auto* item = new QListWidgetItem(tr("%1 %2 — k_p now %3 N/A")
                                             .arg(id, QString::fromStdString(t.name))
                                             .arg(t.currentToForceGainNPerA, 0, 'f', 1),
                                         m_tools);
        item->setData(Qt::UserRole, id);
        item->setSizeHint(QSize(0, 48));  // a row a gloved finger can hit
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(m_ctx.session->toolIds.contains(id) ? Qt::Checked : Qt::Unchecked);
    }
}

void KpSetupPage::setToolChecked(const QString& id, bool checked) {
    for (int i = 0; i < m_tools->count(); ++i)
        if (m_tools->item(i)->data(Qt::UserRole).toString() == id)
            m_tools->item(i)->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

bool KpSetupPage::validatePage() {
    m_ctx.session->driveIndex = std::max(0, m_drive->currentIndex());
    m_ctx.session->toolIds.clear();
    for (int i = 0; i < m_tools->count(); ++i)
        if (m_tools->item(i)->checkState() == Qt::Checked)
            m_ctx.session->toolIds << m_tools->item(i)->data(Qt::UserRole).toString();
    return true;
}

void KpSetupPage::retranslate() {
    setTitle(tr("Drive and tools"));
    setSubTitle(tr("k_p turns the cross-feed motor current into force: P = k_p (I_fwd − I_rev) / 2."));
    m_driveLabel->setText(tr("Cross-feed drive"));
    m_toolsLabel->setText(tr("Write the new k_p into"));
    m_instructions->setText(
        tr("Put a dynamometer or a hydraulic jack with a gauge between the tool block and the workpiece so it "
           "pushes the tool towards the axis like the cutting force. Start the cross-feed dither (as for boring) and "
           "keep it running; at each load the current is averaged at constant velocity in both directions."));
}

}  // namespace tt::ui
