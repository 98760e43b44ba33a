#include "app/cli/run_history.h"

#include <QDateTime>
#include <QFileInfo>
#include <QSysInfo>
#include <cstdio>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_parser.h"
#include "core/storage/history_store.h"

namespace tt::cli {

namespace {

/// How often `--progress` repeats the offline state (the backlog grows meanwhile), ms.
constexpr qint64 kOfflineRepeatMs = 5000;

}  // namespace

void addRunHistoryOptions(CommandParser& parser) {
    parser.addOption(QStringLiteral("journal"),
                     QStringLiteral("With a postgresql:// --db: the terminal's journal, an SQLite file every part "
                                    "is stored in first (default: journal/<machine>@<server>.sqlite in the "
                                    "application's data folder)."),
                     QStringLiteral("file"));
    parser.addOption(QStringLiteral("journal-limit-mb"),
                     QStringLiteral("The journal's size limit, 1..1048576 MiB (default: the setting "
                                    "history/journal_limit_mb, else 1024); at it the loop pauses before the next "
                                    "part until the plant database has taken parts."),
                     QStringLiteral("mb"));
    parser.addOption(QStringLiteral("forward-batch"),
                     QStringLiteral("Parts per batch sent to the plant database, 1..10000 (default %1).")
                         .arg(storage::kDefaultForwardBatchParts),
                     QStringLiteral("n"));
    parser.addOption(QStringLiteral("drain-wait"),
                     QStringLiteral("At the end, wait at most this long for the plant database to take the parts "
                                    "still in the journal, 0..86400 s (default 600); what is left is sent by the "
                                    "next run or `trueturn forward`."),
                     QStringLiteral("s"));
}

storage::JournalOptions journalOptionsOf(const CommandParser& parser, const storage::DatabaseConfig& plant) {
    storage::JournalOptions options;
    options.machine = parser.isSet(QStringLiteral("machine")) ? parser.value(QStringLiteral("machine"))
                                                               : QSysInfo::machineHostName();
    if (options.machine.trimmed().isEmpty())
        throw UsageError("--machine: the lathe's name is empty (a plant database tells its machines by name)");
    options.plant = plant.describe();
    options.limitBytes = parser.isSet(QStringLiteral("journal-limit-mb"))
                             ? parser.integer(QStringLiteral("journal-limit-mb"), 1, 1LL << 20) * 1024 * 1024
                             : storage::journalLimitFromSettings();
    try {
        options.path = parser.isSet(QStringLiteral("journal")) ? parser.value(QStringLiteral("journal"))
                                                               : storage::defaultJournalPath(options.machine, plant);
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--journal: ") + e.what());
    }
    return options;
}

RunHistory::RunHistory(const CommandParser& parser, const QString& database, bool progress) : m_progress(progress) {
    const storage::DatabaseConfig config = databaseConfigFromOption(database);
    if (parser.isSet(QStringLiteral("drain-wait")))
        m_drainWaitS = static_cast<double>(parser.integer(QStringLiteral("drain-wait"), 0, 86400));
    if (config.kind == storage::DatabaseConfig::Kind::Sqlite) {
        for (const char* option : {"journal", "journal-limit-mb", "forward-batch", "drain-wait"})
            if (parser.isSet(QString::fromLatin1(option)))
                throw UsageError(std::string("--") + option +
                                 ": only with a plant database (--db postgresql://...); an SQLite file is the history");
        try {
            m_database = std::make_unique<storage::Database>(config);
            m_store = std::make_unique<storage::SqlHistoryStore>(*m_database);
        } catch (const storage::StorageError& e) {
            throw UsageError(std::string("--db: ") + e.what());
        }
        return;
    }
    storage::ForwarderOptions forward;
    forward.plant = config;
    const storage::JournalOptions journal = journalOptionsOf(parser, config);
    if (parser.isSet(QStringLiteral("forward-batch")))
        forward.settings.batchParts = static_cast<int>(parser.integer(QStringLiteral("forward-batch"), 1, 10000));
    try {
        auto store = std::make_unique<storage::HistoryJournal>(journal);
        m_journal = store.get();
        m_store = std::move(store);
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--journal: ") + e.what());
    }
    forward.journalPath = journal.path;
    forward.machine = journal.machine;
    forward.journalLimitBytes = journal.limitBytes;
    m_forwarder = std::make_unique<storage::PlantForwarderThread>(forward);
    m_forwarder->setStatusCallback([this](const storage::ForwarderStatus& s) { printStatus(s); });
    m_journal->setWrittenCallback([forwarder = m_forwarder.get()] { forwarder->wake(); });
    m_forwarder->start();
}

RunHistory::~RunHistory() {
    if (m_journal) m_journal->setWrittenCallback({});
    m_forwarder.reset();
}

core::HistoryStore& RunHistory::store() {
    return *m_store;
}

void RunHistory::printStatus(const storage::ForwarderStatus& s) {
    if (!m_progress) return;
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    using Link = storage::ForwarderStatus::Link;
    const bool changed = s.link != m_printedLink;
    const bool repeat = s.link == Link::Offline && now - m_lastPrintMs >= kOfflineRepeatMs;
    const bool drained = s.link == Link::Online && s.drained && !m_printedDrained;
    if (!changed && !repeat && !drained && !(s.nearFull() && repeat)) return;
    if (s.link == Link::Starting) return;
    m_printedLink = s.link;
    m_lastPrintMs = now;
    m_printedDrained = s.drained;
    std::fprintf(stderr, "%s\n", qPrintable(s.describe()));
    std::fflush(stderr);
}

void RunHistory::finish() {
    if (!m_forwarder) return;
    const bool drained = m_forwarder->drainAndStop(m_drainWaitS);
    const storage::ForwarderStatus s = m_forwarder->status();
    if (drained) {
        if (m_progress) std::fprintf(stderr, "%s\n", qPrintable(s.describe()));
        return;
    }
    std::fprintf(stderr,
                 "trueturn: the plant database did not take every part within %.0f s: %lld part(s) are kept in the "
                 "journal %s and are sent by the next run or `trueturn forward` (%s)\n",
                 m_drainWaitS, static_cast<long long>(s.backlogParts), qPrintable(m_journal->options().path),
                 qPrintable(s.reason.isEmpty() ? s.describe() : s.reason));
}

void RunHistory::addJson(QJsonObject& out) const {
    if (!m_forwarder) return;
    const storage::ForwarderStatus s = m_forwarder->status();
    out.insert(QStringLiteral("plant"),
               QJsonObject{{QStringLiteral("journal"), m_journal->options().path},
                           {QStringLiteral("machine"), m_journal->options().machine},
                           {QStringLiteral("drained"), s.drained && s.backlogParts == 0},
                           {QStringLiteral("backlog_parts"), static_cast<qint64>(s.backlogParts)},
                           {QStringLiteral("sent_parts"), static_cast<qint64>(s.sentParts)}});
}

}  // namespace tt::cli
