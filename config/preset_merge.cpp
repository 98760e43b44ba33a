#include "config/preset_merge.h"

#include <QJsonValue>

namespace tt::config {

QJsonObject mergePreset(const QJsonObject& base, const QJsonObject& overrides) {
    QJsonObject merged = base;
    for (auto it = overrides.begin(); it != overrides.end(); ++it) {
        const QJsonValue value = it.value();
        if (value.isNull()) {
            merged.remove(it.key());
        } else if (value.isObject() && merged.value(it.key()).isObject()) {
            merged.insert(it.key(), mergePreset(merged.value(it.key()).toObject(), value.toObject()));
        } else if (value.isObject()) {
            // A new object: its own nulls mean "absent" too.
            merged.insert(it.key(), mergePreset(QJsonObject(), value.toObject()));
        } else {
            merged.insert(it.key(), value);
        }
    }
    return merged;
}

}  // namespace tt::config
