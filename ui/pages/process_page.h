#pragma once

#include <vector>

#include "ui/page.h"

class QStackedLayout;
class QTabWidget;

namespace tt::ui {

class EmptyState;
class ProcessTool;

/// The process planner's and designer's page: one tab per process-design tool
/// (ui/process/process_tools.cpp). With no tool built in, it explains what it will hold.
class ProcessPage : public Page {
    Q_OBJECT
public:
    explicit ProcessPage(AppContext& context, QWidget* parent = nullptr);
    QString title() const override;
    void retranslate() override;

    QTabWidget* tabs() const { return m_tabs; }
    /// The tool with this key, or nullptr.
    ProcessTool* tool(const QString& key) const;

private:
    QTabWidget* m_tabs;
    EmptyState* m_empty;
    std::vector<ProcessTool*> m_tools;
};

}  // namespace tt::ui
