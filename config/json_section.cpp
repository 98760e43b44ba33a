#include "config/json_section.h"

#include <limits>
#include <stdexcept>
#include <utility>

#include "config/json_eigen.h"

namespace tt::config {

JsonSection::JsonSection(const QJsonObject& parent, const QString& key, const QString& parentName)
    : m_name(parentName.isEmpty() ? key : parentName + QLatin1Char('.') + key) {
    const QJsonValue v = parent.value(key);
    if (!v.isUndefined() && !v.isObject()) fail(QString(), "must be an object");
    m_object = v.toObject();
}

JsonSection JsonSection::of(QJsonObject object, QString name) {
    JsonSection s;
    s.m_name = std::move(name);
    s.m_object = std::move(object);
    return s;
}

double JsonSection::number(const QString& key, double fallback, double lo, double hi) const {
    try {
        return optionalNumber(m_object, key, fallback, lo, hi);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(m_name.toStdString() + "." + e.what());
    }
}

double JsonSection::required(const QString& key, double lo, double hi) const {
    try {
        return requireNumber(m_object, key, lo, hi);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(m_name.toStdString() + "." + e.what());
    }
}

double JsonSection::positive(const QString& key, double fallback) const {
    const double v = number(key, fallback, -std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
    if (v <= 0.0) fail(key, QStringLiteral("%1 must be > 0").arg(v).toStdString());
    return v;
}

int JsonSection::integer(const QString& key, int fallback, int lo, int hi) const {
    const double v = number(key, fallback, lo, hi);
    if (v != static_cast<int>(v)) fail(key, "must be a whole number");
    return static_cast<int>(v);
}

bool JsonSection::flag(const QString& key, bool fallback) const {
    const QJsonValue v = m_object.value(key);
    if (v.isUndefined()) return fallback;
    if (!v.isBool()) fail(key, "must be true or false");
    return v.toBool();
}

std::string JsonSection::text(const QString& key, const std::string& fallback) const {
    const QJsonValue v = m_object.value(key);
    if (v.isUndefined()) return fallback;
    if (!v.isString()) fail(key, "must be a string");
    return v.toString().toStdString();
}

void JsonSection::fail(const QString& key, const std::string& why) const {
    throw std::invalid_argument(m_name.toStdString() + (key.isEmpty() ? "" : "." + key.toStdString()) + ": " + why);
}

}  // namespace tt::config
