#include <gtest/gtest.h>

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

}  // namespace
}  // namespace tt::test
