#include "core/storage/history_journal.h"

#include <QDir>
#include <QRegularExpression>
#include <QSettings>
#include <QSqlQuery>
#include <QStandardPaths>

namespace tt::storage {

namespace {

QVariant id(std::int64_t v) {
    return QVariant(static_cast<qlonglong>(v));
}

/// A file-name-safe form of `text` (letters, digits, '.', '-', '_'; anything else '_').
QString safeName(const QString& text) {
    QString out = text;
    out.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9._-]")), QStringLiteral("_"));
    return out.isEmpty() ? QStringLiteral("_") : out;
}

std::string quoted(const QString& s) {
    return "'" + s.toStdString() + "'";
}

}  // namespace

QString defaultJournalPath(const QString& machine, const DatabaseConfig& plant) {
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    const QString journals = QDir(folder).filePath(QStringLiteral("journal"));
    if (folder.isEmpty() || !QDir().mkpath(journals))
        throw StorageError("cannot create the journal folder '" + journals.toStdString() + "'");
    const QString name =
        QStringLiteral("%1@%2-%3-%4.sqlite")
            .arg(safeName(machine), safeName(plant.host), QString::number(plant.port), safeName(plant.databaseName));
    return QDir(journals).filePath(name);
}

std::int64_t journalLimitFromSettings() {
    const QVariant mb = QSettings().value(QString::fromLatin1(kJournalLimitSetting));
    bool ok = false;
    const qlonglong value = mb.toLongLong(&ok);
    return ok && value > 0 ? value * 1024 * 1024 : kDefaultJournalLimitBytes;
}

SchemaModule journalSchema() {
    SchemaModule module{QStringLiteral("journal"), {}};
    module.migrations.push_back(
        {1, QStringLiteral("the outbox of a terminal's journal and what the plant database committed"),
         [](Database& db) {
             // kind: run (item 0), part (item: part number), measurement (item: part number), alarm (item: the
             // alarm's row id), end (item: the end's number within the run; status and at: the end).
             db.exec(
                 QStringLiteral("CREATE TABLE journal_outbox (seq INTEGER PRIMARY KEY AUTOINCREMENT,"
                                " kind TEXT NOT NULL, run_id INTEGER NOT NULL, item INTEGER NOT NULL,"
                                " status TEXT, at TEXT)"));
             db.exec(QStringLiteral("CREATE INDEX journal_outbox_items ON journal_outbox (run_id, kind, item)"));
             db.exec(QStringLiteral("CREATE TABLE journal_state (key TEXT PRIMARY KEY, value TEXT NOT NULL)"));
         }});
    return module;
}

std::int64_t journalUsedBytes(Database& journal) {
    const auto pragma = [&journal](const char* name) {
        QSqlQuery q = journal.exec(QStringLiteral("PRAGMA %1").arg(QLatin1String(name)));
        return q.next() ? q.value(0).toLongLong() : 0;
    };
    return (pragma("page_count") - pragma("freelist_count")) * pragma("page_size");
}

HistoryJournal::HistoryJournal(const JournalOptions& options) : m_options(options) {
    if (options.machine.isEmpty()) throw StorageError("a terminal's journal needs the machine's name");
    if (options.limitBytes < (1LL << 20))
        throw StorageError("the journal's size limit " + std::to_string(options.limitBytes) +
                           " bytes is below the smallest, 1 MiB");
    DatabaseConfig config = DatabaseConfig::sqlite(options.path);
    config.durable = true;
    m_db = std::make_unique<Database>(config);
    m_history = std::make_unique<SqlHistoryStore>(*m_db);
    m_db->migrate(journalSchema());
    bindTo(options);
}

HistoryJournal::~HistoryJournal() = default;

void HistoryJournal::bindTo(const JournalOptions& options) {
    m_db->transaction([&] {
        for (const auto& [key, value] : {std::pair{QStringLiteral("machine"), options.machine},
                                         std::pair{QStringLiteral("plant"), options.plant}}) {
            QSqlQuery q = m_db->exec(QStringLiteral("SELECT value FROM journal_state WHERE key = ?"), {key});
            if (!q.next()) {
                q.finish();
                m_db->exec(QStringLiteral("INSERT INTO journal_state (key, value) VALUES (?, ?)"), {key, value});
            } else if (q.value(0).toString() != value) {
                throw StorageError("the journal " + quoted(options.path) + " holds the history of " +
                                   key.toStdString() + " " + quoted(q.value(0).toString()) + ", not " + quoted(value) +
                                   "; it was left untouched (give another journal file)");
            }
        }
    });
}

void HistoryJournal::enqueue(const char* kind, std::int64_t runId, std::int64_t item, const QString& status) {
    m_db->exec(QStringLiteral("INSERT INTO journal_outbox (kind, run_id, item, status, at) VALUES (?, ?, ?, ?, ?)"),
               {QString::fromLatin1(kind), id(runId), id(item),
                status.isEmpty() ? QVariant(QMetaType::fromType<QString>()) : QVariant(status),
                status.isEmpty() ? QVariant(QMetaType::fromType<QString>()) : QVariant(utcNowText())});
}

void HistoryJournal::enqueueOpenMeasurements(std::int64_t runId) {
    // Readings of the run stored and not yet in the outbox (the last z parts, never used by the controller): final.
    m_db->exec(QStringLiteral("INSERT INTO journal_outbox (kind, run_id, item)"
                              " SELECT 'measurement', p.run_id, p.part_number FROM parts p WHERE p.run_id = ?"
                              " AND EXISTS (SELECT 1 FROM measurements m WHERE m.part_id = p.id)"
                              " AND NOT EXISTS (SELECT 1 FROM journal_outbox o WHERE o.run_id = p.run_id"
                              " AND o.kind = 'measurement' AND o.item = p.part_number) ORDER BY p.part_number"),
               {id(runId)});
}

std::int64_t HistoryJournal::beginRun(const core::RunDescription& run) {
    core::RunDescription mine = run;
    if (!mine.machine.empty() && mine.machine != m_options.machine.toStdString())
        throw StorageError("the journal of machine " + quoted(m_options.machine) + " cannot store a run of machine '" +
                           mine.machine + "'");
    mine.machine = m_options.machine.toStdString();
    std::int64_t runId = 0;
    m_db->transaction([&] {
        // Runs left without an end (killed, never resumed): their last readings are final now.
        QSqlQuery open = m_db->exec(QStringLiteral(
            "SELECT r.id FROM runs r WHERE NOT EXISTS (SELECT 1 FROM journal_outbox o WHERE o.run_id = r.id"
            " AND o.kind = 'end')"));
        std::vector<std::int64_t> unfinished;
        while (open.next())
            unfinished.push_back(open.value(0).toLongLong());
        open.finish();
        for (const std::int64_t r : unfinished)
            enqueueOpenMeasurements(r);
        runId = m_history->beginRun(mine);
        enqueue("run", runId, 0);
    });
    if (m_written) m_written();
    return runId;
}

void HistoryJournal::recordPart(std::int64_t runId, const core::PartCompletionRecord& part) {
    m_db->transaction([&] {
        m_history->recordPart(runId, part);
        enqueue("part", runId, part.partNumber);
        if (part.usedMeasurement) enqueue("measurement", runId, part.usedMeasurement->partNumber);
    });
    if (m_written) m_written();
}

void HistoryJournal::recordMeasurement(std::int64_t runId, const core::PartMeasurementRecord& measurement) {
    // Not final yet: the controller's verdicts come with the part that uses it (recordPart).
    m_history->recordMeasurement(runId, measurement);
}

void HistoryJournal::recordAlarm(std::int64_t runId, const core::AlarmRecord& alarm) {
    m_db->transaction([&] { enqueue("alarm", runId, m_history->insertAlarm(runId, alarm)); });
    if (m_written) m_written();
}

void HistoryJournal::finishRun(std::int64_t runId, const std::string& status) {
    m_db->transaction([&] {
        m_history->finishRun(runId, status);
        enqueueOpenMeasurements(runId);
        QSqlQuery q = m_db->exec(
            QStringLiteral("SELECT COUNT(*) FROM journal_outbox WHERE run_id = ? AND kind = 'end'"), {id(runId)});
        const std::int64_t ends = q.next() ? q.value(0).toLongLong() : 0;
        q.finish();
        enqueue("end", runId, ends + 1, QString::fromStdString(status));
    });
    if (m_written) m_written();
}

void HistoryJournal::recordAdaptation(std::int64_t runId, const core::AdaptationRecord& adaptation) {
    m_history->recordAdaptation(runId, adaptation);
}

std::vector<core::RunSummary> HistoryJournal::runs() {
    return m_history->runs();
}

std::vector<core::StoredPart> HistoryJournal::parts(std::int64_t runId) {
    return m_history->parts(runId);
}

std::vector<core::AlarmRecord> HistoryJournal::alarms(std::int64_t runId) {
    return m_history->alarms(runId);
}

std::vector<core::AdaptationRecord> HistoryJournal::adaptations(std::int64_t runId) {
    return m_history->adaptations(runId);
}

std::optional<core::ResumePoint> HistoryJournal::resumePoint(std::optional<std::int64_t> runId) {
    return m_history->resumePoint(runId);
}

JournalUsage HistoryJournal::usage() {
    return {journalUsedBytes(*m_db), m_options.limitBytes};
}

core::Notice HistoryJournal::refusesNextPart() {
    const JournalUsage u = usage();
    if (!u.full()) return {};
    core::Notice full(core::NoticeKind::HistoryFull);
    full.value = static_cast<double>(u.usedBytes);
    full.limit = static_cast<double>(u.limitBytes);
    full.cause = "this terminal's journal holds " + std::to_string(u.usedBytes / (1024 * 1024)) + " MiB, its limit " +
                 std::to_string(u.limitBytes / (1024 * 1024)) +
                 " MiB, and the plant database has not taken its parts yet";
    return full;
}

std::int64_t HistoryJournal::backlogParts() {
    QSqlQuery q = m_db->exec(
        QStringLiteral("SELECT COUNT(*) FROM journal_outbox WHERE kind = 'part' AND seq > COALESCE((SELECT CAST(value"
                       " AS INTEGER) FROM journal_state WHERE key = 'sent_seq'), 0)"));
    return q.next() ? q.value(0).toLongLong() : 0;
}

}  // namespace tt::storage
