#include "devices/api/settings_schema.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <cmath>

#include "devices/api/serial_settings.h"

namespace tt::devices {

namespace {

/// The parts every kind of field has.
SettingField basicField(QString key, QString label, SettingField::Type type, QVariant defaultValue, QString help) {
    SettingField f;
    f.key = std::move(key);
    f.label = std::move(label);
    f.type = type;
    f.defaultValue = std::move(defaultValue);
    f.help = std::move(help);
    return f;
}

}  // namespace

SettingField SettingField::text(QString key, QString label, QString defaultValue, QString help) {
    return basicField(std::move(key), std::move(label), Type::Text, std::move(defaultValue), std::move(help));
}

SettingField SettingField::integer(QString key, QString label, qint64 defaultValue, qint64 minimum, qint64 maximum,
                                   QString unit, QString help) {
    SettingField f = basicField(std::move(key), std::move(label), Type::Integer, defaultValue, std::move(help));
    f.minimum = static_cast<double>(minimum);
    f.maximum = static_cast<double>(maximum);
    f.unit = std::move(unit);
    return f;
}

SettingField SettingField::number(QString key, QString label, double defaultValue, double minimum, double maximum,
                                  QString unit, int decimals, QString help) {
    SettingField f = basicField(std::move(key), std::move(label), Type::Number, defaultValue, std::move(help));
    f.minimum = minimum;
    f.maximum = maximum;
    f.unit = std::move(unit);
    f.decimals = decimals;
    return f;
}

SettingField SettingField::choice(QString key, QString label, QList<SettingChoice> choices, QString defaultValue,
                                  QString help) {
    SettingField f =
        basicField(std::move(key), std::move(label), Type::Choice, std::move(defaultValue), std::move(help));
    f.choices = std::move(choices);
    return f;
}

SettingField SettingField::boolean(QString key, QString label, bool defaultValue, QString help) {
    return basicField(std::move(key), std::move(label), Type::Bool, defaultValue, std::move(help));
}

SettingField SettingField::serialPort(QString key, QString label, QString defaultValue, QString help) {
    return basicField(std::move(key), std::move(label), Type::SerialPort, std::move(defaultValue), std::move(help));
}

SettingField SettingField::folder(QString key, QString label, QString defaultValue, QString help) {
    return basicField(std::move(key), std::move(label), Type::Folder, std::move(defaultValue), std::move(help));
}

SettingField& SettingField::visibleWhen(QString otherKey, QStringList values) {
    visibleWhenKey = std::move(otherKey);
    visibleWhenValues = std::move(values);
    return *this;
}

bool isFieldVisible(const SettingField& field, const QVariantMap& values) {
    if (field.visibleWhenKey.isEmpty()) return true;
    return field.visibleWhenValues.contains(values.value(field.visibleWhenKey).toString());
}

namespace {

QString formatNumber(double v) {
    return QString::number(v, 'g', 10);
}

QString rangeText(const SettingField& field) {
    QString text = QCoreApplication::translate("DeviceSettings", "%1 to %2")
                       .arg(formatNumber(field.minimum), formatNumber(field.maximum));
    if (!field.unit.isEmpty()) text += QLatin1Char(' ') + field.unit;
    return text;
}

bool hasRange(const SettingField& field) {
    return field.minimum < field.maximum;
}

}  // namespace

QString validateField(const SettingField& field, const QVariant& value, Validation depth) {
    const QString name = field.label;
    const QString text = value.toString().trimmed();
    switch (field.type) {
        case SettingField::Type::Text:
            return {};
        case SettingField::Type::Bool:
            if (value.typeId() == QMetaType::Bool || text == QLatin1String("true") || text == QLatin1String("false"))
                return {};
            return QCoreApplication::translate("DeviceSettings", "%1: '%2' is not on or off").arg(name, text);
        case SettingField::Type::Integer: {
            bool ok = false;
            const qint64 v = text.toLongLong(&ok);
            if (text.isEmpty())
                return QCoreApplication::translate("DeviceSettings", "%1: a whole number is required").arg(name);
            if (!ok)
                return QCoreApplication::translate("DeviceSettings", "%1: '%2' is not a whole number").arg(name, text);
            if (!field.allowedValues.isEmpty() && !field.allowedValues.contains(v)) {
                QStringList allowed;
                for (qint64 a : field.allowedValues)
                    allowed << QString::number(a);
                return QCoreApplication::translate("DeviceSettings", "%1: %2 is not one of %3")
                    .arg(name, text, allowed.join(QStringLiteral(", ")));
            }
            if (hasRange(field) && (static_cast<double>(v) < field.minimum || static_cast<double>(v) > field.maximum))
                return QCoreApplication::translate("DeviceSettings", "%1: %2 is outside %3")
                    .arg(name, text, rangeText(field));
            return {};
        }
        case SettingField::Type::Number: {
            bool ok = false;
            const double v = text.toDouble(&ok);
            if (text.isEmpty())
                return QCoreApplication::translate("DeviceSettings", "%1: a number is required").arg(name);
            if (!ok || !std::isfinite(v))
                return QCoreApplication::translate("DeviceSettings", "%1: '%2' is not a number").arg(name, text);
            if (hasRange(field) && (v < field.minimum || v > field.maximum))
                return QCoreApplication::translate("DeviceSettings", "%1: %2 is outside %3")
                    .arg(name, text, rangeText(field));
            return {};
        }
        case SettingField::Type::Choice: {
            QStringList labels;
            for (const SettingChoice& c : field.choices) {
                if (c.value == text) return {};
                labels << c.label;
            }
            return QCoreApplication::translate("DeviceSettings", "%1: '%2' is not one of %3")
                .arg(name, text, labels.join(QStringLiteral(", ")));
        }
        case SettingField::Type::SerialPort:
            if (text.isEmpty())
                return QCoreApplication::translate("DeviceSettings",
                                                   "%1: choose the serial port the device is connected to")
                    .arg(name);
            if (depth == Validation::Full && !serialPortExists(text))
                return QCoreApplication::translate("DeviceSettings",
                                                   "%1: %2 does not exist on this computer (is the cable plugged in?)")
                    .arg(name, text);
            return {};
        case SettingField::Type::Folder: {
            if (text.isEmpty()) return QCoreApplication::translate("DeviceSettings", "%1: choose a folder").arg(name);
            if (depth == Validation::Structure) return {};
            const QFileInfo info(text);
            if (!info.isDir())
                return QCoreApplication::translate("DeviceSettings", "%1: the folder %2 does not exist")
                    .arg(name, text);
            if (!info.isWritable())
                return QCoreApplication::translate("DeviceSettings", "%1: the folder %2 is not writable")
                    .arg(name, text);
            return {};
        }
    }
    return {};
}

QVariantMap withDefaults(const SettingsSchema& schema, const QVariantMap& values) {
    QVariantMap out = values;
    for (const SettingField& field : schema) {
        if (!out.contains(field.key) || !out.value(field.key).isValid()) out.insert(field.key, field.defaultValue);
    }
    return out;
}

QList<SettingIssue> validateSettings(const SettingsSchema& schema, const QVariantMap& values, Validation depth) {
    const QVariantMap complete = withDefaults(schema, values);
    QList<SettingIssue> issues;
    for (const SettingField& field : schema) {
        if (!isFieldVisible(field, complete)) continue;
        const QString problem = validateField(field, complete.value(field.key), depth);
        if (!problem.isEmpty()) issues.append({field.key, problem});
    }
    return issues;
}

QString joinIssues(const QList<SettingIssue>& issues) {
    QStringList messages;
    for (const SettingIssue& issue : issues)
        messages << issue.message;
    return messages.join(QStringLiteral("; "));
}

}  // namespace tt::devices
