#include "ui/log_file.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <stdexcept>

namespace tt::ui {

namespace {

LogFile* g_installed = nullptr;

const char* levelWord(QtMsgType type) {
    switch (type) {
        case QtDebugMsg:
            return "debug";
        case QtInfoMsg:
            return "info";
        case QtWarningMsg:
            return "warning";
        case QtCriticalMsg:
            return "critical";
        case QtFatalMsg:
            return "fatal";
    }
    return "?";
}

/// trueturn.log -> trueturn.<n>.log
QString numbered(const QString& path, int n) {
    const QFileInfo info(path);
    return info.dir().filePath(QStringLiteral("%1.%2.%3").arg(info.completeBaseName()).arg(n).arg(info.suffix()));
}

}  // namespace

LogFile::LogFile(QString path, qint64 maxBytes, int keep)
    : m_path(std::move(path)), m_maxBytes(maxBytes), m_keep(keep), m_file(m_path) {
    if (maxBytes <= 0 || keep < 1)
        throw std::invalid_argument("the log needs a size above 0 and at least one old file");
    QDir().mkpath(QFileInfo(m_path).absolutePath());
    if (!m_file.open(QIODevice::Append | QIODevice::Text))
        throw std::runtime_error("the log file " + m_path.toStdString() +
                                 " cannot be opened: " + m_file.errorString().toStdString());
}

LogFile::~LogFile() {
    if (m_installed && g_installed == this) {
        qInstallMessageHandler(m_previous);
        g_installed = nullptr;
    }
}

QString LogFile::defaultPath() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("logs/trueturn.log"));
}

void LogFile::install() {
    g_installed = this;
    m_installed = true;
    m_previous = qInstallMessageHandler(&LogFile::handle);
}

void LogFile::handle(QtMsgType type, const QMessageLogContext& context, const QString& text) {
    LogFile* log = g_installed;
    if (!log) return;
    log->write(type, context.category, text);
    if (log->m_previous) log->m_previous(type, context, text);
}

void LogFile::write(QtMsgType type, const char* category, const QString& text) {
    const std::lock_guard lock(m_mutex);
    const QByteArray line = QStringLiteral("%1 %2 %3: %4\n")
                                .arg(QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs), levelWord(type),
                                     QString::fromLatin1(category ? category : "default"), text)
                                .toUtf8();
    if (m_file.size() + line.size() > m_maxBytes && m_file.size() > 0) rotate();
    m_file.write(line);
    m_file.flush();
}

void LogFile::rotate() {
    m_file.close();
    QFile::remove(numbered(m_path, m_keep));
    for (int n = m_keep - 1; n >= 1; --n)
        QFile::rename(numbered(m_path, n), numbered(m_path, n + 1));
    QFile::rename(m_path, numbered(m_path, 1));
    m_file.open(QIODevice::Append | QIODevice::Text);
}

}  // namespace tt::ui
