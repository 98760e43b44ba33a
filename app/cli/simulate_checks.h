#pragma once

// The checks of `trueturn simulate`'s options and of the settings stored with a run, before any work
// (issue 17, "Bad input"): the pacing speed, the parts of a resumed run, which run --resume continues.
#include <QString>
#include <QStringList>
#include <cstdint>
#include <optional>

#include "core/ports/history_store.h"
#include "core/run/shaft_study.h"

namespace tt::cli {

class CommandParser;

/// `--resume N` and `--resume=N` written as `--resume --run N` (QCommandLineParser has no optional
/// values); other arguments unchanged.
QStringList splitResumeRun(const QStringList& arguments);

/// --speed: 0 (as fast as possible) or core::kMinRunSpeed .. core::kMaxRunSpeed; a UsageError names
/// the value and the range.
double simulationSpeed(const CommandParser& parser);

/// The run --resume continues: --run N (1 .. 2^53) or none for the newest.
std::optional<std::int64_t> resumeRunId(const CommandParser& parser);

/// Where run `runId` (the newest when none) continues; a UsageError when the history has no such run,
/// it has no finished part or it is complete, listing the runs the history holds.
core::ResumePoint findResumePoint(core::HistoryStore& history, std::optional<std::int64_t> runId);

/// The parts of a resumed run's stored settings within the limits of a new run (the settings may have
/// been edited in the database); a UsageError names the value and the limit.
void checkStoredParts(std::int64_t parts, std::int64_t warmupParts);

/// Why k_eff is "n/a": a variance (open or closed loop) below 1e-12 mm², as on a lathe without variation.
QString kEffUndefinedNote();

/// Runs the study with SIGINT/SIGTERM as a stop after the current part (InterruptGuard) and the parts
/// done on stderr when `progress` or stderr is a terminal; none after an interruption, which is
/// reported on stderr (reportInterrupted).
std::optional<core::LatheStudyResult> runStudyUntilStopped(const core::ShaftScenario& scenario, std::uint64_t seed,
                                                           core::LatheStudyOptions options, bool progress,
                                                           const QString& database);

/// Reports an interrupted study on stderr (what is stored, how to resume) and returns kExitInterrupted.
int reportInterrupted(const core::StudyInterrupted& stop, const QString& database);

}  // namespace tt::cli
