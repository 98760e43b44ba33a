#include "app/cli/run_history.h"

#include <QDateTime>
#include <QFileInfo>
#include <QSysInfo>
#include <cstdio>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_parser.h"
#include "core/storage/history_store.h"
#include "runtime/history/terminal_history.h"

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
    try {
        return runtime::journalOptionsFor(terminalOptionsOf(parser, plant.describe()), plant);
    } catch (const runtime::TerminalHistoryError& e) {
        throw UsageError(std::string(parser.isSet(QStringLiteral("journal")) ? "--journal: " : "--machine: ") +
                         e.what());
    }
}

runtime::TerminalHistoryOptions terminalOptionsOf(const CommandParser& parser, const QString& database) {
    runtime::TerminalHistoryOptions options;
    options.location = database;
    options.machine =
        parser.isSet(QStringLiteral("machine")) ? parser.value(QStringLiteral("machine")) : QSysInfo::machineHostName();
    options.journalLimitBytes = parser.isSet(QStringLiteral("journal-limit-mb"))
                                    ? parser.integer(QStringLiteral("journal-limit-mb"), 1, 1LL << 20) * 1024 * 1024
                                    : storage::journalLimitFromSettings();
    if (parser.isSet(QStringLiteral("journal"))) options.journalPath = parser.value(QStringLiteral("journal"));
    if (parser.isSet(QStringLiteral("forward-batch")))
        options.batchParts = static_cast<int>(parser.integer(QStringLiteral("forward-batch"), 1, 10000));
    return options;
}

RunHistory::RunHistory(const CommandParser& parser, const QString& database, bool progress) : m_progress(progress) {
    const storage::DatabaseConfig config = databaseConfigFromOption(database);
    if (parser.isSet(QStringLiteral("drain-wait")))
        m_drainWaitS = static_cast<double>(parser.integer(QStringLiteral("drain-wait"), 0, 86400));
    if (config.kind == storage::DatabaseConfig::Kind::Sqlite)
        for (const char* option : {"journal", "journal-limit-mb", "forward-batch", "drain-wait"})
            if (parser.isSet(QString::fromLatin1(option)))
                throw UsageError(std::string("--") + option +
                                 ": only with a plant database (--db postgresql://...); an SQLite file is the history");
    runtime::TerminalHistoryOptions options = terminalOptionsOf(parser, database);
    if (config.kind != storage::DatabaseConfig::Kind::Sqlite && options.machine.trimmed().isEmpty())
        throw UsageError("--machine: the lathe's name is empty (a plant database tells its machines by name)");
    try {
        m_history = std::make_unique<runtime::TerminalHistory>(options);
    } catch (const runtime::TerminalHistoryError& e) {
        throw UsageError(
            std::string(e.part() == runtime::TerminalHistoryError::Part::Database ? "--db: " : "--journal: ") +
            e.what());
    }
    if (storage::PlantForwarderThread* forwarder = m_history->forwarder())
        forwarder->setStatusCallback([this](const storage::ForwarderStatus& s) { printStatus(s); });
    m_history->startForwarding();
}

RunHistory::~RunHistory() = default;

core::HistoryStore& RunHistory::store() {
    return m_history->store();
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
    storage::PlantForwarderThread* forwarder = m_history->forwarder();
    if (!forwarder) return;
    const bool drained = m_history->drain(m_drainWaitS);
    const storage::ForwarderStatus s = forwarder->status();
    if (drained) {
        if (m_progress) std::fprintf(stderr, "%s\n", qPrintable(s.describe()));
        return;
    }
    std::fprintf(stderr,
                 "trueturn: the plant database did not take every part within %.0f s: %lld part(s) are kept in the "
                 "journal %s and are sent by the next run or `trueturn forward` (%s)\n",
                 m_drainWaitS, static_cast<long long>(s.backlogParts), qPrintable(m_history->journal()->options().path),
                 qPrintable(s.reason.isEmpty() ? s.describe() : s.reason));
}

void RunHistory::addJson(QJsonObject& out) const {
    if (!forwarding()) return;
    const storage::ForwarderStatus s = m_history->forwarder()->status();
    const storage::JournalOptions& journal = m_history->journal()->options();
    out.insert(QStringLiteral("plant"),
               QJsonObject{{QStringLiteral("journal"), journal.path},
                           {QStringLiteral("machine"), journal.machine},
                           {QStringLiteral("drained"), s.drained && s.backlogParts == 0},
                           {QStringLiteral("backlog_parts"), static_cast<qint64>(s.backlogParts)},
                           {QStringLiteral("sent_parts"), static_cast<qint64>(s.sentParts)}});
}

}  // namespace tt::cli
