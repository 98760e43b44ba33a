#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace tt::devices {

/// The three quantities a drive-current readout delivers.
enum class DriveQuantity { Current, Velocity, Position };

/// Factor that converts a value in `unit` to the engine's unit of `quantity` (A, mm/s, mm):
/// current "A", "mA"; velocity "mm/s", "mm/min", "m/min", "um/s"; position "mm", "um", "m".
/// nullopt for a unit the quantity does not know (never guessed).
std::optional<double> toEngineUnitFactor(DriveQuantity quantity, std::string_view unit);

/// The units accepted for `quantity`, the engine's unit first.
std::vector<std::string_view> driveUnits(DriveQuantity quantity);

}  // namespace tt::devices
