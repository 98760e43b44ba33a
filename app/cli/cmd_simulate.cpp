// `trueturn simulate`: options and output only. The run is one run request (runtime/run/run_request.h: made
// from the options, read with --request FILE.json, or stored with the run that --resume continues), the same
// value the Run page starts; its scenario is runtime::scenarioOf, the closed loop and the open-loop reference
// run in core::runLatheStudy on the built-in simulated lathe, stepped by core::ShaftRunStepper like the
// Run page's loop (with --cnc the closed run goes on the LinuxCNC lathe instead: app/cli/simulate_cnc.h); the
// history is storage::SqlHistoryStore.
#include <QFileInfo>
#include <QString>
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_parser.h"
#include "app/cli/run_history.h"
#include "app/cli/run_interrupt.h"
#include "app/cli/simulate_adaptation.h"
#include "app/cli/simulate_checks.h"
#include "app/cli/simulate_cnc.h"
#include "app/cli/simulate_output.h"
#include "app/cli/simulate_request.h"
#include "app/cli/simulate_verdicts.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"
#include "runtime/run/stored_runs.h"
#include "runtime/run/study_request.h"

namespace tt::cli {

namespace {

/// What the invocation runs: the request and, with --resume, where the stored run continues.
struct Invocation {
    runtime::RunRequest request;
    std::optional<core::ResumePoint> resume;
};

void addSimulateOptions(CommandParser& parser) {
    addRunRequestOptions(parser);
    addRunHistoryOptions(parser);
    parser.addOption(QStringLiteral("profile"),
                     QStringLiteral("Add the profile of the finished parts: mean and standard deviation of the "
                                    "diameter error along the part, after the loop's start-up (2z + 5 parts)."));
    parser.addOption(QStringLiteral("profile-step"),
                     QStringLiteral("Spacing of the profile positions, 1..100 mm (default 12.5: the paper's 25 mm "
                                    "grid and the middle)."),
                     QStringLiteral("mm"), QStringLiteral("12.5"));
    parser.addOption(QStringLiteral("db"),
                     QStringLiteral("Store the run in this history (each part one transaction): an SQLite file or "
                                    "postgresql://user@host:port/database."),
                     QStringLiteral("file"));
    parser.addOption(QStringLiteral("resume"),
                     QStringLiteral("Continue a run stored in --db from its next part, with its own request and the "
                                    "stored controller state: --resume N continues run N, --resume alone the newest."));
    parser.addOption(QStringLiteral("run"), QStringLiteral("With --resume: the run to continue (as --resume N)."),
                     QStringLiteral("N"));
    parser.addOption(QStringLiteral("request"),
                     QStringLiteral("Run this run request (JSON, the format --dump-request prints and the Run page "
                                    "stores) instead of the run options."),
                     QStringLiteral("file"));
    parser.addOption(QStringLiteral("dump-preset"),
                     QStringLiteral("Print the set-up that would run (the preset merged over its based_on chain, "
                                    "with the request's tuning and plant applied) as JSON, and run nothing."));
    parser.addOption(QStringLiteral("dump-request"),
                     QStringLiteral("Print the run request the options (or --request, or the run --resume continues) "
                                    "make, as JSON, and run nothing."));
    addProgressOption(parser);
}

std::optional<QString> databaseOption(const CommandParser& parser) {
    if (!parser.isSet(QStringLiteral("db"))) return std::nullopt;
    return parser.value(QStringLiteral("db"));
}

/// The history of a --db run, opened before the run: an SQLite file itself, a plant database (postgresql://)
/// through the terminal's journal.
std::unique_ptr<RunHistory> openHistory(const CommandParser& parser, const QString& database, bool resume) {
    if (resume && !isPostgresOption(database) && !QFileInfo::exists(database))
        throw UsageError("--db: '" + database.toStdString() + "' does not exist, so there is nothing to resume");
    return std::make_unique<RunHistory>(parser, database, parser.isSet(QStringLiteral("progress")));
}

/// The stored run --resume continues, with its own request.
Invocation resumedRun(const CommandParser& parser, core::HistoryStore& history) {
    if (const std::optional<QString> option = runOptionGiven(parser))
        throw UsageError(option->toStdString() + ": a resumed run keeps its own settings; leave the option out");
    if (parser.isSet(QStringLiteral("request")))
        throw UsageError("--request: a resumed run keeps its own request; leave the option out");
    Invocation run;
    run.resume = findResumePoint(history, resumeRunId(parser));
    try {
        run.request = runtime::requestOfStoredRun(run.resume->run);
    } catch (const runtime::RunRequestError& e) {
        throw UsageError(std::string("--resume: ") + e.what());
    }
    if (!run.request.cnc.isEmpty())
        throw UsageError("--resume: run " + std::to_string(run.resume->run.runId) + " went through " +
                         run.request.cnc.toStdString() + "; a run through a CNC is not resumed headless");
    if (!run.request.endPart)
        throw UsageError("--resume: run " + std::to_string(run.resume->run.runId) +
                         " was started on the Run page without a last part; continue it there");
    checkStoredParts(*run.request.endPart - run.request.warmupParts, run.request.warmupParts);
    return run;
}

/// The request of --request FILE.json (its database replaced by --db when given).
runtime::RunRequest requestFromFile(const CommandParser& parser, const std::optional<QString>& database) {
    if (const std::optional<QString> option = runOptionGiven(parser))
        throw UsageError(option->toStdString() + ": the run request file sets the run; leave the option out");
    try {
        runtime::RunRequest q = runtime::readRunRequestFile(parser.value(QStringLiteral("request")));
        if (database) q.database = *database;
        runtime::validate(q);
        if (!q.endPart) throw runtime::RunRequestError("end_part", "a headless run needs its last part");
        return q;
    } catch (const runtime::RunRequestError& e) {
        throw usageErrorOf(e, QStringLiteral("--request"));
    }
}

Invocation invocationOf(const CommandParser& parser, const std::optional<QString>& database,
                        core::HistoryStore* history) {
    if (parser.isSet(QStringLiteral("resume"))) {
        Invocation run = resumedRun(parser, *history);
        run.request.database = *database;
        return run;
    }
    if (parser.isSet(QStringLiteral("request"))) return {requestFromFile(parser, database), std::nullopt};
    return {requestFromOptions(parser, database.value_or(QString())), std::nullopt};
}

/// Where the profile is taken: every `step` mm along the part and its end.
std::vector<double> profilePositions(double lengthMm, double stepMm) {
    std::vector<double> z;
    const int steps = static_cast<int>(std::floor(lengthMm / stepMm + 1e-9));
    for (int i = 0; i <= steps; ++i)
        z.push_back(std::min(lengthMm, i * stepMm));
    if (z.back() < lengthMm - 1e-9) z.push_back(lengthMm);
    return z;
}

int runStudy(const CommandParser& parser, const Invocation& run, RunHistory* history) {
    const config::LoopScenario scenario = runtime::scenarioOf(run.request);
    core::LatheStudyOptions options = runtime::studyOptionsOf(run.request, scenario);
    const bool profile = parser.isSet(QStringLiteral("profile"));
    if (profile)
        options.profileZMm =
            profilePositions(scenario.partLengthMm, parser.number(QStringLiteral("profile-step"), 1.0, 100.0));
    options.history = history ? &history->store() : nullptr;
    options.resume = run.resume;
    CncRunReport cnc;
    if (!run.request.cnc.isEmpty()) {
        checkCncReachable(run.request);
        options.machine = cncMachineFactory(run.request, cnc, options.history);
    }
    // A run that stops early (a fault, a history that cannot be written) is a std::runtime_error: exit 1 with
    // the reason; what was stored stays stored and the run can be resumed. Ctrl-C or SIGTERM: the run stops
    // after its current part, everything stored is committed, exit 130.
    const std::optional<QString> database =
        run.request.database.isEmpty() ? std::nullopt : std::optional<QString>(run.request.database);
    const std::optional<core::LatheStudyResult> study = runStudyUntilStopped(
        scenario, run.request.seed, options, parser.isSet(QStringLiteral("progress")), database.value_or(QString()));
    if (!study) return kExitInterrupted;
    if (history) history->finish();
    if (parser.json()) {
        QJsonObject out = simulateJson(*study, scenario, profile, database);
        addAdaptationJson(out, *study, scenario);
        if (history) history->addJson(out);
        if (!run.request.cnc.isEmpty()) addCncJson(out, cnc);
        printJson(out);
    } else {
        printSimulateText(run.request.preset, *study, run.request.seed, profile);
        if (!run.request.cnc.isEmpty()) printCncText(run.request.cnc, cnc);
        printAdaptationText(*study);
    }
    return kExitOk;
}

int run(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("simulate"),
                         QStringLiteral("The closed loop on the built-in simulator, headless (paper 000): parts are "
                                        "machined, measured and corrected part by part with the controller; the open "
                                        "loop runs on the same disturbance for k_eff per control point (Table 2). A "
                                        "preset with a lathe section runs the physical lathe, otherwise the "
                                        "controller's statistical plant. The warm-up parts are machined, stored and "
                                        "judged like the others but not counted in k_eff."));
    addSimulateOptions(parser);
    parser.parse(splitResumeRun(arguments));
    const std::optional<QString> database = databaseOption(parser);
    const bool resume = parser.isSet(QStringLiteral("resume"));
    if (resume && !database) throw UsageError("--resume: needs --db, the history of the run to continue");
    resumeRunId(parser);  // --run without --resume, or a bad number, is refused before anything is opened
    std::unique_ptr<RunHistory> history;
    if (parser.isSet(QStringLiteral("dump-preset")) && database && !resume)
        throw UsageError("--dump-preset: prints the set-up and runs nothing; leave --db out");
    const bool dumps = parser.isSet(QStringLiteral("dump-request")) || parser.isSet(QStringLiteral("dump-preset"));
    if (database && (!dumps || resume)) history = openHistory(parser, *database, resume);
    const Invocation run = invocationOf(parser, database, history ? &history->store() : nullptr);
    if (parser.isSet(QStringLiteral("dump-request"))) {
        printJson(runtime::toJson(run.request));
        return kExitOk;
    }
    if (parser.isSet(QStringLiteral("dump-preset"))) {
        printJson(presetDump(runtime::scenarioOf(run.request)));
        return kExitOk;
    }
    return runStudy(parser, run, history.get());
}

}  // namespace

Command makeSimulateCommand() {
    return {QStringLiteral("simulate"),
            QStringLiteral("The closed loop on the built-in simulator: k_eff of LQG, EWMA or open loop (Table 2), "
                           "the profile of the parts, a stored and resumable run"),
            run};
}

}  // namespace tt::cli
