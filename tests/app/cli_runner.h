#pragma once

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QString>
#include <QStringList>
#include "tests/support/patient_wait.h"

namespace tt::test {

/// What a run of the `trueturn` binary produced.
struct CliResult {
    int exitCode = -1;
    QString out;
    QString err;

    /// stdout parsed as a JSON object (empty when it is not one).
    QJsonObject json() const { return QJsonDocument::fromJson(out.toUtf8()).object(); }
};

/// Runs `trueturn args...` headless (no display) and waits up to `timeoutMs`. `extraEnv` is
/// added to the environment (e.g. QT_QPA_PLATFORM=offscreen to start the GUI).
inline CliResult runTrueturn(const QStringList& args, int timeoutMs = kPatientWaitMs,
                             const QProcessEnvironment& extraEnv = QProcessEnvironment()) {
    QProcess process;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));
    env.remove(QStringLiteral("WAYLAND_DISPLAY"));
    env.remove(QStringLiteral("QT_QPA_PLATFORM"));
    env.insert(extraEnv);
    process.setProcessEnvironment(env);
    process.start(QStringLiteral(TRUETURN_EXE), args);
    process.waitForFinished(timeoutMs);
    CliResult r;
    r.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    r.out = QString::fromUtf8(process.readAllStandardOutput());
    r.err = QString::fromUtf8(process.readAllStandardError());
    return r;
}

}  // namespace tt::test
