#pragma once

#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace tt::config {

/// The scenario presets: JSON files built into the binary (`:/presets/NAME.json`, from
/// resources/presets) or any file given by path. Every preset has "name", "description"
/// and the sections the engine parts read ("plant", "controller", "lathe", ...).
class PresetLibrary {
public:
    /// Names of the built-in presets, sorted.
    static QStringList builtInNames();

    /// Loads a built-in preset by name, or a JSON file when `nameOrPath` ends in ".json".
    /// Throws std::invalid_argument with a message naming the valid presets, or the file and
    /// the JSON parse error with its offset.
    static QJsonObject load(const QString& nameOrPath);
};

}  // namespace tt::config
