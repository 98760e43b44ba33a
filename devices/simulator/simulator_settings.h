#pragma once

#include <QVariantMap>

#include "devices/api/gauge_settings.h"
#include "devices/api/settings_schema.h"
#include "devices/simulator/micrometer_emulator.h"

namespace tt::devices {

/// The emulated instrument format matching the gauge settings.
inline MicrometerEmulator::Format micrometerFormat(const QVariantMap& settings) {
    switch (gaugeFormat(settings)) {
        case GaugeFormat::DigimaticNibbles:
            return MicrometerEmulator::Format::DigimaticNibbles;
        case GaugeFormat::DigimaticHex:
            return MicrometerEmulator::Format::DigimaticHex;
        case GaugeFormat::Ascii:
            break;
    }
    return MicrometerEmulator::Format::Ascii;
}

/// Settings of the simulator's devices, per kind.
SettingsSchema simulatedGaugeSchema();
SettingsSchema simulatedProbeSchema();
SettingsSchema simulatedDriveSchema();
SettingsSchema simulatedOutputSchema();

}  // namespace tt::devices
