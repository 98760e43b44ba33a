#include "ui/pages/run_page.h"

#include <QTabWidget>
#include <QVBoxLayout>

#include "ui/boring/boring_panel.h"
#include "ui/pages/planned_page.h"
#include "ui/run/shaft_run_panel.h"

namespace tt::ui {

RunPage::RunPage(AppContext& context, QWidget* parent)
    : Page(PageId::Run, context, parent), m_tabs(new QTabWidget(this)), m_shaft(new ShaftRunPanel(context, this)) {
    m_tabs->setObjectName(QStringLiteral("runTabs"));
    m_tabs->setDocumentMode(true);
    m_tabs->setStyleSheet(
        QStringLiteral("QTabBar::tab { font-size: 14pt; padding: 8px 22px; min-height: 30px; }"
                       "QTabBar::tab:selected { font-weight: bold; }"));
    m_tabs->addTab(m_shaft, QString());
    m_tabs->addTab(new BoringPanel(context, this), QString());  // in-process compensation (paper 001)
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(8, 4, 8, 4);
    layout->addWidget(m_tabs);
    retranslate();
}

RunPage::~RunPage() = default;

QString RunPage::title() const {
    return pageTitle(PageId::Run);
}

void RunPage::retranslate() {
    m_tabs->setTabText(m_tabs->indexOf(m_shaft), tr("Shaft profile (run-to-run)"));
    m_shaft->retranslate();
    if (auto* boring = m_tabs->findChild<BoringPanel*>()) {
        m_tabs->setTabText(m_tabs->indexOf(boring), tr("Boring bar (in-process)"));
        boring->retranslate();
    }
}

runtime::RunSession& RunPage::session() {
    return m_shaft->session();
}

ProfilePanel* RunPage::profilePanel() const {
    return m_shaft->profilePanel();
}

ManualEntryPanel* RunPage::manualEntry() const {
    return m_shaft->manualEntry();
}

QListWidget* RunPage::alarms() const {
    return m_shaft->alarms();
}

runtime::RunRequest RunPage::request() const {
    return m_shaft->request();
}

}  // namespace tt::ui
