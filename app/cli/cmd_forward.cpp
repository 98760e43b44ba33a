// `trueturn forward`: sends what a terminal's journal still holds to the plant database (storage's
// PlantForwarderThread, the same forwarder a run starts) and stops when it is all sent or the wait is over.
#include <QFile>
#include <QJsonObject>
#include <cstdio>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_parser.h"
#include "app/cli/run_history.h"
#include "core/storage/plant_forwarder_thread.h"

namespace tt::cli {

namespace {

int run(const QStringList& arguments) {
    CommandParser parser(
        QStringLiteral("forward"),
        QStringLiteral("Sends the parts a terminal's journal still holds to the plant database, in order and in "
                       "batches, each at most once (what the server has is not inserted again), retrying while the "
                       "server cannot be reached; ends when everything is sent or after --drain-wait."));
    parser.addOption(QStringLiteral("db"), QStringLiteral("The plant database, postgresql://user@host:port/database."),
                     QStringLiteral("url"));
    parser.addOption(QStringLiteral("machine"),
                     QStringLiteral("The lathe whose journal is sent (default: this computer's host name)."),
                     QStringLiteral("name"));
    addRunHistoryOptions(parser);
    parser.addOption(QStringLiteral("progress"), QStringLiteral("Report the plant database's state on stderr."));
    parser.parse(arguments);

    const QString url = parser.required(QStringLiteral("db"));
    if (!isPostgresOption(url)) throw UsageError("--db: a plant database is a postgresql:// address");
    const storage::DatabaseConfig plant = databaseConfigFromOption(url);
    const storage::JournalOptions journal = journalOptionsOf(parser, plant);
    if (!QFile::exists(journal.path))
        throw UsageError("--journal: '" + journal.path.toStdString() + "' does not exist: nothing was kept for " +
                         journal.machine.toStdString());
    try {
        storage::HistoryJournal check(journal);  // refuses a journal of another machine or plant
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--journal: ") + e.what());
    }
    storage::ForwarderOptions options{journal.path, plant, journal.machine, journal.limitBytes, {}};
    if (parser.isSet(QStringLiteral("forward-batch")))
        options.settings.batchParts = static_cast<int>(parser.integer(QStringLiteral("forward-batch"), 1, 10000));
    const double waitS = parser.isSet(QStringLiteral("drain-wait"))
                             ? static_cast<double>(parser.integer(QStringLiteral("drain-wait"), 0, 86400))
                             : 600.0;
    storage::PlantForwarderThread forwarder(options);
    const bool progress = parser.isSet(QStringLiteral("progress"));
    forwarder.setStatusCallback([progress, last = storage::ForwarderStatus::Link::Starting](
                                    const storage::ForwarderStatus& s) mutable {
        if (!progress || s.link == last) return;
        last = s.link;
        std::fprintf(stderr, "%s\n", qPrintable(s.describe()));
    });
    forwarder.start();
    const bool drained = forwarder.drainAndStop(waitS);
    const storage::ForwarderStatus s = forwarder.status();
    if (parser.json())
        printJson(QJsonObject{{QStringLiteral("journal"), journal.path},
                              {QStringLiteral("machine"), journal.machine},
                              {QStringLiteral("drained"), drained},
                              {QStringLiteral("sent_parts"), static_cast<qint64>(s.sentParts)},
                              {QStringLiteral("backlog_parts"), static_cast<qint64>(s.backlogParts)}});
    else
        printLine(s.describe());
    if (drained) return kExitOk;
    std::fprintf(stderr, "trueturn forward: %lld part(s) not sent within %.0f s: %s\n",
                 static_cast<long long>(s.backlogParts), waitS, qPrintable(s.reason));
    return kExitFailure;
}

}  // namespace

Command makeForwardCommand() {
    return {QStringLiteral("forward"),
            QStringLiteral("Send what a terminal's journal still holds to the plant database"), run};
}

}  // namespace tt::cli
