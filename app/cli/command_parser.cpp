#include "app/cli/command_parser.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "app/cli/command.h"

namespace tt::cli {

namespace {

UsageError optionError(const QString& name, const QString& why) {
    return UsageError(QStringLiteral("--%1: %2").arg(name, why).toStdString());
}

}  // namespace

CommandParser::CommandParser(const QString& command, const QString& description) : m_command(command) {
    m_parser.setApplicationDescription(description);
    m_parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    m_parser.addHelpOption();
    m_parser.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("Machine-readable JSON on stdout.")));
}

void CommandParser::addOption(const QString& name, const QString& description, const QString& valueName,
                              const QString& defaultValue) {
    QCommandLineOption option(name, description, valueName, defaultValue);
    m_parser.addOption(option);
}

void CommandParser::addPositional(const QString& name, const QString& description) {
    m_parser.addPositionalArgument(name, description);
    m_positionalNames << name;
}

void CommandParser::parse(const QStringList& arguments) {
    QStringList all = arguments;
    all.prepend(QStringLiteral("trueturn ") + m_command);
    if (!m_parser.parse(all)) throw UsageError(m_parser.errorText().toStdString());
    if (m_parser.isSet(QStringLiteral("help"))) {
        std::fputs(qPrintable(m_parser.helpText()), stdout);
        throw HelpShown{};
    }
    if (m_parser.positionalArguments().size() > m_positionalNames.size())
        throw UsageError(QStringLiteral("unexpected argument '%1'")
                             .arg(m_parser.positionalArguments().at(m_positionalNames.size()))
                             .toStdString());
}

bool CommandParser::isSet(const QString& name) const {
    return m_parser.isSet(name);
}

QString CommandParser::value(const QString& name) const {
    return m_parser.value(name);
}

QString CommandParser::required(const QString& name) const {
    const QString v = m_parser.value(name);
    if (v.isEmpty()) throw optionError(name, QStringLiteral("is required"));
    return v;
}

long long CommandParser::integer(const QString& name, long long minValue, long long maxValue) const {
    bool ok = false;
    const long long v = required(name).toLongLong(&ok);
    if (!ok) throw optionError(name, QStringLiteral("'%1' is not a whole number").arg(value(name)));
    if (v < minValue || v > maxValue)
        throw optionError(name, QStringLiteral("%1 is outside %2 .. %3").arg(v).arg(minValue).arg(maxValue));
    return v;
}

double CommandParser::number(const QString& name, double minValue, double maxValue) const {
    bool ok = false;
    const double v = required(name).toDouble(&ok);
    if (!ok || !std::isfinite(v)) throw optionError(name, QStringLiteral("'%1' is not a number").arg(value(name)));
    if (v < minValue || v > maxValue)
        throw optionError(name, QStringLiteral("%1 is outside %2 .. %3").arg(v).arg(minValue).arg(maxValue));
    return v;
}

QString CommandParser::choice(const QString& name, const QStringList& choices) const {
    const QString v = required(name);
    if (!choices.contains(v))
        throw optionError(name, QStringLiteral("'%1' is not one of %2").arg(v, choices.join(QStringLiteral(", "))));
    return v;
}

QStringList CommandParser::positionals(int count) const {
    const QStringList args = m_parser.positionalArguments();
    if (args.size() < count)
        throw UsageError(QStringLiteral("missing %1").arg(m_positionalNames.value(args.size())).toStdString());
    return args.mid(0, count);
}

namespace {

/// Throws when stdout did not take everything written so far (a full disk, a closed pipe).
void flushStdout() {
    if (std::fflush(stdout) != 0 || std::ferror(stdout))
        throw std::runtime_error(std::string("cannot write the output: ") + std::strerror(errno));
}

/// Throws naming the first number in `value` that is NaN or infinite (JSON would print it as null).
void requireFinite(const QJsonValue& value, const QString& where) {
    if (value.isDouble() && !std::isfinite(value.toDouble()))
        throw std::runtime_error("the result " + where.toStdString() + " is not a finite number");
    if (value.isArray()) {
        const QJsonArray array = value.toArray();
        for (qsizetype i = 0; i < array.size(); ++i)
            requireFinite(array.at(i), QStringLiteral("%1[%2]").arg(where).arg(i));
    }
    if (value.isObject()) {
        const QJsonObject object = value.toObject();
        for (auto it = object.begin(); it != object.end(); ++it)
            requireFinite(it.value(), where.isEmpty() ? it.key() : where + QLatin1Char('.') + it.key());
    }
}

/// Whether every number in `value` is finite (no text built: a report holds millions of numbers).
bool allFinite(const QJsonValue& value) {
    if (value.isDouble()) return std::isfinite(value.toDouble());
    if (value.isArray()) {
        const QJsonArray array = value.toArray();
        return std::all_of(array.begin(), array.end(), [](const QJsonValue& v) { return allFinite(v); });
    }
    if (value.isObject()) {
        const QJsonObject object = value.toObject();
        return std::all_of(object.begin(), object.end(), [](const QJsonValue& v) { return allFinite(v); });
    }
    return true;
}

}  // namespace

void printJson(const QJsonObject& object) {
    if (!allFinite(object)) requireFinite(object, QString());  // names the first number that is not finite
    std::fputs(QJsonDocument(object).toJson(QJsonDocument::Indented).constData(), stdout);
    flushStdout();
}

void printLine(const QString& line) {
    std::fputs(qPrintable(line), stdout);
    std::fputc('\n', stdout);
    flushStdout();
}

}  // namespace tt::cli
