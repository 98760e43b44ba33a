#pragma once

#include <QList>
#include <QMetaType>
#include <QString>
#include <QVariantMap>
#include <optional>

#include "core/ports/device_health.h"
#include "devices/api/device.h"
#include "devices/api/device_kind.h"

namespace tt::runtime {

/// The id of the trial instance the Devices page tests typed settings on (DeviceHub::startTrial).
inline const QString kTrialDeviceId = QStringLiteral("trial");

/// One device instance as the windows see it: a snapshot taken in the device thread (DeviceHub keeps the
/// latest of each), never the instance itself. What a device can do is told by capabilities, never by
/// what it is.
struct DeviceView {
    QString id;
    QString name;
    QString pluginId;
    devices::DeviceKind kind = devices::DeviceKind::Gauge;
    QVariantMap settings;   ///< validated, with defaults filled in
    quintptr instance = 0;  ///< tells instances apart: another value, another instance (its settings were replaced)
    core::DeviceHealth health{core::DeviceState::Disconnected, {}};
    QString liveValue;  ///< "26.812 mm"
    QString lastError;
    QList<devices::DeviceStatistic> statistics;
    // ---- capabilities ----
    std::optional<devices::FaultSwitches> faults;    ///< the instrument has fault switches (a simulated one)
    bool runsBoringPass = false;                     ///< it runs a simulated boring pass of its own (BoringTruth)
    bool standBendsBar = false;                      ///< it sits on a stand with a screw jack (probe calibration)
    bool standAppliesLoad = false;                   ///< it sits on a stand with a hydraulic jack (k_p calibration)
    bool uploadsTable = false;                       ///< it takes a linearisation table (probe mandrels)
    std::optional<devices::MandrelInfo> mandrel;     ///< what the mandrel says about itself
    std::optional<devices::MandrelTableInfo> table;  ///< the table it reports
    devices::TableUploadStatus upload;               ///< the running or last table upload
};

/// The tone and one line for the status bar over every device (DeviceManager's summary, from snapshots).
struct DeviceSummary {
    enum class Tone { None, Ok, Warning, Fault };
    Tone tone = Tone::None;
    QString text;
};

}  // namespace tt::runtime

Q_DECLARE_METATYPE(tt::runtime::DeviceView)
