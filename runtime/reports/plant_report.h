#pragma once

#include <QDateTime>
#include <QJsonObject>
#include <QString>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/common/tolerance.h"
#include "core/storage/database.h"
#include "core/storage/plant_query.h"

namespace tt::runtime {

/// A machine's state on the plant overview.
enum class MachineState {
    Running,  ///< its newest run has not ended and stored a part within kRunningWithinS
    Idle,     ///< otherwise, when its terminal reports (or it writes without a journal)
    Offline,  ///< its terminal has not reported for kOfflineAfterS (the plant database does not hear from it)
};

/// A part stored this long ago or less means the machine is running, s.
inline constexpr qint64 kRunningWithinS = 600;
/// A terminal silent this long is offline, s (it reports every 10 s while idle, with every batch otherwise).
inline constexpr qint64 kOfflineAfterS = 60;
/// Parts in a capability window of the overview (the last 125, compared with the 125 before).
inline constexpr int kPlantWindowParts = 125;

/// "running", "idle", "offline".
std::string machineStateName(MachineState state);

/// The capability of one control point of a machine: Cpk of its newest window of readings and of the window
/// before, computed as `trueturn report --machine M --point I --last N [--skip N]` computes them (I-MR,
/// core/quality's analysePoint, the stored tolerance of the newest judged reading).
struct PlantPointCapability {
    int pointIndex = 0;  ///< 0-based
    double zMm = 0.0;
    std::int64_t count = 0;        ///< readings in the newest window
    std::int64_t countBefore = 0;  ///< readings in the window before
    std::optional<double> cpk;        ///< none: no tolerance stored, or too few readings
    std::optional<double> cpkBefore;  ///< none: the same, for the window before
    /// cpk - cpkBefore when both exist.
    std::optional<double> change() const {
        return cpk && cpkBefore ? std::optional<double>(*cpk - *cpkBefore) : std::nullopt;
    }
};

/// One machine of the plant overview.
struct PlantMachine {
    std::string machine;
    MachineState state = MachineState::Idle;
    std::optional<QDateTime> lastPartAt;       ///< UTC
    std::optional<QDateTime> reportedAt;       ///< when its terminal last reported, UTC
    std::optional<std::int64_t> backlogParts;  ///< parts kept on its terminal, when the terminal reports it
    bool journalNearFull = false;              ///< its journal is near its bound (the last report)
    std::optional<std::int64_t> runId;         ///< its newest run in the plant database
    core::VerdictCounts today;                 ///< the day's parts by their verdict (worst of their points)
    std::int64_t todayParts = 0;               ///< the day's parts, with or without a verdict
    std::vector<PlantPointCapability> points;  ///< ascending point
    std::int64_t openAlarmCount = 0;           ///< alarms of its newest run while it has not ended
    std::vector<storage::PlantAlarm> openAlarms;  ///< the newest of them, newest first
};

/// The plant overview at one moment.
struct PlantOverview {
    QDateTime at;       ///< when the states are judged, UTC
    QDateTime dayFrom;  ///< the day counted ("today"): local midnight of `at`, as UTC
    QDateTime dayTo;
    int windowParts = kPlantWindowParts;
    std::vector<PlantMachine> machines;
};

/// The plant overview of `db` at `at` (now by default): every machine with its state, backlog, the local day's
/// verdicts, per point the Cpk of its newest `windowParts` readings and of the ones before, its open alarms.
/// Throws storage::StorageError.
PlantOverview plantOverview(storage::Database& db, const QDateTime& at = QDateTime::currentDateTimeUtc(),
                            int windowParts = kPlantWindowParts);

/// The overview as JSON (`trueturn plant --json`; docs in README).
QJsonObject plantOverviewJson(const PlantOverview& overview);

}  // namespace tt::runtime
