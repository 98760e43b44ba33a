#pragma once

#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <string>

namespace tt::config {

/// Reads the fields of one object of a preset and names "section.field" in every error, e.g.
/// "lathe.stiffness.headstock_n_per_mm: 0 is outside 1 .. 1e+08". An absent section reads as an empty
/// object, so every optional field takes its default.
class JsonSection {
public:
    /// The object `key` of `parent`, named `parentName.key` (or `key` when parentName is empty); throws
    /// std::invalid_argument "<name>: must be an object" when the key holds anything else.
    JsonSection(const QJsonObject& parent, const QString& key, const QString& parentName = QString());
    /// An object already at hand, named `name` in messages.
    static JsonSection of(QJsonObject object, QString name);

    /// The section's name in messages ("lathe.workpiece").
    const QString& name() const { return m_name; }
    /// Whether the section has field `key`.
    bool has(const QString& key) const { return m_object.contains(key); }
    /// Field `key` as it is (undefined when absent), for readers of other types.
    QJsonValue value(const QString& key) const { return m_object.value(key); }

    /// Optional number in [lo, hi], `fallback` when absent (optionalNumber).
    double number(const QString& key, double fallback, double lo, double hi) const;
    /// Required number in [lo, hi] (requireNumber).
    double required(const QString& key, double lo, double hi) const;
    /// Optional number > 0, `fallback` when absent ("<name>.<key>: must be > 0").
    double positive(const QString& key, double fallback) const;
    /// Optional whole number in [lo, hi] ("<name>.<key>: must be a whole number").
    int integer(const QString& key, int fallback, int lo, int hi) const;
    /// Optional true/false ("<name>.<key>: must be true or false").
    bool flag(const QString& key, bool fallback) const;
    /// Optional string ("<name>.<key>: must be a string").
    std::string text(const QString& key, const std::string& fallback) const;

    /// Throws std::invalid_argument "<name>.<key>: <why>" ("<name>: <why>" for an empty key).
    [[noreturn]] void fail(const QString& key, const std::string& why) const;

private:
    JsonSection() = default;

    QString m_name;
    QJsonObject m_object;
};

}  // namespace tt::config
