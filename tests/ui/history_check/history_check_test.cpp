#include "ui/history_check.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>

#include "core/storage/database.h"
#include "core/storage/schemas.h"
#include "scripted_prompt.h"
#include "ui/app_context.h"
#include "ui/app_state.h"

namespace tt::ui {
namespace {

TEST(HistoryCheck, CreatesTheHistoryWithEverySchemaModuleAndDescribesIt) {
    QTemporaryDir dir;
    test::ScriptedPrompt prompt;
    AppState state;
    AppContext context{&prompt, &state, nullptr, dir.filePath(QStringLiteral("history.sqlite"))};
    EXPECT_TRUE(checkHistoryAtStart(context, nullptr, &prompt));
    EXPECT_TRUE(prompt.log.isEmpty());
    EXPECT_EQ(state.databaseDescription(), QStringLiteral("SQLite ") + context.databasePath);
    storage::Database db(storage::DatabaseConfig::sqlite(context.databasePath));
    for (const storage::SchemaModule& module : storage::allSchemas())
        EXPECT_EQ(db.schemaVersion(module.name), module.migrations.back().version) << module.name.toStdString();
}

TEST(HistoryCheck, ADamagedFileIsReportedAndLeftAsItWas) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("history.sqlite"));
    const QByteArray garbage = QByteArray("this is not a history file").repeated(100);
    {
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(garbage);
    }
    test::ScriptedPrompt prompt;
    AppState state;
    AppContext context{&prompt, &state, nullptr, path};
    EXPECT_FALSE(checkHistoryAtStart(context, nullptr, &prompt));
    ASSERT_EQ(prompt.log.size(), 1);
    EXPECT_TRUE(prompt.lastText.contains(QStringLiteral("damaged or not a TrueTurn database")))
        << prompt.lastText.toStdString();
    EXPECT_TRUE(state.databaseDescription().contains(QStringLiteral("damaged"))) << "the status bar says why";
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_EQ(f.readAll(), garbage);
}

TEST(HistoryCheck, WithoutAPromptOnlyTheStatusSaysIt) {
    test::ScriptedPrompt prompt;
    AppState state;
    AppContext context{&prompt, &state, nullptr, QStringLiteral("postgresql://nobody@127.0.0.1:1/none")};
    EXPECT_FALSE(checkHistoryAtStart(context, nullptr, nullptr));
    EXPECT_TRUE(prompt.log.isEmpty());
    EXPECT_TRUE(state.databaseDescription().contains(QStringLiteral("cannot connect"))) << "unreachable server named";
}

}  // namespace
}  // namespace tt::ui
