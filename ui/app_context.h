#pragma once

#include <QString>

namespace tt::devices {
class DeviceManager;
}

namespace tt::ui {

class AppState;
class Prompt;
class LanguageSwitcher;

/// The services every page receives from the application (wired in app/main.cpp or a test):
/// the prompt for dialogs, the shared machine state, and where history is stored.
struct AppContext {
    Prompt* prompt = nullptr;
    AppState* state = nullptr;
    LanguageSwitcher* language = nullptr;
    QString databasePath;  ///< SQLite file (or PostgreSQL connection name) of the run history
    /// The device instances (gauge, probe, drive readout, CNC output), made before the main window
    /// (app/gui.cpp: TerminalDevices); required by the Devices page, used by the Run page's real lathe.
    devices::DeviceManager* devices = nullptr;
};

}  // namespace tt::ui
