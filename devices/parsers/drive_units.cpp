#include "devices/parsers/drive_units.h"

#include <utility>

namespace tt::devices {

namespace {

std::vector<std::pair<std::string_view, double>> table(DriveQuantity quantity) {
    switch (quantity) {
        case DriveQuantity::Current:
            return {{"A", 1.0}, {"mA", 1e-3}};
        case DriveQuantity::Velocity:
            return {{"mm/s", 1.0}, {"mm/min", 1.0 / 60.0}, {"m/min", 1000.0 / 60.0}, {"um/s", 1e-3}};
        case DriveQuantity::Position:
            return {{"mm", 1.0}, {"um", 1e-3}, {"m", 1000.0}};
    }
    return {};
}

}  // namespace

std::optional<double> toEngineUnitFactor(DriveQuantity quantity, std::string_view unit) {
    for (const auto& [name, factor] : table(quantity))
        if (name == unit) return factor;
    return std::nullopt;
}

std::vector<std::string_view> driveUnits(DriveQuantity quantity) {
    std::vector<std::string_view> names;
    for (const auto& entry : table(quantity))
        names.push_back(entry.first);
    return names;
}

}  // namespace tt::devices
