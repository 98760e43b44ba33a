#pragma once

#include "ui/page.h"
#include "runtime/run/run_request.h"

class QListWidget;
class QTabWidget;

namespace tt::runtime {
class RunSession;
}  // namespace tt::runtime

namespace tt::ui {

class ManualEntryPanel;
class ProfilePanel;
class ShaftRunPanel;

/// The operator's main page: one tab per kind of closed loop. The first tab is run-to-run control of the
/// shaft profile (ShaftRunPanel: the loop on the built-in simulated lathe or on the real lathe through the
/// devices of the Devices page, with the run history, paper 000). Another loop is one more tab: add it to
/// tabs() in the constructor and name it in retranslate().
class RunPage : public Page {
    Q_OBJECT
public:
    explicit RunPage(AppContext& context, QWidget* parent = nullptr);
    ~RunPage() override;
    QString title() const override;
    void retranslate() override;

    /// The tabs, one per kind of closed loop.
    QTabWidget* tabs() const { return m_tabs; }
    /// The shaft run-to-run tab and, for the tests and the shell, its parts.
    ShaftRunPanel& shaft() { return *m_shaft; }
    runtime::RunSession& session();
    ProfilePanel* profilePanel() const;
    ManualEntryPanel* manualEntry() const;
    QListWidget* alarms() const;
    /// The run request the shaft tab's controls make now.
    runtime::RunRequest request() const;

private:
    QTabWidget* m_tabs;
    ShaftRunPanel* m_shaft;
};

}  // namespace tt::ui
