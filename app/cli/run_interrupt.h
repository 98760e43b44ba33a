#pragma once

#include <QString>
#include <atomic>
#include <cstdint>
#include <string>

namespace tt::cli {

/// Exit code of a command stopped by Ctrl-C or SIGTERM (128 + SIGINT, as the shells report it).
inline constexpr int kExitInterrupted = 130;

/// While alive, SIGINT and SIGTERM only set stopRequested(): the long work stops at a safe point (a
/// simulated run after its current part, everything stored committed). A second signal ends the
/// process at once (the default action is restored by the first). The previous handlers come back on
/// destruction.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// Set by SIGINT or SIGTERM while a guard is alive.
    static const std::atomic<bool>& stopRequested();
};

/// Progress of long work on stderr: `stage: part N of M (P %)`, at most every 0.25 s. On a terminal one
/// line is rewritten in place; with `--progress` and stderr not a terminal (a log) each report is a line.
class ProgressPrinter {
public:
    /// Prints when stderr is a terminal or `forced` (--progress); `unit` names what is counted ("part"; empty:
    /// the stage says it).
    explicit ProgressPrinter(bool forced, std::string unit = "part");
    ~ProgressPrinter();
    ProgressPrinter(const ProgressPrinter&) = delete;
    ProgressPrinter& operator=(const ProgressPrinter&) = delete;

    /// Reports `done` of `total` in `stage`; the last one of a stage is always printed.
    void report(const std::string& stage, std::int64_t done, std::int64_t total);
    /// Ends a line rewritten in place (before a message or the result).
    void finish();
    /// Whether anything is printed.
    bool enabled() const { return m_enabled; }

private:
    bool m_enabled = false;
    bool m_terminal = false;
    bool m_lineOpen = false;
    std::int64_t m_lastMs = -1;
    std::string m_stage;
    std::string m_unit;
};

class CommandParser;

/// Adds `--progress` to a command's options (progress on stderr also when it is not a terminal).
void addProgressOption(CommandParser& parser);

/// For work stopped by Ctrl-C or SIGTERM before it finished: ends the progress line, says on stderr
/// that `command` was interrupted and `kept` (what stays as it was), returns kExitInterrupted.
int reportCancelled(ProgressPrinter& progress, const char* command, const char* kept);

}  // namespace tt::cli
