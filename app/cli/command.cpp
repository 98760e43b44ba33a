#include "app/cli/command.h"

#include <trueturn/version.h>
#include <QCoreApplication>
#include <cstdio>
#include <exception>

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

}  // namespace

int runCommand(int argc, char** argv) {
    QCoreApplication app(argc, argv);
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
