#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/control/run_to_run_controller.h"

namespace tt::core {

/// Largest history a run-to-run controller keeps to place late measurements, parts.
inline constexpr int kMaxHistoryParts = 4096;

/// Throws std::invalid_argument unless `parts` is 1 .. kMaxHistoryParts ("<who>: the history must be
/// 1 .. 4096 parts").
void requireHistoryParts(int parts, const std::string& who);

/// Throws std::invalid_argument unless the measurement has one value per control point ("<who>: a
/// measurement needs N values, got M").
void requireMeasurementSize(const PartMeasurement& measurement, int points, const std::string& who);

/// Throws std::invalid_argument unless `part` is `lastPart` + 1 once the controller has started
/// ("<who>: part numbers must increase by one (expected N, got M)").
void requireNextPart(bool started, std::int64_t lastPart, std::int64_t part, const std::string& who);

/// The parts a run-to-run controller has machined: from `firstPart` to `lastPart` once `started`, of
/// which it keeps the last `keptParts` to pair late measurements with.
struct MachinedParts {
    bool started = false;
    std::int64_t firstPart = 0;
    std::int64_t lastPart = 0;
    int keptParts = 0;
};

/// Why no value of a measurement of `part` can be used: the part has not been machined yet, was
/// machined before the controller started, or is too late (`stillKept` false: it has left the kept
/// history). Nothing when the measurement can be placed.
std::optional<Notice> partRejection(const MachinedParts& parts, std::int64_t part, bool stillKept);

/// Why one measured value cannot be used: NaN or Inf (nonFiniteReason), or its point was already
/// measured for `part`. Nothing when it can be used.
std::optional<Notice> valueRejection(double valueMm, bool alreadyMeasured, std::int64_t part);

/// A verdict that refuses all `points` values for one reason.
MeasurementVerdict rejectEveryPoint(int points, const Notice& why);

/// Slot of `index` in a ring buffer of `size` entries (negative indices wrap as well).
std::size_t ringSlot(std::int64_t index, std::int64_t size);

/// CRC-16/CCITT-FALSE (core/common) of a controller's configuration numbers, stored in its state so
/// that a state cannot be restored into a differently configured controller.
std::uint16_t configurationFingerprint(const std::vector<double>& numbers);

}  // namespace tt::core
