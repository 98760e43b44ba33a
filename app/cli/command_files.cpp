#include "app/cli/command_files.h"

#include <QFile>
#include <stdexcept>

namespace tt::cli {

QByteArray readInputFile(const QString& path, const core::InputLimits& limits) {
    try {
        const std::string text = core::readBoundedFile(QFile::encodeName(path).toStdString(), limits);
        return QByteArray(text.data(), static_cast<qsizetype>(text.size()));
    } catch (const std::invalid_argument& e) {
        throw inputError(path, e.what());
    }
}

void writeOutputFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size() || !file.flush())
        throw std::runtime_error(QStringLiteral("cannot write %1: %2").arg(path, file.errorString()).toStdString());
}

UsageError inputError(const QString& path, const std::string& what) {
    return UsageError(QStringLiteral("%1: %2").arg(path, QString::fromStdString(what)).toStdString());
}

}  // namespace tt::cli
