#pragma once

#include <QString>
#include <optional>

namespace tt::app {

/// Options of the GUI (`trueturn [options]`), parsed without a display so --help and --version
/// work on a headless machine.
struct GuiOptions {
    QString page;           ///< page to open first ("run", "devices", ...)
    QString language;       ///< "en" or "ru"; empty: the saved choice
    QString databasePath;   ///< history database; empty: the default in the user's data folder
    QString machine;        ///< the lathe's name in a plant database (kept as a setting); empty: unchanged
    QString screenshotDir;  ///< grab every page to <dir>/<page>.png and quit
    int quitAfterMs = -1;   ///< quit after this many milliseconds (test hook); -1: never
    bool kiosk = false;     ///< full screen, no window decorations, quitting needs an engineer
};

/// Result of parsing: options to run with, or an exit code when the process is done
/// (help/version printed, or a usage error reported on stderr).
struct GuiParse {
    std::optional<GuiOptions> options;
    int exitCode = 0;
};

/// Parses argv for the GUI; prints help/version/errors itself.
GuiParse parseGuiOptions(int argc, char** argv);

}  // namespace tt::app
