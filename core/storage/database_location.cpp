#include "core/storage/database_location.h"

#include <QDir>
#include <QStandardPaths>
#include <stdexcept>

namespace tt::storage {

QString defaultDatabasePath() {
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    if (folder.isEmpty() || !QDir().mkpath(folder))
        throw std::runtime_error("cannot create the data folder '" + folder.toStdString() + "'");
    return QDir(folder).filePath(QStringLiteral("history.sqlite"));
}

}  // namespace tt::storage
