#pragma once

#include <QDir>
#include <QProcess>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <QUuid>

namespace tt::test {

/// A PostgreSQL server of the test's own, started by scripts/start-test-postgres.sh in a fresh folder under /tmp
/// (the postgres user must reach it), so the test may stop it at once, start it again or stream it to a hot
/// standby without disturbing the server the other tests share. Stopped and removed on destruction.
class OwnPostgres {
public:
    /// A new server; with `primary`, a streaming hot standby of that server instead.
    explicit OwnPostgres(const OwnPostgres* primary = nullptr)
        : m_dir(QStringLiteral("/tmp/tt-pg-") + QUuid::createUuid().toString(QUuid::Id128).left(12)) {
        const int firstPort = 58000 + static_cast<int>(QRandomGenerator::global()->bounded(1500u)) * 2;
        const QStringList args = primary ? QStringList{QStringLiteral("--standby"), m_dir, primary->m_dir,
                                                       QString::number(firstPort)}
                                         : QStringList{m_dir, QString::number(firstPort)};
        const QString out = script(args);
        const QRegularExpressionMatch m =
            QRegularExpression(QStringLiteral("TRUETURN_PG(?:_STANDBY)?_URL=postgresql://[^@]*@127\\.0\\.0\\.1:(\\d+)/"))
                .match(out);
        if (m.hasMatch()) m_port = m.captured(1).toInt();
    }
    ~OwnPostgres() {
        script({QStringLiteral("--stop"), m_dir});
        QDir(m_dir).removeRecursively();
    }
    OwnPostgres(const OwnPostgres&) = delete;
    OwnPostgres& operator=(const OwnPostgres&) = delete;

    /// Whether the server runs; why not otherwise.
    bool ok() const { return m_port > 0; }
    const QString& problem() const { return m_problem; }
    int port() const { return m_port; }
    /// postgresql://user@127.0.0.1:port/database
    QString url(const QString& user, const QString& database) const {
        return QStringLiteral("postgresql://%1@127.0.0.1:%2/%3").arg(user).arg(m_port).arg(database);
    }
    /// Stops the server at once, as a crash or a power cut would (pg_ctl stop -m immediate).
    bool crash() { return !script({QStringLiteral("--crash"), m_dir}).isNull(); }
    /// Starts it again on the same port.
    bool restart() { return !script({QStringLiteral("--restart"), m_dir}).isNull(); }

private:
    /// Runs the script; its stdout, or a null string (and m_problem) when it failed.
    QString script(const QStringList& args) {
        QProcess p;
        p.start(QStringLiteral(TRUETURN_SOURCE_DIR "/scripts/start-test-postgres.sh"), args);
        if (!p.waitForFinished(180000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
            m_problem = QString::fromUtf8(p.readAllStandardError());
            return QString();
        }
        const QString out = QString::fromUtf8(p.readAllStandardOutput());
        return out.isNull() ? QStringLiteral("") : out;
    }

    QString m_dir;
    int m_port = 0;
    QString m_problem;
};

}  // namespace tt::test
