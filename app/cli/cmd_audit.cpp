// `trueturn audit verify`: argument parsing and output only. The chain is checked by
// storage::verifyAuditChain (core/storage/audit_chain.h); the canonical row encoding is documented there.
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <memory>
#include <stdexcept>

#include "app/cli/command.h"
#include "app/cli/command_database.h"
#include "app/cli/command_parser.h"
#include "core/storage/audit_chain.h"
#include "core/storage/database.h"

namespace tt::cli {

namespace {

QString kindName(storage::AuditChainProblem::Kind kind) {
    switch (kind) {
        case storage::AuditChainProblem::Kind::Edited:
            return QStringLiteral("edited");
        case storage::AuditChainProblem::Kind::Deleted:
            return QStringLiteral("deleted");
        case storage::AuditChainProblem::Kind::Inserted:
            return QStringLiteral("inserted");
        case storage::AuditChainProblem::Kind::Head:
            return QStringLiteral("head");
    }
    return QString();
}

QJsonObject toJson(const storage::AuditChainState& state, const QString& database) {
    QJsonArray problems;
    for (const storage::AuditChainProblem& p : state.problems)
        problems.append(
            QJsonObject{{QStringLiteral("kind"), kindName(p.kind)},
                        {QStringLiteral("row_id"), p.rowId ? QJsonValue(p.rowId) : QJsonValue()},
                        {QStringLiteral("after_row_id"), p.afterRowId ? QJsonValue(p.afterRowId) : QJsonValue()},
                        {QStringLiteral("missing_rows"), p.missingRows},
                        {QStringLiteral("message"), p.message}});
    return {{QStringLiteral("database"), database},
            {QStringLiteral("rows"), state.rows},
            {QStringLiteral("chained_rows"), state.chainedRows},
            {QStringLiteral("head_hash"), state.headHash},
            {QStringLiteral("intact"), state.intact()},
            {QStringLiteral("problems"), problems}};
}

void printText(const storage::AuditChainState& state, const QString& database) {
    printLine(QStringLiteral("Audit trail of %1: %2 row(s), %3 in the chain; head %4")
                  .arg(database)
                  .arg(state.rows)
                  .arg(state.chainedRows)
                  .arg(state.headHash));
    for (const storage::AuditChainProblem& p : state.problems)
        printLine(kindName(p.kind) + QStringLiteral(": ") + p.message);
    printLine(state.intact() ? QStringLiteral("the chain is intact")
                             : QStringLiteral("the chain is broken: %1 problem(s)").arg(state.problems.size()));
}

int run(const QStringList& arguments) {
    CommandParser parser(
        QStringLiteral("audit"),
        QStringLiteral("verify: checks the audit trail's hash chain (each row carries the SHA-256 of its content and "
                       "of the row before it) and names every row that was edited, deleted or inserted outside "
                       "TrueTurn. Exit 0: intact; 1: changed (the rows are listed); 2: bad input."));
    parser.addPositional(QStringLiteral("verify"), QStringLiteral("What to do: verify."));
    parser.addOption(QStringLiteral("db"),
                     QStringLiteral("The database: an SQLite file or postgresql://user@host:port/database."),
                     QStringLiteral("file"));
    parser.parse(arguments);
    const QString action = parser.positionals(1).first();
    if (action != QLatin1String("verify"))
        throw UsageError("'" + action.toStdString() + "' is not an audit action; valid: verify");
    const QString database = parser.required(QStringLiteral("db"));
    if (!isPostgresOption(database) && !QFileInfo::exists(database))
        throw UsageError("--db: '" + database.toStdString() + "' does not exist");
    storage::AuditChainState state;
    try {
        storage::Database db(databaseConfigFromOption(database));
        state = storage::verifyAuditChain(db);
    } catch (const storage::StorageError& e) {
        throw UsageError(std::string("--db: ") + e.what());
    }
    if (parser.json())
        printJson(toJson(state, database));
    else
        printText(state, database);
    if (!state.intact())
        throw std::runtime_error(
            "the audit trail was changed outside TrueTurn: " + std::to_string(state.problems.size()) +
            " problem(s), the first: " + state.problems.front().message.toStdString());
    return kExitOk;
}

}  // namespace

Command makeAuditCommand() {
    return {QStringLiteral("audit"),
            QStringLiteral("verify: the audit trail's hash chain; names edited, deleted and inserted rows"), run};
}

}  // namespace tt::cli
