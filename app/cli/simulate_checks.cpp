#include "app/cli/simulate_checks.h"

#include <cstdio>
#include <stdexcept>
#include <string>

#include "app/cli/command.h"
#include "app/cli/command_parser.h"
#include "app/cli/run_interrupt.h"
#include "core/run/run_limits.h"

namespace tt::cli {

namespace {

/// "1 (complete, 100 parts), 2 (running, 40 parts)": the newest `shown` runs of the history.
std::string listRuns(core::HistoryStore& history) {
    constexpr std::size_t shown = 10;
    const std::vector<core::RunSummary> runs = history.runs();
    if (runs.empty()) return "the history holds no run";
    std::string list;
    for (std::size_t i = 0; i < runs.size() && i < shown; ++i)
        list += (i ? ", " : "") + std::to_string(runs[i].runId) + " (" + runs[i].status + ", " +
                std::to_string(runs[i].partCount) + " parts)";
    if (runs.size() > shown) list += " and " + std::to_string(runs.size() - shown) + " older";
    return "the history holds run(s) " + list;
}

}  // namespace

QStringList splitResumeRun(const QStringList& arguments) {
    QStringList out;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString& a = arguments[i];
        if (a.startsWith(QLatin1String("--resume="))) {
            out << QStringLiteral("--resume") << QStringLiteral("--run") << a.mid(9);
        } else if (a == QLatin1String("--resume") && i + 1 < arguments.size() &&
                   !arguments[i + 1].startsWith(QLatin1Char('-'))) {
            out << a << QStringLiteral("--run") << arguments[++i];
        } else {
            out << a;
        }
    }
    return out;
}

double simulationSpeed(const CommandParser& parser) {
    const double speed = parser.number(QStringLiteral("speed"), 0.0, core::kMaxRunSpeed);
    try {
        core::checkRunSpeed(speed);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--speed: ") + e.what());
    }
    return speed;
}

std::optional<std::int64_t> resumeRunId(const CommandParser& parser) {
    if (!parser.isSet(QStringLiteral("run"))) return std::nullopt;
    if (!parser.isSet(QStringLiteral("resume"))) throw UsageError("--run: only with --resume, the run to continue");
    try {
        return parser.integer(QStringLiteral("run"), 1, 1LL << 53);
    } catch (const UsageError& e) {  // written as --resume N by the user
        throw UsageError(std::string("--resume N: the run number ") + std::string(e.what()).substr(7));
    }
}

core::ResumePoint findResumePoint(core::HistoryStore& history, std::optional<std::int64_t> runId) {
    const std::string which = runId ? "run " + std::to_string(*runId) : "the last run";
    bool exists = !runId;
    if (runId)
        for (const core::RunSummary& r : history.runs())
            exists = exists || r.runId == *runId;
    if (!exists) throw UsageError("--resume: there is no run " + std::to_string(*runId) + "; " + listRuns(history));
    const std::optional<core::ResumePoint> point = history.resumePoint(runId);
    if (!point) throw UsageError("--resume: " + which + " has no finished part to continue from; " + listRuns(history));
    if (point->run.status == "complete")
        throw UsageError("--resume: " + which + " (" + std::to_string(point->run.runId) + ") is already complete; " +
                         listRuns(history));
    return *point;
}

void checkStoredParts(std::int64_t parts, std::int64_t warmupParts) {
    try {
        core::checkRunParts(parts, warmupParts);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--resume: the settings stored with the run ask for ") + e.what());
    }
}

QString kEffUndefinedNote() {
    return QStringLiteral(
        "k_eff n/a: the open- or closed-loop variance is below 1e-12 mm² (σ 1 nm): the parts do "
        "not vary from one to the next, so their ratio is no effectiveness");
}

std::optional<core::LatheStudyResult> runStudyUntilStopped(const core::ShaftScenario& scenario, std::uint64_t seed,
                                                           core::LatheStudyOptions options, bool progress,
                                                           const QString& database) {
    const InterruptGuard interrupts;
    options.stop = &InterruptGuard::stopRequested();
    ProgressPrinter printer(progress);
    if (printer.enabled())
        options.progress = [&printer](const std::string& stage, std::int64_t part, std::int64_t total) {
            printer.report(stage, part, total);
        };
    try {
        core::LatheStudyResult result = core::runLatheStudy(scenario, seed, options);
        printer.finish();
        return result;
    } catch (const core::StudyInterrupted& stop) {
        printer.finish();
        reportInterrupted(stop, database);
        return std::nullopt;
    }
}

int reportInterrupted(const core::StudyInterrupted& stop, const QString& database) {
    std::string why = "trueturn simulate: interrupted after part " + std::to_string(stop.lastPart);
    if (!stop.closedLoop)
        why += " of the open-loop reference; the stored run is complete, no result is printed";
    else if (stop.runId)
        why += "; every finished part is stored; continue with: trueturn simulate --db " + database.toStdString() +
               " --resume " + std::to_string(*stop.runId);
    else
        why += "; nothing was stored (no --db)";
    std::fprintf(stderr, "%s\n", why.c_str());
    return kExitInterrupted;
}

}  // namespace tt::cli
