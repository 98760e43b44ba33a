// The application's log (ui/log_file.h): every Qt message as one line with its category, rotated when
// the file grows past its size, the oldest file dropped.
#include "ui/log_file.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QLoggingCategory>
#include <QTemporaryDir>

#include "runtime/log_categories.h"
#include "ui/log_categories.h"

namespace tt::ui {
namespace {

QString readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

TEST(LogFile, WritesEveryMessageWithItsCategoryAndLevel) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("logs/trueturn.log"));
    {
        LogFile log(path);
        log.install();
        QLoggingCategory::setFilterRules(QStringLiteral("trueturn.*.info=true"));
        qCInfo(lcLoop) << "run started";
        qCWarning(lcUi) << "something to look at";
        QLoggingCategory::setFilterRules(QString());
    }
    const QString text = readAll(path);
    EXPECT_TRUE(text.contains(QStringLiteral(" info trueturn.loop: run started"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral(" warning trueturn.ui: something to look at"))) << text.toStdString();
    EXPECT_EQ(text.count(QLatin1Char('\n')), 2);
}

TEST(LogFile, RotatesAtItsSizeAndKeepsTheNewestFiles) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("trueturn.log"));
    LogFile log(path, 200, 2);
    for (int i = 0; i < 40; ++i)
        log.write(QtInfoMsg, "trueturn.loop", QStringLiteral("line %1 of the log").arg(i, 2, 10, QLatin1Char('0')));
    EXPECT_TRUE(QFile::exists(dir.filePath(QStringLiteral("trueturn.1.log"))));
    EXPECT_TRUE(QFile::exists(dir.filePath(QStringLiteral("trueturn.2.log"))));
    EXPECT_FALSE(QFile::exists(dir.filePath(QStringLiteral("trueturn.3.log")))) << "two old files are kept";
    for (const QString& name : QDir(dir.path()).entryList(QDir::Files))
        EXPECT_LE(QFile(dir.filePath(name)).size(), 200) << name.toStdString();
    EXPECT_TRUE(readAll(path).contains(QStringLiteral("line 39 of the log"))) << "the newest line is in the file";
    EXPECT_FALSE(readAll(path).contains(QStringLiteral("line 00 of"))) << "the oldest went with the rotation";
}

TEST(LogFile, RefusesASizeOfZero) {
    QTemporaryDir dir;
    EXPECT_THROW(LogFile(dir.filePath(QStringLiteral("a.log")), 0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace tt::ui
