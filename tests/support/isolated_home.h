#pragma once

#include <QByteArray>
#include <QTemporaryDir>

namespace tt::test {

/// Points QSettings and QStandardPaths of this test process at a fresh temporary folder
/// (XDG_CONFIG_HOME, XDG_DATA_HOME), so tests never touch the user's data and parallel test
/// processes never share a settings file. (Qt's QStandardPaths test mode is not used: it puts
/// every process into the same ~/.qttest folder.) Construct before the Q*Application.
class IsolatedHome {
public:
    IsolatedHome() {
        qputenv("XDG_CONFIG_HOME", m_dir.filePath(QStringLiteral("config")).toUtf8());
        qputenv("XDG_DATA_HOME", m_dir.filePath(QStringLiteral("data")).toUtf8());
        qputenv("XDG_CACHE_HOME", m_dir.filePath(QStringLiteral("cache")).toUtf8());
    }

private:
    QTemporaryDir m_dir;
};

}  // namespace tt::test
