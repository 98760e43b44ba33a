#pragma once

#include <QList>
#include <QMainWindow>

#include "ui/app_context.h"
#include "ui/page.h"

class QAction;
class QButtonGroup;
class QLabel;
class QMenu;
class QStackedWidget;
class QToolButton;
class QCloseEvent;

namespace tt::ui {

class KeypadLauncher;

/// The operator terminal's main window: a navigation rail of large buttons on the left, a header
/// with the page title and the loop and device badges, the pages, and a status bar.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(AppContext& context, QWidget* parent = nullptr);

    void showPage(PageId id);
    /// Shows the Reports page with the reports of `machine` (all its runs), analysed.
    void showReportsOf(const QString& machine);
    PageId currentPage() const;
    Page* page(PageId id) const;
    const QList<Page*>& pages() const { return m_pages; }

    /// The About box (version, what TrueTurn does), through the prompt.
    void showAbout();

    /// Kiosk mode (`trueturn --kiosk`): quitting needs an engineer (engineerMayQuit in ui/kiosk.h).
    void setKiosk(bool kiosk) { m_kiosk = kiosk; }
    bool isKiosk() const { return m_kiosk; }
    /// The on-screen keypad for numeric fields: the "On-screen keypad" setting (View menu) or a touch.
    KeypadLauncher* keypad() const { return m_keypad; }

    /// Whether the window may close now: in kiosk mode an engineer allowed it; with a run going or
    /// unapplied edits the user confirmed. Asks through the prompt.
    bool mayClose();

protected:
    void changeEvent(QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

private:
    QWidget* buildNavigation();
    QWidget* buildHeader();
    void buildStatusBar();
    void buildMenus();
    void retranslate();
    void updateLoopState();
    void updateDeviceState();
    void updateDatabase();

    AppContext& m_context;
    QList<Page*> m_pages;
    QList<QToolButton*> m_navButtons;
    QButtonGroup* m_navGroup = nullptr;
    QStackedWidget* m_stack = nullptr;
    QLabel* m_pageTitle = nullptr;
    QLabel* m_loopBadge = nullptr;
    QLabel* m_deviceBadge = nullptr;
    QLabel* m_statusLoop = nullptr;
    QLabel* m_statusDevices = nullptr;
    QLabel* m_statusDatabase = nullptr;
    QMenu* m_fileMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    QMenu* m_languageMenu = nullptr;
    QMenu* m_helpMenu = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_aboutAction = nullptr;
    QAction* m_keypadAction = nullptr;
    QAction* m_soundAction = nullptr;
    KeypadLauncher* m_keypad = nullptr;
    bool m_kiosk = false;
    QList<QAction*> m_languageActions;
};

}  // namespace tt::ui
