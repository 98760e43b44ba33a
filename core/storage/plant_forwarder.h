#pragma once

#include <QDateTime>
#include <QMetaType>
#include <QString>
#include <cstdint>
#include <memory>
#include <optional>

#include "core/storage/database.h"
#include "core/storage/history_journal.h"
#include "core/storage/journal_batch.h"

namespace tt::storage {

/// Parts per batch sent to the plant database (docs/BENCHMARKS.md, "The plant-wide history": measured with
/// 20 terminals against one server).
inline constexpr int kDefaultForwardBatchParts = 200;

/// The longest a statement of the forwarder may run on the plant database before the server cancels it (the
/// batch is then sent again), ms.
inline constexpr int kForwardStatementTimeoutMs = 60000;

/// How the forwarder sends and retries.
struct ForwarderSettings {
    int batchParts = kDefaultForwardBatchParts;  ///< parts per batch, 1 .. 10000
    double firstRetryS = 0.5;                    ///< the first wait after a failure, doubled after each failure
    double maxRetryS = 30.0;                     ///< the longest wait between two attempts
    double reportEveryS = 10.0;                  ///< how often the terminal reports its backlog while idle
};

/// What the forwarder of a terminal is doing, for the status bar, `simulate --progress` and the log. A copy
/// (a snapshot), safe to pass between threads.
struct ForwarderStatus {
    /// Starting: not yet connected once; Online: the last attempt reached the plant database; Offline: it failed.
    enum class Link { Starting, Online, Offline };
    Link link = Link::Starting;
    QDateTime offlineSince;         ///< local time of the first failed attempt in a row (invalid when online)
    QString reason;                 ///< why offline, in the server's or the network's words
    double retryInS = 0.0;          ///< the wait before the next attempt when offline, s
    std::int64_t backlogParts = 0;  ///< parts stored on this terminal and not yet committed by the plant database
    std::int64_t sentParts = 0;     ///< parts the plant database committed since the forwarder started
    bool drained = false;           ///< online, and nothing is waiting
    std::int64_t journalBytes = 0;  ///< the journal's pages in use
    std::int64_t journalLimitBytes = 0;

    /// The journal is at kJournalWarnShare of its bound or more (the operator is warned).
    bool nearFull() const {
        return journalLimitBytes > 0 &&
               journalBytes >= static_cast<std::int64_t>(kJournalWarnShare * journalLimitBytes);
    }
    /// The journal is at its bound: the loop takes no new part.
    bool full() const { return journalLimitBytes > 0 && journalBytes >= journalLimitBytes; }
    /// One line in English: "plant database offline since 14:02, 37 parts kept on this terminal (...)",
    /// "plant database: every part sent", "plant database: sending, 120 parts kept on this terminal".
    QString describe() const;
};

/// Sends a terminal's journal to the plant database: reads the outbox after what the server committed,
/// inserts a batch in one server transaction (writePlantBatch: idempotent), then records it as committed in
/// the journal and, above kJournalTrimShare of the bound, deletes the oldest committed parts from the
/// journal. Opens its connections (the journal's and the server's) in the thread that calls it; a failed
/// attempt drops the server's connection, the next one connects again. Not thread-safe: one thread
/// (PlantForwarderThread) drives it.
class PlantForwarder {
public:
    /// `journalPath` is opened at once (it exists: the loop made it); the plant database at the first send.
    PlantForwarder(const QString& journalPath, const DatabaseConfig& plant, const QString& machine,
                   std::int64_t journalLimitBytes, const ForwarderSettings& settings = {});
    ~PlantForwarder();
    PlantForwarder(const PlantForwarder&) = delete;
    PlantForwarder& operator=(const PlantForwarder&) = delete;

    /// Sends the next batch; returns the parts in it (a batch may hold only alarms or run ends: 0), none when
    /// nothing was waiting. Throws StorageError when the plant database cannot be reached or refuses the batch
    /// (nothing of it is kept there).
    std::optional<std::int64_t> sendBatch();
    /// Records the terminal's backlog in the plant database (a heartbeat); throws StorageError.
    void report();
    /// Forgets the plant database's connection (after a failure).
    void disconnect();
    /// Parts not yet committed by the plant database (read from the journal; works offline).
    std::int64_t backlogParts();
    /// The journal's size against its bound.
    JournalUsage usage();

private:
    Database& plant();
    TerminalReport terminalReport(std::int64_t backlog);

    DatabaseConfig m_plantConfig;
    QString m_machine;
    std::int64_t m_limitBytes;
    ForwarderSettings m_settings;
    std::unique_ptr<Database> m_journal;
    std::unique_ptr<Database> m_plant;
};

}  // namespace tt::storage

Q_DECLARE_METATYPE(tt::storage::ForwarderStatus)
