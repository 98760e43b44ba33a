#include "app/gui_options.h"

#include <trueturn/version.h>
#include <QCommandLineParser>
#include <QStringList>
#include <cstdio>

#include "app/cli/command.h"
#include "ui/page.h"

namespace tt::app {

namespace {

QStringList pageKeys() {
    QStringList keys;
    for (ui::PageId id : ui::kAllPages)
        keys << ui::pageKey(id);
    return keys;
}

void addOptions(QCommandLineParser& parser) {
    parser.setApplicationDescription(
        QStringLiteral(
            "TrueTurn: adaptive accuracy control for lathes.\n"
            "Without a command it opens the operator terminal. Headless commands:\n  trueturn <command> --help\n"
            "Commands: ") +
        cli::commandNames());
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption({QStringLiteral("page"), QStringLiteral("Page to open: %1.").arg(pageKeys().join(u", ")),
                      QStringLiteral("name")});
    parser.addOption({QStringLiteral("lang"), QStringLiteral("Interface language: en or ru."), QStringLiteral("code")});
    parser.addOption({QStringLiteral("db"),
                      QStringLiteral("Run history: an SQLite file, or a postgresql:// plant database written through "
                                     "this terminal's journal."),
                      QStringLiteral("file")});
    parser.addOption({QStringLiteral("machine"),
                      QStringLiteral("This lathe's name in a plant database (kept for later starts; default: the "
                                     "computer's name)."),
                      QStringLiteral("name")});
    parser.addOption({QStringLiteral("screenshots"), QStringLiteral("Save every page as PNG into the folder and quit."),
                      QStringLiteral("dir")});
    parser.addOption({QStringLiteral("kiosk"),
                      QStringLiteral("Kiosk mode: full screen, no window decorations; only an engineer may quit.")});
    parser.addOption(
        {QStringLiteral("quit-after-ms"), QStringLiteral("Quit after the given time (tests)."), QStringLiteral("ms")});
}

GuiParse usage(const QString& why) {
    std::fprintf(stderr, "trueturn: %s\n", qPrintable(why));
    return {std::nullopt, cli::kExitUsage};
}

GuiParse readValues(const QCommandLineParser& parser) {
    GuiOptions o;
    o.page = parser.value(QStringLiteral("page"));
    if (!o.page.isEmpty() && !pageKeys().contains(o.page))
        return usage(QStringLiteral("--page: unknown page '%1'; pages: %2").arg(o.page, pageKeys().join(u", ")));
    o.language = parser.value(QStringLiteral("lang"));
    if (!o.language.isEmpty() && o.language != u"en" && o.language != u"ru")
        return usage(QStringLiteral("--lang: '%1' is not en or ru").arg(o.language));
    o.databasePath = parser.value(QStringLiteral("db"));
    o.machine = parser.value(QStringLiteral("machine")).trimmed();
    if (parser.isSet(QStringLiteral("machine")) && o.machine.isEmpty())
        return usage(QStringLiteral("--machine: the lathe's name is empty"));
    o.screenshotDir = parser.value(QStringLiteral("screenshots"));
    o.kiosk = parser.isSet(QStringLiteral("kiosk"));
    if (parser.isSet(QStringLiteral("quit-after-ms"))) {
        bool ok = false;
        o.quitAfterMs = parser.value(QStringLiteral("quit-after-ms")).toInt(&ok);
        if (!ok || o.quitAfterMs < 0) return usage(QStringLiteral("--quit-after-ms: expected milliseconds >= 0"));
    }
    return {o, 0};
}

}  // namespace

GuiParse parseGuiOptions(int argc, char** argv) {
    QStringList args;
    for (int i = 0; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    QCommandLineParser parser;
    addOptions(parser);
    if (!parser.parse(args)) return usage(parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) {
        // No QCoreApplication yet (help works without a display), so Qt cannot name the executable.
        QString help = parser.helpText();
        help.replace(QStringLiteral("<executable_name>"), QStringLiteral("trueturn"));
        std::fputs(qPrintable(help), stdout);
        return {std::nullopt, cli::kExitOk};
    }
    if (parser.isSet(QStringLiteral("version"))) {
        std::printf("TrueTurn %s\n", tt::kVersion);
        return {std::nullopt, cli::kExitOk};
    }
    if (!parser.positionalArguments().isEmpty())
        return usage(QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().first()));
    return readValues(parser);
}

}  // namespace tt::app
