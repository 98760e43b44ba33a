// The Run page with the plant database on a real PostgreSQL server, offscreen: the server is stopped at once
// (pg_ctl stop -m immediate) while the loop runs; the loop goes on (parts keep coming), the page and the status
// bar say since when the plant database is offline and how many parts this terminal keeps; started again, the
// terminal's journal drains and the page says so, and the plant database holds every part the journal holds.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSqlQuery>
#include <QTest>
#include <functional>
#include <memory>

#include "core/storage/database.h"
#include "core/storage/history_journal.h"
#include "run_window.h"
#include "runtime/history/terminal_history.h"
#include "runtime/run/run_session.h"
#include "screenshots.h"
#include "tests/support/own_postgres.h"
#include "tests/support/patient_wait.h"

namespace tt::ui {
namespace {

using test::waitFor;

qint64 scalar(storage::Database& db, const QString& sql, const QVariantList& bindings = {}) {
    QSqlQuery q = db.exec(sql, bindings);
    return q.next() ? q.value(0).toLongLong() : -1;
}

/// The parts a plant-link text says this terminal keeps ("...; parts kept on this terminal: 37"); -1 without.
int keptParts(const QString& text) {
    const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("kept on this terminal: (\\d+)")).match(text);
    return m.hasMatch() ? m.captured(1).toInt() : -1;
}

constexpr const char* kMachine = "gui-lathe";

class RunPlantDatabaseTest : public test::RunWindowTest {
protected:
    void SetUp() override {
        server = std::make_unique<tt::test::OwnPostgres>();
        if (!server->ok()) {
            if (TRUETURN_POSTGRES_REQUIRED) FAIL() << "no PostgreSQL server: " << server->problem().toStdString();
            GTEST_SKIP() << "needs the PostgreSQL server binaries: " << server->problem().toStdString();
        }
        storage::Database admin(storage::DatabaseConfig::postgresUrl(server->url("trueturn", "postgres")));
        admin.exec(QStringLiteral("CREATE DATABASE plant"));
        QSettings().setValue(QString::fromLatin1(runtime::kMachineNameSetting), QString::fromLatin1(kMachine));
        context.databasePath = server->url("trueturn", "plant");
    }
    void TearDown() override { QSettings().remove(QString::fromLatin1(runtime::kMachineNameSetting)); }

    std::unique_ptr<tt::test::OwnPostgres> server;
};

TEST_F(RunPlantDatabaseTest, TheRunGoesOnThroughAStoppedPlantDatabaseShowsWhatItKeepsAndDrains) {
    MainWindow window(context);
    RunPage* page = showRunPage(window);
    ASSERT_NE(page, nullptr);
    auto* link = window.findChild<QLabel*>(QStringLiteral("plantLink"));
    auto* statusBar = window.findChild<QLabel*>(QStringLiteral("statusDatabase"));
    ASSERT_TRUE(link && statusBar);
    const auto parts = [&] { return page->session().snapshot().partsFinished; };

    window.findChild<QComboBox*>(QStringLiteral("speedCombo"))->setCurrentIndex(2);  // x360
    window.findChild<QPushButton*>(QStringLiteral("startButton"))->click();
    ASSERT_TRUE(waitFor([&] { return parts() >= 10 && link->text().contains(QStringLiteral("every part sent")); }))
        << link->text().toStdString();
    EXPECT_TRUE(link->isVisible());

    ASSERT_TRUE(server->crash()) << server->problem().toStdString();
    const qint64 atStop = parts();
    // The loop neither stops nor waits: parts go on, kept on this terminal, and the operator sees so.
    ASSERT_TRUE(waitFor([&] {
        return link->text().contains(QStringLiteral("offline since")) && keptParts(link->text()) >= 5 &&
               parts() >= atStop + 10;
    })) << link->text().toStdString();
    EXPECT_EQ(page->session().snapshot().state, core::LoopState::Running);
    EXPECT_TRUE(statusBar->text().contains(QStringLiteral("Plant database offline since")))
        << statusBar->text().toStdString();
    EXPECT_EQ(state.plantLinkWarns(), true);
    EXPECT_TRUE(test::saveScreenshot(window, QStringLiteral("run_page_plant_offline")));

    ASSERT_TRUE(server->restart()) << server->problem().toStdString();
    window.findChild<QPushButton*>(QStringLiteral("stopButton"))->click();
    ASSERT_TRUE(waitFor([&] { return page->session().snapshot().state == core::LoopState::Idle; }));
    // Back: the journal drains (the forwarder retries within 30 s) and the page says so.
    ASSERT_TRUE(waitFor([&] { return link->text().contains(QStringLiteral("every part sent")); }))
        << link->text().toStdString();
    EXPECT_FALSE(state.plantLinkWarns());
    EXPECT_FALSE(statusBar->text().contains(QStringLiteral("offline"))) << statusBar->text().toStdString();

    // Every part of the journal is in the plant database once.
    storage::Database plant(storage::DatabaseConfig::postgresUrl(context.databasePath));
    storage::DatabaseConfig journalConfig = storage::DatabaseConfig::sqlite(storage::defaultJournalPath(
        QString::fromLatin1(kMachine), storage::DatabaseConfig::postgresUrl(context.databasePath)));
    journalConfig.readOnly = true;
    storage::Database journal(journalConfig);
    const qint64 journalParts = scalar(journal, QStringLiteral("SELECT COUNT(*) FROM parts"));
    EXPECT_GE(journalParts, atStop + 10);
    EXPECT_EQ(
        scalar(plant, QStringLiteral("SELECT COUNT(*) FROM parts p JOIN runs r ON r.id = p.run_id WHERE r.machine = ?"),
               {QString::fromLatin1(kMachine)}),
        journalParts);
    EXPECT_EQ(scalar(plant, QStringLiteral("SELECT COUNT(*) FROM measurements")),
              scalar(journal, QStringLiteral("SELECT COUNT(*) FROM measurements")));
}

}  // namespace
}  // namespace tt::ui
