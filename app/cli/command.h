#pragma once

#include <QString>
#include <QStringList>
#include <functional>
#include <stdexcept>
#include <vector>

namespace tt::cli {

/// Bad input to a command: printed as one line on stderr ("trueturn lqg: --delay: 9 is outside
/// 1 .. 8") and the process exits with code 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Exit codes of every command.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  ///< the command ran but the work failed (I/O, numerics)
inline constexpr int kExitUsage = 2;    ///< bad command, option or input
/// The work ran but its result is outside the tolerance asked for (schedule-feed --verify).
inline constexpr int kExitOutOfTolerance = 3;

/// One headless sub-command of `trueturn` (DESIGN.md, "Command line").
struct Command {
    QString name;
    QString summary;  ///< one line, shown by `trueturn --help`
    /// Runs with the arguments after the command name; returns the exit code, throws UsageError.
    std::function<int(const QStringList& arguments)> run;
    /// Whether the command, given these arguments, paints (fonts, charts into a PDF): runCommand then makes
    /// a QApplication on the offscreen platform instead of a QCoreApplication. Empty: never.
    std::function<bool(const QStringList& arguments)> paints = {};
};

/// Every command, in the order `--help` lists them (app/cli/commands.cpp).
const std::vector<Command>& commands();

/// The command names, comma separated ("bench, fit-profile, lqg, simulate").
QString commandNames();

/// Runs `trueturn <command> ...` (argv[1] is the command). Creates the QCoreApplication.
int runCommand(int argc, char** argv);

}  // namespace tt::cli
