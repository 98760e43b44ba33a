#include "app/cli/command.h"

#include <trueturn/version.h>
#include <QApplication>
#include <QCoreApplication>
#include <QFile>
#include <QTemporaryDir>
#include <cstdio>
#include <exception>
#include <memory>

#include "app/cli/command_parser.h"

namespace tt::cli {

QString commandNames() {
    QStringList names;
    for (const Command& c : commands())
        names << c.name;
    return names.join(QStringLiteral(", "));
}

namespace {

const Command* findCommand(const QString& name) {
    for (const Command& c : commands())
        if (c.name == name) return &c;
    return nullptr;
}

int fail(const QString& prefix, const char* what, int code) {
    std::fprintf(stderr, "%s: %s\n", qPrintable(prefix), what);
    return code;
}

/// A QCoreApplication, or a QApplication on the offscreen platform (never a display) when the command paints.
std::unique_ptr<QCoreApplication> makeApplication(int& argc, char** argv) {
    QStringList raw;
    for (int i = 2; i < argc; ++i)
        raw << QString::fromLocal8Bit(argv[i]);
    const Command* command = argc > 1 ? findCommand(QString::fromLocal8Bit(argv[1])) : nullptr;
    if (!command || !command->paints || !command->paints(raw)) return std::make_unique<QCoreApplication>(argc, argv);
    qputenv("QT_QPA_PLATFORM", "offscreen");
    if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
        // A headless shell has no session runtime folder; a private one (0700) instead of Qt's warning on stderr.
        static QTemporaryDir runtime;
        if (runtime.isValid()) qputenv("XDG_RUNTIME_DIR", QFile::encodeName(runtime.path()));
    }
    return std::make_unique<QApplication>(argc, argv);
}

}  // namespace

int runCommand(int argc, char** argv) {
    const std::unique_ptr<QCoreApplication> app = makeApplication(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("TrueTurn"));
    QCoreApplication::setApplicationName(QStringLiteral("TrueTurn"));
    QCoreApplication::setApplicationVersion(QString::fromLatin1(tt::kVersion));
    QStringList args = QCoreApplication::arguments().mid(1);
    const QString name = args.takeFirst();
    const Command* command = findCommand(name);
    if (!command) {
        const QString why = QStringLiteral("unknown command '%1'; valid commands: %2").arg(name, commandNames());
        return fail(QStringLiteral("trueturn"), qPrintable(why), kExitUsage);
    }
    const QString prefix = QStringLiteral("trueturn ") + name;
    try {
        return command->run(args);
    } catch (const HelpShown&) {
        return kExitOk;
    } catch (const UsageError& e) {
        return fail(prefix, e.what(), kExitUsage);
    } catch (const std::invalid_argument& e) {
        return fail(prefix, e.what(), kExitUsage);
    } catch (const std::exception& e) {
        return fail(prefix, e.what(), kExitFailure);
    }
}

}  // namespace tt::cli
