#pragma once

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <initializer_list>

namespace tt::cli {

/// Thrown after `--help` was printed; the dispatcher exits 0.
struct HelpShown {};

/// QCommandLineParser for one sub-command, with the common `--json` and `--help` options and
/// range-checked typed accessors. Every problem is a UsageError naming the option.
class CommandParser {
public:
    /// A parser for `trueturn <command>`; `description` is the first paragraph of its --help.
    CommandParser(const QString& command, const QString& description);

    /// Adds `--name`; with a `valueName` it takes a value (shown in --help), else it is a flag.
    void addOption(const QString& name, const QString& description, const QString& valueName = QString(),
                   const QString& defaultValue = QString());
    /// Adds a positional argument (FILE.csv) for --help; positionals() checks the count.
    void addPositional(const QString& name, const QString& description);

    /// Parses the arguments after the command name; prints help and throws HelpShown on --help.
    void parse(const QStringList& arguments);

    /// Whether `--name` was given.
    bool isSet(const QString& name) const;
    /// Whether `--json` was given (output as JSON on stdout).
    bool json() const { return isSet(QStringLiteral("json")); }
    /// The value of `--name`, or its default (empty when it has none).
    QString value(const QString& name) const;
    /// Every value of a repeated `--name` (empty when absent).
    QStringList values(const QString& name) const { return m_parser.values(name); }
    /// The value, which must be given.
    QString required(const QString& name) const;
    /// Integer in [minValue, maxValue].
    long long integer(const QString& name, long long minValue, long long maxValue) const;
    /// Finite number in [minValue, maxValue].
    double number(const QString& name, double minValue, double maxValue) const;
    /// One of `choices`.
    QString choice(const QString& name, const QStringList& choices) const;
    /// The positional arguments; exactly `count` of them are required.
    QStringList positionals(int count) const;

private:
    QString m_command;
    QCommandLineParser m_parser;
    QStringList m_positionalNames;
};

/// Writes `object` as indented JSON on stdout and flushes it; throws std::runtime_error (exit 1)
/// when the output cannot be written (a full disk) or a number in it is NaN or infinite.
void printJson(const QJsonObject& object);
/// Writes a line on stdout and flushes it; throws std::runtime_error when it cannot be written.
void printLine(const QString& line);

}  // namespace tt::cli
