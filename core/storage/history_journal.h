#pragma once

#include <QString>
#include <cstdint>
#include <functional>
#include <memory>

#include "core/ports/history_store.h"
#include "core/storage/database.h"
#include "core/storage/history_store.h"

namespace tt::storage {

/// Default bound of a terminal's journal, bytes (1 GiB): about 3 million parts of 5 points.
inline constexpr std::int64_t kDefaultJournalLimitBytes = 1LL << 30;
/// Share of the bound from which the operator is warned (ForwarderStatus::nearFull).
inline constexpr double kJournalWarnShare = 0.9;
/// Share of the bound above which parts the plant database already holds are deleted from the journal.
inline constexpr double kJournalTrimShare = 0.5;

/// The QSettings key of the journal's bound in MiB (default kDefaultJournalLimitBytes).
inline constexpr const char* kJournalLimitSetting = "history/journal_limit_mb";

/// A terminal's journal: where it is, whose history it holds and how big it may grow.
struct JournalOptions {
    QString path;     ///< the SQLite file (created when missing)
    QString machine;  ///< the lathe whose runs it holds (stored with every run; the plant database checks it)
    QString plant;    ///< the plant database it forwards to (DatabaseConfig::describe(), no password)
    std::int64_t limitBytes = kDefaultJournalLimitBytes;  ///< at this size no new part is taken (loop pauses)
};

/// The journal of `machine` for the plant database `plant`, next to the application's data:
/// <AppDataLocation>/journal/<machine>@<host>-<port>-<database>.sqlite (the folder is created). Throws
/// StorageError when the folder cannot be created.
QString defaultJournalPath(const QString& machine, const DatabaseConfig& plant);

/// The journal's bound from QSettings (kJournalLimitSetting, MiB), kDefaultJournalLimitBytes when unset.
std::int64_t journalLimitFromSettings();

/// The schema module "journal" of a terminal's journal: the outbox (every stored item in the order the loop
/// stored it, for the forwarder) and the journal's own state (machine, plant, what the plant committed).
SchemaModule journalSchema();

/// How full a journal is, in bytes of the SQLite pages in use (free pages are reused, not counted).
struct JournalUsage {
    std::int64_t usedBytes = 0;
    std::int64_t limitBytes = 0;
    bool nearFull() const { return usedBytes >= static_cast<std::int64_t>(kJournalWarnShare * limitBytes); }
    bool full() const { return usedBytes >= limitBytes; }
};

/// The bytes of `journal`'s pages in use.
std::int64_t journalUsedBytes(Database& journal);

/// A terminal's local history, written first by the loop: an SQLite file (WAL, synchronous=FULL) holding the
/// same history tables as any TrueTurn history plus an outbox. Every part, reading, verdict, alarm, correction
/// and run end is stored in the loop's own transaction together with its outbox entry; the forwarder
/// (PlantForwarder) sends the outbox to the plant database in order and records what the server committed.
/// A reading enters the outbox once it is final: when the part whose correction used it is stored (with the
/// controller's verdicts), when its run ends, or when another run begins (an abandoned run's last readings).
/// Takes no new part (refusesNextPart) when the journal reaches its bound. Use from one thread (QtSql).
class HistoryJournal final : public core::HistoryStore {
public:
    /// Opens (creates) the journal. Throws StorageError when the file belongs to another machine or plant,
    /// cannot be opened, or is not a TrueTurn journal.
    explicit HistoryJournal(const JournalOptions& options);
    ~HistoryJournal() override;

    std::int64_t beginRun(const core::RunDescription& run) override;
    void recordPart(std::int64_t runId, const core::PartCompletionRecord& part) override;
    void recordMeasurement(std::int64_t runId, const core::PartMeasurementRecord& measurement) override;
    void recordAlarm(std::int64_t runId, const core::AlarmRecord& alarm) override;
    void finishRun(std::int64_t runId, const std::string& status) override;
    /// Kept in this terminal's journal (and its audit trail); not forwarded to the plant database yet.
    void recordAdaptation(std::int64_t runId, const core::AdaptationRecord& adaptation) override;

    std::vector<core::RunSummary> runs() override;
    std::vector<core::StoredPart> parts(std::int64_t runId) override;
    std::vector<core::AlarmRecord> alarms(std::int64_t runId) override;
    std::vector<core::AdaptationRecord> adaptations(std::int64_t runId) override;
    std::optional<core::ResumePoint> resumePoint(std::optional<std::int64_t> runId = std::nullopt) override;
    /// HistoryFull when the journal's pages in use reach the bound.
    core::Notice refusesNextPart() override;

    /// Its size against the bound.
    JournalUsage usage();
    /// Parts stored here that the plant database has not committed yet.
    std::int64_t backlogParts();
    /// Called after every write that adds to the outbox (the forwarder is woken with it); may be empty.
    void setWrittenCallback(std::function<void()> callback) { m_written = std::move(callback); }
    /// The options it was opened with.
    const JournalOptions& options() const { return m_options; }
    /// The journal's database (the loop's connection).
    Database& database() { return *m_db; }

private:
    void enqueue(const char* kind, std::int64_t runId, std::int64_t item, const QString& status = {});
    void enqueueOpenMeasurements(std::int64_t runId);
    void bindTo(const JournalOptions& options);

    JournalOptions m_options;
    std::unique_ptr<Database> m_db;
    std::unique_ptr<SqlHistoryStore> m_history;
    std::function<void()> m_written;
};

}  // namespace tt::storage
