#include "core/storage/database_location.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

namespace tt::storage {
namespace {

TEST(DatabaseLocation, DefaultIsHistoryFileInCreatedDataFolder) {
    const QString path = defaultDatabasePath();
    EXPECT_TRUE(path.endsWith(QStringLiteral("/history.sqlite"))) << path.toStdString();
    EXPECT_TRUE(QFileInfo(path).dir().exists());
    EXPECT_TRUE(path.startsWith(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)));
}

}  // namespace
}  // namespace tt::storage
