#pragma once

#include <QJsonObject>
#include <QString>
#include <memory>

#include "core/ports/history_store.h"
#include "core/storage/database.h"
#include "core/storage/history_journal.h"
#include "core/storage/plant_forwarder_thread.h"
#include "runtime/history/terminal_history.h"

namespace tt::cli {

class CommandParser;

/// The history a command's run writes, from its --db option: an SQLite file is the history itself (as for a
/// single lathe); a postgresql:// plant database is written through the terminal's journal (an SQLite file next
/// to the application's data, or --journal) and a forwarder thread that sends it to the plant database, so the
/// run neither stops nor waits when the plant database is down (the forwarder retries: 0.5 s doubling to 30 s).
class RunHistory {
public:
    /// --machine is the lathe (default: this computer's host name); --journal, --journal-limit-mb,
    /// --forward-batch and --drain-wait are added by addRunHistoryOptions. With `progress`, the plant
    /// database's state is reported on stderr when it changes (and every 5 s while it is offline). Throws
    /// UsageError ("--db: ...", "--journal: ...") with the reason.
    RunHistory(const CommandParser& parser, const QString& database, bool progress);
    ~RunHistory();
    RunHistory(const RunHistory&) = delete;
    RunHistory& operator=(const RunHistory&) = delete;

    /// The store the loop writes.
    core::HistoryStore& store();
    /// Whether the runs go to a plant database through the journal.
    bool forwarding() const { return m_history->forwarder() != nullptr; }
    /// At the end of the command: waits until the forwarder has sent everything, at most --drain-wait
    /// seconds, and says on stderr what was not sent (it stays in the journal and goes with the next run
    /// or `trueturn forward`).
    void finish();
    /// Adds "plant": {journal, drained, backlog_parts, sent_parts} to a command's JSON when forwarding.
    void addJson(QJsonObject& out) const;

private:
    void printStatus(const storage::ForwarderStatus& status);

    std::unique_ptr<runtime::TerminalHistory> m_history;
    double m_drainWaitS = 600.0;
    bool m_progress = false;
    qint64 m_lastPrintMs = -1;
    storage::ForwarderStatus::Link m_printedLink = storage::ForwarderStatus::Link::Starting;
    bool m_printedDrained = false;
};

/// Adds the options of a plant-database run: --journal FILE, --journal-limit-mb N, --forward-batch N,
/// --drain-wait S.
void addRunHistoryOptions(CommandParser& parser);

/// The terminal's history options of --db (`database`), --machine, --journal, --journal-limit-mb and
/// --forward-batch; throws UsageError.
runtime::TerminalHistoryOptions terminalOptionsOf(const CommandParser& parser, const QString& database);

/// The journal options of --db (a postgresql:// URL), --machine and --journal / --journal-limit-mb; throws
/// UsageError.
storage::JournalOptions journalOptionsOf(const CommandParser& parser, const storage::DatabaseConfig& plant);

}  // namespace tt::cli
