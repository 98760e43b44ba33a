#pragma once

#include <QString>
#include <memory>

#include "core/storage/data_stores.h"

namespace tt::devices {
class DeviceManager;
}

namespace tt::ui {

class AppState;
class Prompt;
class LanguageSwitcher;

/// The services every page receives from the application (wired in app/gui.cpp or a test):
/// the prompt for dialogs, the shared machine state, where history is stored and its one data access
/// object.
struct AppContext {
    Prompt* prompt = nullptr;
    AppState* state = nullptr;
    LanguageSwitcher* language = nullptr;
    QString databasePath;  ///< SQLite file (or PostgreSQL connection name) of the run history
    /// The device instances (gauge, probe, drive readout, CNC output), made before the main window
    /// (app/gui.cpp: TerminalDevices); required by the Devices page, used by the Run page's real lathe.
    devices::DeviceManager* devices = nullptr;
    /// The data access object of `databasePath` (made on first use, or given by the application).
    std::shared_ptr<storage::DataStores> stores = nullptr;

    /// The database's stores for the GUI thread; made again when `databasePath` changes.
    storage::DataStores& data() {
        if (!stores || stores->location() != databasePath) stores = std::make_shared<storage::DataStores>(databasePath);
        return *stores;
    }
};

}  // namespace tt::ui
