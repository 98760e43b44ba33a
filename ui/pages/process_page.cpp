#include "ui/pages/process_page.h"

#include <QStackedLayout>
#include <QTabWidget>
#include <QVBoxLayout>

#include "ui/empty_state.h"
#include "ui/pages/planned_page.h"
#include "ui/process/process_tools.h"

namespace tt::ui {

ProcessPage::ProcessPage(AppContext& context, QWidget* parent)
    : Page(PageId::Process, context, parent), m_tabs(new QTabWidget(this)), m_empty(new EmptyState(this)) {
    m_tabs->setObjectName(QStringLiteral("processTabs"));
    m_tabs->setDocumentMode(true);
    m_tabs->setStyleSheet(
        QStringLiteral("QTabBar::tab { font-size: 14pt; padding: 8px 22px; min-height: 30px; }"
                       "QTabBar::tab:selected { font-weight: bold; }"));
    m_tools = makeProcessTools(context, this);
    for (ProcessTool* tool : m_tools) {
        tool->setObjectName(tool->key());
        m_tabs->addTab(tool, QString());
    }
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(8, 4, 8, 4);
    layout->addWidget(m_tools.empty() ? static_cast<QWidget*>(m_empty) : m_tabs);
    (m_tools.empty() ? static_cast<QWidget*>(m_tabs) : m_empty)->hide();
    retranslate();
}

QString ProcessPage::title() const {
    return pageTitle(PageId::Process);
}

ProcessTool* ProcessPage::tool(const QString& key) const {
    for (ProcessTool* tool : m_tools)
        if (tool->key() == key) return tool;
    return nullptr;
}

void ProcessPage::retranslate() {
    m_empty->setTexts(tr("Process design"),
                      tr("Feed scheduling against force deformation with its CNC program, the corrective "
                         "pulse of the feed drives at corners, and hydraulic feed stabilisation."));
    for (ProcessTool* tool : m_tools) {
        m_tabs->setTabText(m_tabs->indexOf(tool), tool->title());
        tool->retranslate();
    }
}

}  // namespace tt::ui
