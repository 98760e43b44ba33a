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

std::optional<Notice> partRejection(const MachinedParts& parts, std::int64_t part, bool stillKept) {
    Notice n{NoticeKind::None, part};
    if (!parts.started || part > parts.lastPart)
        n.kind = NoticeKind::NotMachinedYet;
    else if (part < parts.firstPart)
        n.kind = NoticeKind::NotUnderController;
    else if (!stillKept) {
        n.kind = NoticeKind::TooLate;
        n.limit = static_cast<double>(parts.keptParts);
    }
    if (!n) return std::nullopt;
    return n;
}

std::optional<Notice> valueRejection(double valueMm, bool alreadyMeasured, std::int64_t part) {
    if (auto why = nonFiniteReason(valueMm)) return why;
    if (alreadyMeasured) return Notice{NoticeKind::AlreadyMeasured, part};
    return std::nullopt;
}

MeasurementVerdict rejectEveryPoint(int points, const Notice& why) {
    const auto m = static_cast<std::size_t>(points);
    return MeasurementVerdict{std::vector<bool>(m, false), std::vector<Notice>(m, why)};
}

std::size_t ringSlot(std::int64_t index, std::int64_t size) {
    return static_cast<std::size_t>(((index % size) + size) % size);
}

std::uint16_t configurationFingerprint(const std::vector<double>& numbers) {
    return crc16Ccitt(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(numbers.data()),
                                                    numbers.size() * sizeof(double)));
}

}  // namespace tt::core
