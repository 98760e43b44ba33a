#pragma once

#include <QFile>
#include <QString>
#include <QtGlobal>
#include <mutex>

namespace tt::ui {

/// The application's log: every Qt message (the categories trueturn.devices, .devices.traffic,
/// .storage, .ui, .loop and Qt's own) as one line "time level category: text" in a file in the user's
/// data folder, rotated when it grows past a size (trueturn.log -> trueturn.1.log -> ... ; the oldest
/// dropped). Messages still reach the previous handler (the terminal). Thread-safe.
class LogFile {
public:
    /// Writes to `path`, rotating at `maxBytes` (> 0) and keeping `keep` (>= 1) older files. Throws
    /// std::runtime_error when the file cannot be opened (the folder is created when missing).
    LogFile(QString path, qint64 maxBytes = 1 << 20, int keep = 4);
    ~LogFile();
    LogFile(const LogFile&) = delete;
    LogFile& operator=(const LogFile&) = delete;

    /// Makes this the handler of every Qt message (until destroyed).
    void install();
    /// Writes one line (also what the handler does).
    void write(QtMsgType type, const char* category, const QString& text);
    const QString& path() const { return m_path; }

    /// The default place: <data folder>/logs/trueturn.log.
    static QString defaultPath();

private:
    void rotate();
    static void handle(QtMsgType type, const QMessageLogContext& context, const QString& text);

    QString m_path;
    qint64 m_maxBytes;
    int m_keep;
    QFile m_file;
    std::mutex m_mutex;
    QtMessageHandler m_previous = nullptr;
    bool m_installed = false;
};

}  // namespace tt::ui
