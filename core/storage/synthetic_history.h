#pragma once

#include <cstdint>
#include <string>

#include "core/storage/database.h"

namespace tt::storage {

/// What writeSyntheticHistory generates: `parts` turned shafts spread evenly over `runs` runs on `machines`
/// lathes, each measured at `points` control points against an h7-like outer-diameter tolerance.
struct SyntheticHistorySpec {
    std::int64_t parts = 1000;           ///< 1 .. kMaxSyntheticParts
    int points = 5;                      ///< control points per part, 1 .. 16
    int runs = 10;                       ///< 1 .. 1000 (at most one run per part)
    int machines = 3;                    ///< machine names "lathe-1" .. "lathe-<machines>", 1 .. 100
    std::uint64_t seed = 1;              ///< the same seed gives the same values
    double nominalMm = 27.0;             ///< nominal diameter of every point
    double upperDeviationMm = 0.0;       ///< es of the tolerance (h7 at 27 mm: 0)
    double lowerDeviationMm = -0.021;    ///< ei of the tolerance (h7 at 27 mm: -0.021 mm, ISO 286-1)
    double implausibleFraction = 0.001;  ///< share of readings stored as refused (implausible), 0 .. 0.5
    std::int64_t firstPartEpochS = 1767225600;  ///< when the first part is stored (default 2026-01-01 00:00 UTC)
    /// The machines work side by side: each machine's parts are one minute apart from the first part on (a
    /// shop), instead of every part of the history one minute after the previous one (one machine at a time).
    bool machinesInParallel = false;
};

/// Largest history writeSyntheticHistory writes in one call.
inline constexpr std::int64_t kMaxSyntheticParts = 10'000'000;

/// What was written.
struct SyntheticHistoryResult {
    std::int64_t firstRunId = 0;
    std::int64_t lastRunId = 0;
    std::int64_t parts = 0;
    std::int64_t readings = 0;  ///< measurement rows (parts x points)
};

/// Appends a generated, realistic quality history to `db` in ONE transaction (nothing is left on failure):
/// per run and point a diameter process nominal - 0.0105 mm + N(0, 0.002 mm) point offset + the residual drift the
/// closed loop leaves (AR(1), phi 0.95, innovation 0.0003 mm: about 0.001 mm) + N(0, 0.003 mm) scatter; the verdict of
/// each reading from core's outer-diameter rule (above the upper limit rework, below the lower limit scrap); a share of
/// the readings stored as refused ("implausible", no verdict) as the loop stores them; parts one minute apart. For
/// benchmarks, demonstrations and tests of the reports at shop scale; corrections and controller state are not
/// generated. Throws std::invalid_argument on a spec out of range, StorageError on a database failure.
SyntheticHistoryResult writeSyntheticHistory(Database& db, const SyntheticHistorySpec& spec);

}  // namespace tt::storage
