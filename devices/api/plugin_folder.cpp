#include "devices/api/plugin_folder.h"

#include <QCoreApplication>
#include <QDir>

namespace tt::devices {

QString defaultPluginFolder() {
    const QString overridden = qEnvironmentVariable("TRUETURN_PLUGIN_DIR");
    if (!overridden.isEmpty()) return QDir(overridden).absolutePath();
    return QDir::cleanPath(
        QDir(QCoreApplication::applicationDirPath()).filePath(QString::fromLatin1(kPluginSubfolder)));
}

}  // namespace tt::devices
