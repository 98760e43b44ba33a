#include "app/cli/run_interrupt.h"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <utility>

#include "app/cli/command_parser.h"

namespace tt::cli {

namespace {

std::atomic<bool> g_stop{false};
struct sigaction g_previousInt {};
struct sigaction g_previousTerm {};

extern "C" void onStopSignal(int /*signal*/) {
    g_stop.store(true);
}

std::int64_t nowMs() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

}  // namespace

InterruptGuard::InterruptGuard() {
    static_assert(std::atomic<bool>::is_always_lock_free, "the stop flag is set from a signal handler");
    g_stop.store(false);
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // a second Ctrl-C ends the process
    sigaction(SIGINT, &action, &g_previousInt);
    sigaction(SIGTERM, &action, &g_previousTerm);
}

InterruptGuard::~InterruptGuard() {
    sigaction(SIGINT, &g_previousInt, nullptr);
    sigaction(SIGTERM, &g_previousTerm, nullptr);
}

const std::atomic<bool>& InterruptGuard::stopRequested() {
    return g_stop;
}

ProgressPrinter::ProgressPrinter(bool forced, std::string unit)
    : m_terminal(isatty(STDERR_FILENO) == 1), m_unit(std::move(unit)) {
    m_enabled = forced || m_terminal;
}

ProgressPrinter::~ProgressPrinter() {
    finish();
}

void ProgressPrinter::report(const std::string& stage, std::int64_t done, std::int64_t total) {
    if (!m_enabled) return;
    const std::int64_t now = nowMs();
    const bool last = done >= total;
    if (stage == m_stage && !last && m_lastMs >= 0 && now - m_lastMs < 250) return;
    if (stage != m_stage) finish();
    m_stage = stage;
    m_lastMs = now;
    const double percent = total > 0 ? 100.0 * static_cast<double>(done) / static_cast<double>(total) : 0.0;
    std::fprintf(stderr, "%s%s: %s%s%lld of %lld (%.0f %%)%s", m_terminal ? "\r" : "", stage.c_str(), m_unit.c_str(),
                 m_unit.empty() ? "" : " ", static_cast<long long>(done), static_cast<long long>(total), percent,
                 m_terminal ? "" : "\n");
    std::fflush(stderr);
    m_lineOpen = m_terminal;
}

int reportCancelled(ProgressPrinter& progress, const char* command, const char* kept) {
    progress.finish();
    std::fprintf(stderr, "trueturn %s: interrupted; %s\n", command, kept);
    return kExitInterrupted;
}

void addProgressOption(CommandParser& parser) {
    parser.addOption(QStringLiteral("progress"),
                     QStringLiteral("Report the work done on stderr (always when stderr is a terminal)."));
}

void ProgressPrinter::finish() {
    if (m_lineOpen) std::fputc('\n', stderr);
    m_lineOpen = false;
}

}  // namespace tt::cli
