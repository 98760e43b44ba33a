#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include <trueturn/version.h>

#include "cli_runner.h"

namespace tt::test {
namespace {

TEST(Dispatcher, VersionPrintsTheVersion) {
    const CliResult r = runTrueturn({QStringLiteral("--version")});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out.trimmed(), QStringLiteral("TrueTurn ") + QString::fromLatin1(tt::kVersion));
}

TEST(Dispatcher, HelpListsOptionsAndCommandsWithoutADisplay) {
    const CliResult r = runTrueturn({QStringLiteral("--help")});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_TRUE(r.out.contains(QStringLiteral("--screenshots")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("Commands:")));
    // The manual page (help2man) takes its synopsis from this line.
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("Usage: trueturn [options]"))) << r.out.toStdString();
}

TEST(Dispatcher, UnknownCommandExitsTwoNamingTheValidCommands) {
    const CliResult r = runTrueturn({QStringLiteral("nosuchcommand")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(r.err.startsWith(QStringLiteral("trueturn: unknown command 'nosuchcommand'; valid commands:")))
        << r.err.toStdString();
    EXPECT_EQ(r.err.count(QLatin1Char('\n')), 1) << "one line";
}

TEST(Dispatcher, UnknownOptionExitsTwo) {
    const CliResult r = runTrueturn({QStringLiteral("--frobnicate")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("frobnicate"))) << r.err.toStdString();
}

TEST(Dispatcher, BadGuiOptionValueExitsTwo) {
    const CliResult r = runTrueturn({QStringLiteral("--page"), QStringLiteral("nowhere")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("unknown page 'nowhere'"))) << r.err.toStdString();
}

TEST(Dispatcher, GuiWithoutDisplaySaysSo) {
    const CliResult r = runTrueturn({});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("no display"))) << r.err.toStdString();
}

/// The GUI with its own settings and data folders, on the offscreen platform.
QProcessEnvironment offscreenGui(const QTemporaryDir& home) {
    QProcessEnvironment env;
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), home.filePath(QStringLiteral("config")));
    env.insert(QStringLiteral("XDG_DATA_HOME"), home.filePath(QStringLiteral("data")));
    return env;
}

TEST(Gui, StartsOffscreenOnTheSimulatorAndQuitsCleanly) {
    QTemporaryDir home;
    const CliResult r =
        runTrueturn({QStringLiteral("--quit-after-ms"), QStringLiteral("1500")}, 60000, offscreenGui(home));
    EXPECT_EQ(r.exitCode, 0) << r.err.toStdString();
    EXPECT_TRUE(QFileInfo::exists(home.filePath(QStringLiteral("data/TrueTurn/TrueTurn/history.sqlite"))))
        << "the embedded history is created in the user's data folder";
    // A fresh machine has no user: the first start asks for the administrator (the log says so).
    QFile log(home.filePath(QStringLiteral("data/TrueTurn/TrueTurn/logs/trueturn.log")));
    ASSERT_TRUE(log.open(QIODevice::ReadOnly)) << log.fileName().toStdString();
    EXPECT_TRUE(log.readAll().contains("first start: no user yet, asking for the administrator"));
}

TEST(Gui, KioskModeStartsAndTheTestTimerEndsItWithoutTheEngineersQuestion) {
    QTemporaryDir home;
    const CliResult r =
        runTrueturn({QStringLiteral("--kiosk"), QStringLiteral("--quit-after-ms"), QStringLiteral("1500")}, 60000,
                    offscreenGui(home));
    EXPECT_EQ(r.exitCode, 0) << r.err.toStdString();
    EXPECT_TRUE(runTrueturn({QStringLiteral("--help")}).out.contains(QStringLiteral("--kiosk")));
}

TEST(Gui, SavesAScreenshotOfEveryPage) {
    QTemporaryDir home;
    const QString shots = home.filePath(QStringLiteral("shots"));
    const CliResult r = runTrueturn({QStringLiteral("--screenshots"), shots}, 60000, offscreenGui(home));
    EXPECT_EQ(r.exitCode, 0) << r.err.toStdString();
    const QStringList pages = QDir(shots).entryList({QStringLiteral("*.png")}, QDir::Files, QDir::Name);
    EXPECT_EQ(pages,
              (QStringList{QStringLiteral("calibration.png"), QStringLiteral("controller.png"),
                           QStringLiteral("devices.png"), QStringLiteral("measurements.png"),
                           QStringLiteral("plant.png"), QStringLiteral("process.png"), QStringLiteral("reports.png"),
                           QStringLiteral("run.png"), QStringLiteral("settings.png"), QStringLiteral("tools.png")}));
}

}  // namespace
}  // namespace tt::test
