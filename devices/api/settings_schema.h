#pragma once

#include <QList>
#include <QString>
#include <QStringList>
#include <QVariant>
#include <QVariantMap>

namespace tt::devices {

/// One choice of a Choice field: the stored value and the label shown.
struct SettingChoice {
    QString value;
    QString label;
};

/// One setting of a device instance, described so that the Devices page can draw the form
/// for any plugin and check the values before the device is created.
struct SettingField {
    enum class Type {
        Text,        ///< free text (QString)
        Integer,     ///< whole number in [minimum, maximum], optionally one of allowedValues
        Number,      ///< real number in [minimum, maximum]
        Choice,      ///< one of `choices` (stored as the choice's value string)
        Bool,        ///< on/off
        SerialPort,  ///< a serial port name (/dev/ttyUSB0, COM3); must exist when validated
        Folder,      ///< a folder that must exist
    };

    QString key;    ///< stable key in the settings map ("baud")
    QString label;  ///< shown in the form ("Baud rate")
    Type type = Type::Text;
    QString unit;           ///< shown after the editor ("mm", "ms"); empty for none
    QString help;           ///< one sentence shown under the field
    QVariant defaultValue;  ///< value of a new instance
    double minimum = 0.0;   ///< Integer/Number: inclusive range (ignored when minimum >= maximum)
    double maximum = 0.0;
    int decimals = 3;               ///< Number: digits shown after the decimal point
    QList<qint64> allowedValues;    ///< Integer: the only accepted values (e.g. standard baud rates)
    QList<SettingChoice> choices;   ///< Choice: the options
    QString visibleWhenKey;         ///< shown and checked only when that field ...
    QStringList visibleWhenValues;  ///< ... has one of these values

    /// Builders for readable schemas.
    static SettingField text(QString key, QString label, QString defaultValue, QString help = {});
    static SettingField integer(QString key, QString label, qint64 defaultValue, qint64 minimum, qint64 maximum,
                                QString unit = {}, QString help = {});
    static SettingField number(QString key, QString label, double defaultValue, double minimum, double maximum,
                               QString unit = {}, int decimals = 3, QString help = {});
    static SettingField choice(QString key, QString label, QList<SettingChoice> choices, QString defaultValue,
                               QString help = {});
    static SettingField boolean(QString key, QString label, bool defaultValue, QString help = {});
    static SettingField serialPort(QString key, QString label, QString defaultValue = {}, QString help = {});
    static SettingField folder(QString key, QString label, QString defaultValue, QString help = {});
    /// This field only applies when `key` has one of `values`.
    SettingField& visibleWhen(QString key, QStringList values);
};

/// The settings of one device kind of one plugin, in form order.
using SettingsSchema = QList<SettingField>;

/// A problem with one value: the field key and a message in the user's terms that names the
/// field ("Baud rate: 9601 is not a standard rate (1200, 2400, ...)").
struct SettingIssue {
    QString key;
    QString message;
};

/// Whether `field` applies given the other values (see SettingField::visibleWhen).
bool isFieldVisible(const SettingField& field, const QVariantMap& values);
/// How far validation goes: Full also checks that serial ports and folders exist now (the form,
/// adding a device); Structure checks types, ranges and choices only (restoring saved devices,
/// whose adapter may be unplugged at start-up: the device then reports the missing port).
enum class Validation { Full, Structure };
/// Problems of `value` for `field`; empty when valid.
QString validateField(const SettingField& field, const QVariant& value, Validation depth = Validation::Full);
/// Every problem of `values` against `schema` (missing values take their default first).
QList<SettingIssue> validateSettings(const SettingsSchema& schema, const QVariantMap& values,
                                     Validation depth = Validation::Full);
/// `values` completed with the defaults of fields they lack, converted to the field types.
QVariantMap withDefaults(const SettingsSchema& schema, const QVariantMap& values);
/// The messages of `issues` joined for an exception or a log line.
QString joinIssues(const QList<SettingIssue>& issues);

}  // namespace tt::devices
