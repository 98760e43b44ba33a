#include "core/control/run_to_run_checks.h"

#include <span>
#include <stdexcept>

#include "core/common/crc16.h"
#include "core/control/correction_limits.h"

namespace tt::core {

void requireHistoryParts(int parts, const std::string& who) {
    if (parts < 1 || parts > kMaxHistoryParts)
        throw std::invalid_argument(who + ": the history must be 1 .. " + std::to_string(kMaxHistoryParts) + " parts");
}

void requireMeasurementSize(const PartMeasurement& measurement, int points, const std::string& who) {
    if (measurement.deviationMm.size() != points)
        throw std::invalid_argument(who + ": a measurement needs " + std::to_string(points) + " values, got " +
                                    std::to_string(measurement.deviationMm.size()));
}

void requireNextPart(bool started, std::int64_t lastPart, std::int64_t part, const std::string& who) {
    if (started && part != lastPart + 1)
        throw std::invalid_argument(who + ": part numbers must increase by one (expected " +
                                    std::to_string(lastPart + 1) + ", got " + std::to_string(part) + ")");
}

std::optional<std::string> partRejection(const MachinedParts& parts, std::int64_t part, bool stillKept) {
    if (!parts.started || part > parts.lastPart) return "part " + std::to_string(part) + " has not been machined yet";
    if (part < parts.firstPart) return "part " + std::to_string(part) + " was not machined under this controller";
    if (!stillKept)
        return "part " + std::to_string(part) + " is too late: the controller keeps the last " +
               std::to_string(parts.keptParts) + " parts";
    return std::nullopt;
}

std::optional<std::string> valueRejection(double valueMm, bool alreadyMeasured, std::int64_t part) {
    if (auto why = nonFiniteReason(valueMm)) return why;
    if (alreadyMeasured) return "point already measured for part " + std::to_string(part);
    return std::nullopt;
}

MeasurementVerdict rejectEveryPoint(int points, const std::string& why) {
    const auto m = static_cast<std::size_t>(points);
    return MeasurementVerdict{std::vector<bool>(m, false), std::vector<std::string>(m, why)};
}

std::size_t ringSlot(std::int64_t index, std::int64_t size) {
    return static_cast<std::size_t>(((index % size) + size) % size);
}

std::uint16_t configurationFingerprint(const std::vector<double>& numbers) {
    return crc16Ccitt(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(numbers.data()),
                                                    numbers.size() * sizeof(double)));
}

}  // namespace tt::core
