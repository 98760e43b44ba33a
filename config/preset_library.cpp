#include "config/preset_library.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonParseError>
#include <stdexcept>

#include "core/common/bounded_input.h"

namespace tt::config {

namespace {

const QString kPresetFolder = QStringLiteral(":/presets");

/// The bytes of a built-in preset (a Qt resource) or of a preset file (at most kDocumentLimits).
QByteArray presetBytes(const QString& path, const QString& shownName) {
    if (path.startsWith(QStringLiteral(":/"))) {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly))
            throw std::invalid_argument("cannot open preset '" + shownName.toStdString() +
                                        "': " + file.errorString().toStdString());
        return file.readAll();
    }
    try {
        const std::string text = core::readBoundedFile(QFile::encodeName(path).toStdString(), core::kDocumentLimits);
        return QByteArray(text.data(), static_cast<qsizetype>(text.size()));
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("preset '" + shownName.toStdString() + "': " + e.what());
    }
}

QJsonObject parseFile(const QString& path, const QString& shownName) {
    QJsonParseError error{};
    const QJsonDocument doc = QJsonDocument::fromJson(presetBytes(path, shownName), &error);
    if (error.error != QJsonParseError::NoError)
        throw std::invalid_argument("preset '" + shownName.toStdString() + "' is not valid JSON at byte " +
                                    std::to_string(error.offset) + ": " + error.errorString().toStdString());
    if (!doc.isObject()) throw std::invalid_argument("preset '" + shownName.toStdString() + "' must be a JSON object");
    return doc.object();
}

}  // namespace

QStringList PresetLibrary::builtInNames() {
    QStringList names;
    const QStringList files = QDir(kPresetFolder).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (const QString& f : files)
        names << QFileInfo(f).completeBaseName();
    return names;
}

QJsonObject PresetLibrary::load(const QString& nameOrPath) {
    if (nameOrPath.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) return parseFile(nameOrPath, nameOrPath);
    const QString path = kPresetFolder + QLatin1Char('/') + nameOrPath + QStringLiteral(".json");
    if (!QFile::exists(path))
        throw std::invalid_argument("unknown preset '" + nameOrPath.toStdString() +
                                    "'; built-in presets: " + builtInNames().join(QStringLiteral(", ")).toStdString());
    return parseFile(path, nameOrPath);
}

}  // namespace tt::config
