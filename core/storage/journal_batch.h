#pragma once

#include <QString>
#include <QVariant>
#include <QVariantList>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "core/storage/database.h"

namespace tt::storage {

/// A stretch of a journal's outbox with the rows it names, as the plant database receives it. Values are
/// copied column by column (QVariants of the journal's columns), so the plant holds exactly what the journal
/// holds. Rows are named by their natural key (the run's uid, the part number, the point), never by the
/// journal's row ids, so the batch inserts the same rows whichever ids the plant database gives.
struct JournalBatch {
    /// A run the batch refers to, with its points.
    struct Run {
        QString uid;
        QVariantList columns;  ///< kRunColumns, in order (run_uid last)
        std::vector<QVariantList> points;  ///< point_index, z_mm
    };
    /// A part with its corrections.
    struct Part {
        QString runUid;
        std::int64_t partNumber = 0;
        QVariantList columns;                   ///< started_s, finished_s, recorded_at
        std::vector<QVariantList> corrections;  ///< point_index, z_mm, computed_mm, applied_mm
    };
    /// The final readings of a part.
    struct Measurement {
        QString runUid;
        std::int64_t partNumber = 0;
        std::vector<QVariantList> points;  ///< kMeasurementColumns without part_id, in order
    };
    /// An alarm, known by its journal sequence within the run.
    struct Alarm {
        QString runUid;
        std::int64_t seq = 0;
        QVariantList columns;  ///< part_number, time_s, kind, message, recorded_at
    };
    /// The end of a run (a run ends once per stop, resume and completion).
    struct End {
        QString runUid;
        std::int64_t seq = 0;
        QString status;
        QString finishedAt;
    };

    std::int64_t firstSeq = 0;  ///< the oldest outbox entry of the batch
    std::int64_t lastSeq = 0;   ///< the newest; the plant has everything up to it once the batch is committed
    std::vector<Run> runs;      ///< every run the entries refer to
    std::vector<Part> parts;
    std::vector<Measurement> measurements;
    std::vector<Alarm> alarms;
    std::vector<End> ends;

    bool empty() const { return lastSeq == 0; }
};

/// The outbox entries after `afterSeq` of `journal` in order, up to `maxParts` parts (and the other entries
/// between them, at most 8 × maxParts entries), with their rows. Empty when nothing is waiting. Throws
/// StorageError on a journal that cannot be read.
JournalBatch readJournalBatch(Database& journal, std::int64_t afterSeq, int maxParts);

/// Inserts `batch` into the plant database `plant` in ONE transaction, idempotently: every row is inserted
/// unless its natural key is there (ON CONFLICT DO NOTHING on the unique keys: run uid, (run, part), (part,
/// point), (run, alarm sequence), (run, end)), so a batch sent twice (a commit whose answer was lost) inserts
/// nothing twice. With `status` also records the terminal's report (plant_terminal_status) in the same
/// transaction. Throws StorageError with the server's words; nothing is kept of a failed batch.
struct TerminalReport {
    QString machine;
    std::int64_t backlogParts = 0;  ///< parts still in the journal after this batch
    std::int64_t journalBytes = 0;
    std::int64_t journalLimitBytes = 0;
};
void writePlantBatch(Database& plant, const JournalBatch& batch, const std::optional<TerminalReport>& status = {});

/// Records the terminal's report alone (no batch): after the journal drained, and as a heartbeat.
void writeTerminalReport(Database& plant, const TerminalReport& status);

/// The newest outbox entry the plant database has committed (0: none).
std::int64_t journalSentSeq(Database& journal);
/// Records that the plant database committed every entry up to `seq` (never moves back).
void markJournalSent(Database& journal, std::int64_t seq);
/// Parts of `journal` the plant database has not committed.
std::int64_t journalBacklogParts(Database& journal);

/// Deletes, oldest first, parts (with their corrections and readings) and alarms the plant database has
/// committed, while the journal's pages in use exceed `keepBytes`; the parts a resume needs (each run's
/// last `delay + 1` parts) stay. At most `maxParts` parts per call (short write transactions). Returns the
/// parts deleted.
std::int64_t trimJournal(Database& journal, std::int64_t keepBytes, int maxParts = 2000);

}  // namespace tt::storage
