#pragma once

#include "core/ports/history_store.h"
#include "core/storage/database.h"

namespace tt::storage {

/// The schema module "history" (runs, run_points, parts, corrections, measurements, run_state, alarms; since
/// version 5 run_ends and plant_terminal_status, and on PostgreSQL the plant's roles: plant_roles.h).
SchemaModule historySchema();
/// The schema module "adaptation": what the adaptive loop did in each run (adaptations), a module of its own so the
/// history's migrations stay one list per feature. Needs "history" first (its rows name a run).
SchemaModule adaptationSchema();

/// The run history over SQL (SQLite file or PostgreSQL), implementing the loop's HistoryStore port.
/// Each finished part is one transaction (part, corrections, the verdicts on the measurement its
/// correction used, the controller state for resume), so a run killed at any moment loses at most
/// the part in progress. Use from the thread that opened the Database (QtSql rule). Every failure
/// is a StorageError naming what could not be stored; what was stored before stays intact.
class SqlHistoryStore final : public core::HistoryStore {
public:
    /// Applies the "history" and "adaptation" migrations to `database` (which must outlive the store).
    explicit SqlHistoryStore(Database& database);

    std::int64_t beginRun(const core::RunDescription& run) override;
    void recordPart(std::int64_t runId, const core::PartCompletionRecord& part) override;
    void recordMeasurement(std::int64_t runId, const core::PartMeasurementRecord& measurement) override;
    void recordAlarm(std::int64_t runId, const core::AlarmRecord& alarm) override;
    void finishRun(std::int64_t runId, const std::string& status) override;
    void recordAdaptation(std::int64_t runId, const core::AdaptationRecord& adaptation) override;

    std::vector<core::RunSummary> runs() override;
    std::vector<core::StoredPart> parts(std::int64_t runId) override;
    std::vector<core::AlarmRecord> alarms(std::int64_t runId) override;
    std::vector<core::AdaptationRecord> adaptations(std::int64_t runId) override;
    std::optional<core::ResumePoint> resumePoint(std::optional<std::int64_t> runId = std::nullopt) override;

    /// Stores an alarm (as recordAlarm) and returns its row id.
    std::int64_t insertAlarm(std::int64_t runId, const core::AlarmRecord& alarm);

    /// The database the history is stored in.
    Database& database() { return m_db; }

private:
    std::optional<core::RunSummary> run(std::int64_t runId);
    qint64 partId(std::int64_t runId, std::int64_t partNumber);
    void writeMeasurement(qint64 partId, const core::PartMeasurementRecord& measurement);
    std::vector<core::StoredPart> loadParts(std::int64_t runId, std::int64_t fromPartNumber);

    Database& m_db;
};

/// Controller state as text: the kind, then the values with 17 significant digits (exact round trip,
/// "nan" and "inf" included).
std::string encodeControllerValues(const std::vector<double>& values);
/// Inverse of encodeControllerValues; throws StorageError on a damaged text.
std::vector<double> decodeControllerValues(const std::string& text);

}  // namespace tt::storage
