#include "ui/main_window.h"

#include "ui/log_categories.h"

#include <algorithm>

#include <QActionGroup>
#include <QApplication>
#include <QButtonGroup>
#include <QCloseEvent>
#include <QEvent>
#include <QFontMetrics>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QSettings>
#include <QStackedWidget>
#include <QStatusBar>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include "ui/about.h"
#include "ui/app_state.h"
#include "ui/keypad.h"
#include "ui/kiosk.h"
#include "ui/language.h"
#include "ui/pages/page_factory.h"
#include "ui/pages/reports_page.h"
#include "ui/prompt.h"
#include "ui/run/verdict_counter.h"

namespace tt::ui {

namespace {

QString toneName(AppState::Tone tone) {
    switch (tone) {
        case AppState::Tone::Ok:
            return QStringLiteral("ok");
        case AppState::Tone::Warning:
            return QStringLiteral("warn");
        case AppState::Tone::Fault:
            return QStringLiteral("fault");
        case AppState::Tone::Idle:
            break;
    }
    return QStringLiteral("idle");
}

QString loopTone(AppState::Loop loop) {
    switch (loop) {
        case AppState::Loop::Running:
            return QStringLiteral("ok");
        case AppState::Loop::Paused:
            return QStringLiteral("warn");
        case AppState::Loop::Fault:
            return QStringLiteral("fault");
        case AppState::Loop::Idle:
            break;
    }
    return QStringLiteral("idle");
}

void setTone(QLabel* label, const QString& tone) {
    label->setProperty("tone", tone);
    label->style()->unpolish(label);
    label->style()->polish(label);
}

}  // namespace

MainWindow::MainWindow(AppContext& context, QWidget* parent) : QMainWindow(parent), m_context(context) {
    setObjectName(QStringLiteral("MainWindow"));
    setWindowIcon(QIcon(QStringLiteral(":/icons/trueturn.svg")));
    m_stack = new QStackedWidget(this);
    for (PageId id : kAllPages) {
        Page* page = createPage(id, context, m_stack);
        m_pages.append(page);
        m_stack->addWidget(page);
        connect(page, &Page::reportsRequested, this, &MainWindow::showReportsOf);
    }
    auto* central = new QWidget(this);
    auto* outer = new QHBoxLayout(central);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->setSpacing(0);
    outer->addWidget(buildNavigation());
    auto* right = new QVBoxLayout;
    right->setSpacing(0);
    right->addWidget(buildHeader());
    right->addWidget(m_stack, 1);
    outer->addLayout(right, 1);
    setCentralWidget(central);
    buildMenus();
    buildStatusBar();
    if (context.state) {
        connect(context.state, &AppState::loopChanged, this, &MainWindow::updateLoopState);
        connect(context.state, &AppState::devicesChanged, this, &MainWindow::updateDeviceState);
        connect(context.state, &AppState::databaseChanged, this, &MainWindow::updateDatabase);
    }
    retranslate();
    showPage(PageId::Run);
    resize(1280, 800);
}

QWidget* MainWindow::buildNavigation() {
    auto* rail = new QWidget(this);
    rail->setObjectName(QStringLiteral("NavigationRail"));
    rail->setAttribute(Qt::WA_StyledBackground, true);
    auto* layout = new QVBoxLayout(rail);
    layout->setContentsMargins(0, 0, 0, 8);
    layout->setSpacing(2);
    auto* brand = new QLabel(QStringLiteral("TrueTurn"), rail);
    brand->setObjectName(QStringLiteral("BrandLabel"));
    layout->addWidget(brand);
    m_navGroup = new QButtonGroup(this);
    m_navGroup->setExclusive(true);
    for (int i = 0; i < m_pages.size(); ++i) {
        auto* button = new QToolButton(rail);
        button->setObjectName(QStringLiteral("nav_") + pageKey(m_pages[i]->id()));
        button->setCheckable(true);
        button->setIcon(m_pages[i]->icon());
        button->setIconSize(QSize(32, 32));
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        m_navGroup->addButton(button, i);
        m_navButtons.append(button);
        layout->addWidget(button);
    }
    layout->addStretch(1);
    connect(m_navGroup, &QButtonGroup::idClicked, this, [this](int index) { showPage(m_pages[index]->id()); });
    return rail;
}

QWidget* MainWindow::buildHeader() {
    auto* header = new QWidget(this);
    header->setObjectName(QStringLiteral("PageHeader"));
    header->setAttribute(Qt::WA_StyledBackground, true);
    auto* layout = new QHBoxLayout(header);
    layout->setContentsMargins(24, 10, 16, 10);
    m_pageTitle = new QLabel(header);
    m_pageTitle->setObjectName(QStringLiteral("PageTitle"));
    m_loopBadge = new QLabel(header);
    m_loopBadge->setObjectName(QStringLiteral("LoopBadge"));
    m_deviceBadge = new QLabel(header);
    m_deviceBadge->setObjectName(QStringLiteral("DeviceBadge"));
    layout->addWidget(m_pageTitle, 1);
    layout->addWidget(m_deviceBadge);
    layout->addSpacing(8);
    layout->addWidget(m_loopBadge);
    return header;
}

void MainWindow::buildStatusBar() {
    m_statusLoop = new QLabel(this);
    m_statusDevices = new QLabel(this);
    m_statusDatabase = new QLabel(this);
    m_statusLoop->setObjectName(QStringLiteral("statusLoop"));
    m_statusDevices->setObjectName(QStringLiteral("statusDevices"));
    m_statusDatabase->setObjectName(QStringLiteral("statusDatabase"));
    statusBar()->addWidget(m_statusLoop);
    statusBar()->addWidget(m_statusDevices);
    statusBar()->addPermanentWidget(m_statusDatabase);
}

void MainWindow::buildMenus() {
    m_fileMenu = menuBar()->addMenu(QString());
    m_quitAction = m_fileMenu->addAction(QString(), this, &QWidget::close);
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_viewMenu = menuBar()->addMenu(QString());
    m_languageMenu = m_viewMenu->addMenu(QString());
    auto* languages = new QActionGroup(this);
    for (const QString& code : LanguageSwitcher::available()) {
        QAction* action = m_languageMenu->addAction(LanguageSwitcher::nativeName(code));
        action->setCheckable(true);
        action->setData(code);
        languages->addAction(action);
        m_languageActions.append(action);
        connect(action, &QAction::triggered, this, [this, code] {
            if (m_context.language) m_context.language->apply(code);
        });
    }
    m_keypad = new KeypadLauncher(this);
    m_keypadAction = m_viewMenu->addAction(QString());
    m_keypadAction->setObjectName(QStringLiteral("keypadAction"));
    m_keypadAction->setCheckable(true);
    m_keypadAction->setChecked(QSettings().value(QStringLiteral("ui/onScreenKeypad"), false).toBool());
    m_keypad->setAlwaysOn(m_keypadAction->isChecked());
    connect(m_keypadAction, &QAction::toggled, this, [this](bool on) {
        m_keypad->setAlwaysOn(on);
        QSettings().setValue(QStringLiteral("ui/onScreenKeypad"), on);
    });
    m_soundAction = m_viewMenu->addAction(QString());
    m_soundAction->setObjectName(QStringLiteral("soundAction"));
    m_soundAction->setCheckable(true);
    m_soundAction->setChecked(QSettings().value(kSoundOnOutOfTolerance, false).toBool());
    connect(m_soundAction, &QAction::toggled, this, [](bool on) { QSettings().setValue(kSoundOnOutOfTolerance, on); });
    m_helpMenu = menuBar()->addMenu(QString());
    m_aboutAction = m_helpMenu->addAction(QString(), this, &MainWindow::showAbout);
}

void MainWindow::showPage(PageId id) {
    for (int i = 0; i < m_pages.size(); ++i) {
        if (m_pages[i]->id() != id) continue;
        m_stack->setCurrentIndex(i);
        m_navButtons[i]->setChecked(true);
        m_pageTitle->setText(m_pages[i]->title());
        qCInfo(lcUi).noquote() << "page" << pageKey(id);
        return;
    }
}

void MainWindow::showReportsOf(const QString& machine) {
    showPage(PageId::Reports);
    if (auto* reports = qobject_cast<ReportsPage*>(page(PageId::Reports))) reports->showMachine(machine);
}

PageId MainWindow::currentPage() const {
    return m_pages[m_stack->currentIndex()]->id();
}

Page* MainWindow::page(PageId id) const {
    for (Page* p : m_pages)
        if (p->id() == id) return p;
    return nullptr;
}

void MainWindow::showAbout() {
    if (!m_context.prompt) return;
    m_context.prompt->inform(this, tr("About TrueTurn"),
                             About::text(m_context.state ? m_context.state->logFilePath() : QString()));
}

bool MainWindow::mayClose() {
    if (m_kiosk && !engineerMayQuit(m_context, this)) return false;
    QStringList reasons;
    const AppState::Loop loop = m_context.state ? m_context.state->loop() : AppState::Loop::Idle;
    if (loop == AppState::Loop::Running || loop == AppState::Loop::Paused)
        reasons << tr("a run is going (loop: %1); quitting stops it, its finished parts stay in the history")
                       .arg(AppState::loopName(loop));
    for (const Page* p : m_pages)
        if (const QString edits = p->unappliedEdits(); !edits.isEmpty())
            reasons << tr("%1 not applied; quitting discards them").arg(edits);
    if (reasons.isEmpty()) return true;
    if (!m_context.prompt) return false;
    return m_context.prompt->ask(
               this, tr("Quit TrueTurn?"),
               tr("Before you quit:\n• %1\n\nQuit anyway?").arg(reasons.join(QStringLiteral("\n• ")))) ==
           Prompt::Answer::Yes;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (mayClose())
        event->accept();
    else
        event->ignore();
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QMainWindow::changeEvent(event);
}

void MainWindow::retranslate() {
    setWindowTitle(tr("TrueTurn — adaptive lathe control"));
    int widestButton = 0;
    for (int i = 0; i < m_pages.size(); ++i) {
        QToolButton* button = m_navButtons[i];
        button->setText(m_pages[i]->title());
        button->ensurePolished();
        QFont bold = button->font();  // the current page's name is shown in bold
        bold.setBold(true);
        const int boldExtra = QFontMetrics(bold).horizontalAdvance(button->text()) -
                              button->fontMetrics().horizontalAdvance(button->text());
        widestButton = std::max(widestButton, button->sizeHint().width() + boldExtra);
    }
    for (QToolButton* button : m_navButtons)
        button->setMinimumWidth(widestButton);  // a wide page never squeezes a page name in the rail
    m_pageTitle->setText(m_pages[m_stack->currentIndex()]->title());
    m_fileMenu->setTitle(tr("&File"));
    m_quitAction->setText(tr("&Quit"));
    m_viewMenu->setTitle(tr("&View"));
    m_languageMenu->setTitle(tr("&Language"));
    m_helpMenu->setTitle(tr("&Help"));
    m_aboutAction->setText(tr("&About TrueTurn"));
    m_keypadAction->setText(tr("On-screen &keypad"));
    m_soundAction->setText(tr("&Sound on rework or scrap"));
    const QString current = m_context.language ? m_context.language->current() : QStringLiteral("en");
    for (QAction* a : m_languageActions)
        a->setChecked(a->data().toString() == current);
    updateLoopState();
    updateDeviceState();
    updateDatabase();
}

void MainWindow::updateLoopState() {
    const AppState::Loop loop = m_context.state ? m_context.state->loop() : AppState::Loop::Idle;
    const QString detail = m_context.state ? m_context.state->loopDetail() : QString();
    m_loopBadge->setText(tr("Loop: %1").arg(AppState::loopName(loop)));
    setTone(m_loopBadge, loopTone(loop));
    m_statusLoop->setText(detail.isEmpty() ? tr("Loop: %1").arg(AppState::loopName(loop))
                                           : tr("Loop: %1 — %2").arg(AppState::loopName(loop), detail));
}

void MainWindow::updateDeviceState() {
    const AppState::Tone tone = m_context.state ? m_context.state->deviceTone() : AppState::Tone::Idle;
    QString summary = m_context.state ? m_context.state->deviceSummary() : QString();
    if (summary.isEmpty()) summary = tr("no devices connected");
    m_deviceBadge->setText(tr("Devices: %1")
                               .arg(tone == AppState::Tone::Ok        ? tr("ready")
                                    : tone == AppState::Tone::Fault   ? tr("fault")
                                    : tone == AppState::Tone::Warning ? tr("check")
                                                                      : tr("none")));
    setTone(m_deviceBadge, toneName(tone));
    m_statusDevices->setText(tr("Devices: %1").arg(summary));
}

void MainWindow::updateDatabase() {
    QString db = m_context.state ? m_context.state->databaseDescription() : QString();
    if (db.isEmpty()) db = m_context.databasePath;
    const QString plant = m_context.state ? m_context.state->plantLink() : QString();
    // With a plant database its link is what the operator needs to read; the URL is in the tooltip.
    m_statusDatabase->setText(plant.isEmpty() ? tr("History: %1").arg(db) : plant);
    m_statusDatabase->setToolTip(tr("History: %1").arg(db));
    setTone(m_statusDatabase,
            m_context.state && m_context.state->plantLinkWarns() ? QStringLiteral("warn") : QStringLiteral("idle"));
}

}  // namespace tt::ui
