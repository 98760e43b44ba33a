#pragma once

#include <QString>
#include <memory>

#include "core/auth/access_guard.h"
#include "core/storage/data_stores.h"

namespace tt::runtime {
class DeviceHub;
}

namespace tt::ui {

class AppState;
class ControllerTuning;
class Prompt;
class LanguageSwitcher;
class UserSession;

/// The services every page receives from the application (wired in app/gui.cpp or a test):
/// the prompt for dialogs, the shared machine state, where history is stored and its one data access
/// object.
struct AppContext {
    Prompt* prompt = nullptr;
    AppState* state = nullptr;
    LanguageSwitcher* language = nullptr;
    QString databasePath;  ///< SQLite file (or PostgreSQL connection name) of the run history
    /// The devices (gauge, probe, drive readout, CNC output) in their own thread, made before the main window
    /// (app/gui.cpp: runtime::TerminalDevices); required by the Devices page, used by the Run page's machines.
    runtime::DeviceHub* devices = nullptr;
    /// The data access object of `databasePath` (made on first use, or given by the application).
    std::shared_ptr<storage::DataStores> stores = nullptr;
    /// Who is logged in and the idle log-out (ui/auth/user_session.h); null = no log-in (tests of pages).
    UserSession* session = nullptr;
    /// The session's access guard, given to every store: a change the logged-in role may not make is
    /// refused by the store. Null = not access-controlled (tests of pages that log nobody in).
    const core::auth::AccessGuard* access = nullptr;
    /// The controller tuning applied on the Controller page, taken by the Run page's loop (ui/controller/
    /// controller_tuning.h); null = the pages do not share it (tests of one page).
    ControllerTuning* tuning = nullptr;

    /// The database's stores for the GUI thread; made again when `databasePath` changes.
    storage::DataStores& data() {
        if (!stores || stores->location() != databasePath) stores = std::make_shared<storage::DataStores>(databasePath);
        stores->setAccess(access);
        return *stores;
    }
};

}  // namespace tt::ui
