#pragma once

#include <gtest/gtest.h>

#include <QByteArray>
#include <QFile>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include "cli_runner.h"

namespace tt::test {

/// Writes `content` to the file `path` (created or truncated); a failure fails the test.
inline void writeFile(const QString& path, const QByteArray& content) {
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate)) << qPrintable(path);
    ASSERT_EQ(file.write(content), content.size()) << qPrintable(path);
}

/// Runs `trueturn args...` on bad input and checks the refusal: exit code 2, nothing on stdout,
/// exactly one line on stderr, containing `phrase`.
inline void expectRefused(const QStringList& args, const QString& phrase) {
    const CliResult r = runTrueturn(args);
    EXPECT_EQ(r.exitCode, 2) << qPrintable(args.join(' ')) << ": " << qPrintable(r.err);
    EXPECT_TRUE(r.out.isEmpty()) << qPrintable(r.out);
    EXPECT_EQ(r.err.trimmed().count(QLatin1Char('\n')), 0) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(phrase)) << "expected '" << qPrintable(phrase) << "' in: " << qPrintable(r.err);
}

/// A command-line test with its own temporary folder for the command's input and output files.
class CliTest : public ::testing::Test {
protected:
    /// The path of `name` in the test's folder.
    QString path(const QString& name) const { return m_dir.filePath(name); }

    /// Writes `content` to `name` in the test's folder; returns its path.
    QString write(const QString& name, const QByteArray& content) {
        const QString file = path(name);
        writeFile(file, content);
        return file;
    }

    QTemporaryDir m_dir;
};

}  // namespace tt::test
