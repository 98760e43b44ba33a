#include "app/gui.h"

#include <trueturn/version.h>
#include <QApplication>
#include <QDir>
#include <QLoggingCategory>
#include <QSettings>
#include <QTimer>
#include <cstdio>
#include <memory>

#include "app/gui_options.h"
#include "core/storage/database_location.h"
#include "devices/api/plugin_folder.h"
#include "runtime/devices/terminal_devices.h"
#include "runtime/history/terminal_history.h"
#include "ui/app_state.h"
#include "ui/auth/log_in_gate.h"
#include "ui/auth/user_session.h"
#include "ui/controller/controller_tuning.h"
#include "ui/history_check.h"
#include "ui/kiosk.h"
#include "ui/language.h"
#include "ui/log_file.h"
#include "ui/main_window.h"
#include "ui/prompt.h"
#include "ui/run/interrupted_run.h"
#include "ui/style.h"

namespace tt::app {

namespace {

bool haveDisplay() {
    return !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") || !qEnvironmentVariableIsEmpty("DISPLAY") ||
           !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
}

/// Grabs every page of the window into `dir` as <page>.png; returns the number written.
int saveScreenshots(ui::MainWindow& window, const QString& dir) {
    QDir().mkpath(dir);
    int written = 0;
    for (ui::Page* page : window.pages()) {
        window.showPage(page->id());
        QCoreApplication::processEvents();
        const QString file = QDir(dir).filePath(ui::pageKey(page->id()) + QStringLiteral(".png"));
        if (window.grab().save(file)) ++written;
    }
    return written;
}

}  // namespace

int runGui(int argc, char** argv) {
    const GuiParse parsed = parseGuiOptions(argc, argv);
    if (!parsed.options) return parsed.exitCode;
    const GuiOptions& options = *parsed.options;
    if (!haveDisplay()) {
        std::fprintf(stderr,
                     "trueturn: no display (DISPLAY is not set). Run a headless command such as "
                     "'trueturn simulate', or set QT_QPA_PLATFORM=offscreen.\n");
        return 1;
    }
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("TrueTurn"));
    QApplication::setApplicationName(QStringLiteral("TrueTurn"));
    QApplication::setApplicationVersion(QString::fromLatin1(tt::kVersion));
    ui::applyOperatorStyle(app);

    ui::LanguageSwitcher language;
    if (options.language.isEmpty())
        language.applySaved();
    else
        language.apply(options.language);

    // The devices before the window, so every page sees the same instances.
    runtime::TerminalDevices devices(devices::defaultPluginFolder());
    for (const QString& problem : devices.problems())
        std::fprintf(stderr, "trueturn: devices: %s\n", qPrintable(problem));

    if (!options.machine.isEmpty())
        QSettings().setValue(QString::fromLatin1(runtime::kMachineNameSetting), options.machine);
    ui::AppState state;
    ui::DialogPrompt prompt;
    ui::AppContext context{&prompt, &state, &language,
                           options.databasePath.isEmpty() ? storage::defaultDatabasePath() : options.databasePath,
                           &devices.hub()};
    // The tuning applied on the Controller page reaches the Run page's loop.
    ui::ControllerTuning tuning;
    context.tuning = &tuning;
    // The application's log in the user's data folder (its path is in the About box).
    std::unique_ptr<ui::LogFile> log;
    try {
        log = std::make_unique<ui::LogFile>(ui::LogFile::defaultPath());
        log->install();
        // The product's own categories log at info level in the GUI (the command line stays quiet).
        QLoggingCategory::setFilterRules(QStringLiteral("trueturn.*.info=true"));
        state.setLogFilePath(log->path());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "trueturn: no log file: %s\n", e.what());
    }
    // The one data access object of the history database, shared by every page of the GUI thread.
    context.stores = std::make_shared<storage::DataStores>(context.databasePath);
    // Roles: every store asks the session's guard; the first start creates the administrator, later
    // starts ask for a log-in (not for --screenshots, which changes nothing and logs nobody in).
    ui::UserSession session(&state);
    context.session = &session;
    context.access = &session.guard();
    // --quit-after-ms (tests) also closes a log-in dialog that nobody answers, and ends the event loop directly:
    // quit() would close the window, which in kiosk mode or with a run going asks the user first.
    if (options.quitAfterMs >= 0)
        QTimer::singleShot(options.quitAfterMs, &app, [] {
            if (QWidget* dialog = QApplication::activeModalWidget()) dialog->close();
            QCoreApplication::exit(0);
        });
    if (options.screenshotDir.isEmpty() && !ui::logInAtStart(context)) return 0;
    ui::MainWindow window(context);
    ui::logInAgainAfterLogOut(context, &window);
    for (ui::PageId id : ui::kAllPages)
        if (ui::pageKey(id) == options.page) window.showPage(id);
    window.setKiosk(options.kiosk);
    if (options.kiosk)
        ui::showAsKiosk(&window);
    else
        window.show();

    if (options.screenshotDir.isEmpty())
        QTimer::singleShot(0, &window, [&] {
            // An interrupted run is offered for resume once the history is known to be usable.
            if (ui::checkHistoryAtStart(context, &window, &prompt)) ui::offerInterruptedRun(context, window);
        });
    else
        ui::checkHistoryAtStart(context, &window, nullptr);  // screenshots: the status bar says it, no dialog

    if (!options.screenshotDir.isEmpty()) {
        const int written = saveScreenshots(window, options.screenshotDir);
        std::printf("trueturn: %d page screenshots written to %s\n", written, qPrintable(options.screenshotDir));
        return written == static_cast<int>(window.pages().size()) ? 0 : 1;
    }
    return QApplication::exec();
}

}  // namespace tt::app
