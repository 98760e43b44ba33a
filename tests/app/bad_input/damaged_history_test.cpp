// A damaged SQLite history given as --db is refused and nothing is created beside it: a history cut short
// (as a full disk or a copy broken off leaves it) at several lengths, a file whose first page is damaged, and
// someone else's database. Before, the read-only check of a file in WAL mode left '-wal' and '-shm' beside it.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include "cli_test.h"

namespace {

using tt::test::CliResult;
using tt::test::expectRefused;
using tt::test::runTrueturn;

class DamagedHistory : public tt::test::CliTest {
protected:
    /// A real history of `parts` parts written by `trueturn simulate`, closed cleanly (no side files).
    QString history(const QString& name, int parts) {
        const QString file = path(name);
        const CliResult r =
            runTrueturn({"simulate", "--parts", QString::number(parts), "--warmup", "0", "--db", file, "--json"});
        EXPECT_EQ(r.exitCode, 0) << qPrintable(r.err);
        return file;
    }
    /// The files of the test's folder.
    QStringList files() const { return QDir(m_dir.path()).entryList(QDir::Files, QDir::Name); }
    static QByteArray bytes(const QString& file) {
        QFile f(file);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }
};

TEST_F(DamagedHistory, AHistoryCutShortIsRefusedAndNothingIsCreatedBesideIt) {
    const QString whole = history(QStringLiteral("whole.sqlite"), 600);
    const QByteArray content = bytes(whole);
    ASSERT_GT(content.size(), 50000);
    ASSERT_EQ(files(), QStringList{QStringLiteral("whole.sqlite")}) << "a clean close leaves no side file";
    for (const double share : {0.5, 0.1, 0.02}) {
        const QString name = QStringLiteral("cut-%1.sqlite").arg(share);
        const QByteArray cut = content.left(static_cast<qsizetype>(content.size() * share));
        const QString file = write(name, cut);
        const CliResult r = runTrueturn({"simulate", "--parts", "100", "--db", file, "--json"});
        EXPECT_EQ(r.exitCode, 2) << share << ": " << qPrintable(r.err);
        EXPECT_TRUE(r.err.contains(QStringLiteral("is damaged or not a TrueTurn database"))) << qPrintable(r.err);
        EXPECT_TRUE(r.out.isEmpty());
        for (const char* suffix : {"-wal", "-shm", "-journal"})
            EXPECT_FALSE(QFileInfo::exists(file + QLatin1String(suffix))) << share << ": " << suffix << " left";
        EXPECT_EQ(bytes(file), cut) << share << ": the refused file was changed";
        QFile::remove(file);
    }
    // The other commands that read a history refuse it the same way.
    const QString cut = write(QStringLiteral("cut.sqlite"), content.left(content.size() / 2));
    for (const QStringList& args :
         {QStringList{"report", "--db", cut, "--json"}, QStringList{"identify", "--db", cut, "--json"},
          QStringList{"audit", "verify", "--db", cut}}) {
        const CliResult r = runTrueturn(args);
        EXPECT_EQ(r.exitCode, 2) << qPrintable(args.join(' ')) << ": " << qPrintable(r.err);
        EXPECT_TRUE(r.err.contains(QStringLiteral("damaged"))) << qPrintable(r.err);
    }
    EXPECT_EQ(files(), (QStringList{QStringLiteral("cut.sqlite"), QStringLiteral("whole.sqlite")}));
}

TEST_F(DamagedHistory, AFileWithADamagedHeaderIsRefusedUntouched) {
    QByteArray content = bytes(history(QStringLiteral("h.sqlite"), 200));
    content.replace(0, 16, QByteArray(16, 'X'));  // the "SQLite format 3" magic
    const QString file = write(QStringLiteral("header.sqlite"), content);
    expectRefused({"simulate", "--parts", "100", "--db", file},
                  QStringLiteral("is damaged or not a TrueTurn database"));
    EXPECT_EQ(bytes(file), content);
    EXPECT_EQ(files(), (QStringList{QStringLiteral("h.sqlite"), QStringLiteral("header.sqlite")}));
}

}  // namespace
