#pragma once

#include <QVariantMap>

#include "devices/api/settings_schema.h"
#include "devices/parsers/gauge_decoder.h"
#include "devices/parsers/length_unit.h"

namespace tt::devices {

/// The gauge fields shared by the serial gauge and the simulator's gauge: output format
/// ("format": ascii / digimatic-nibbles / digimatic-hex), the unit the instrument is set to
/// ("instrumentUnit", used when the frame carries none) and the unit of the job's drawing
/// ("jobUnit": readings in another unit are refused).
SettingsSchema gaugeFormatFields();

GaugeFormat gaugeFormat(const QVariantMap& settings);
LengthUnit instrumentUnit(const QVariantMap& settings);
LengthUnit jobUnit(const QVariantMap& settings);

}  // namespace tt::devices
