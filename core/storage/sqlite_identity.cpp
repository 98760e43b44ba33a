#include "core/storage/sqlite_identity.h"

#include <QFileInfo>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QStringList>
#include <QUuid>

#include "core/storage/database.h"

namespace tt::storage {

namespace {

/// A StorageError with the message `text` (QString::arg placeholders filled in by the caller).
StorageError storageError(const QString& text) {
    return StorageError(text.toStdString());
}

void requireWritableFolder(const QString& path) {
    const QFileInfo folder(QFileInfo(path).absolutePath());
    if (!folder.exists())
        throw storageError(QStringLiteral("the folder '%1' of the history file does not exist").arg(folder.filePath()));
    if (!folder.isWritable())
        throw storageError(
            QStringLiteral("the folder '%1' of the history file '%2' is read-only (SQLite writes its journal beside "
                           "the file)")
                .arg(folder.filePath(), path));
}

/// The user tables of the SQLite file at `path`, read over a read-only connection; throws on a file
/// that SQLite cannot read.
QStringList tablesReadOnly(const QString& path) {
    const QString name = QStringLiteral("trueturn-identify-") + QUuid::createUuid().toString();
    QStringList tables;
    QString error;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name);
        db.setDatabaseName(path);
        db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY"));
        if (!db.open()) {
            error = db.lastError().text();
        } else {
            QSqlQuery q(db);
            if (q.exec(QStringLiteral("SELECT name FROM sqlite_master WHERE type = 'table' AND name NOT LIKE "
                                      "'sqlite_%' ORDER BY name"))) {
                while (q.next())
                    tables << q.value(0).toString();
            } else {
                error = q.lastError().text();
            }
        }
        db.close();
    }
    QSqlDatabase::removeDatabase(name);
    if (!error.isEmpty())
        throw storageError(
            QStringLiteral("the history file '%1' is damaged or not a TrueTurn database (%2); it was left untouched")
                .arg(path, error));
    return tables;
}

}  // namespace

void requireTrueTurnSqliteFile(const QString& path) {
    requireWritableFolder(path);
    const QFileInfo file(path);
    if (!file.exists() || file.size() == 0) return;
    if (!file.isWritable()) throw storageError(QStringLiteral("the history file '%1' is read-only").arg(path));
    const QStringList tables = tablesReadOnly(path);
    if (tables.isEmpty() || tables.contains(QStringLiteral("schema_versions"))) return;
    QString shown = tables.mid(0, 5).join(QStringLiteral(", "));
    if (tables.size() > 5) shown += QStringLiteral(", ...");
    throw storageError(
        QStringLiteral("the file '%1' is not a TrueTurn database (it holds the tables %2); it was left untouched")
            .arg(path, shown));
}

}  // namespace tt::storage
