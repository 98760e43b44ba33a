#include "core/sim/feed_drives/corner_scenario.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "core/common/text_format.h"
#include "core/sim/shaft/lathe_random.h"

namespace tt::core {

namespace {

void requireRange(double v, double lo, double hi, const std::string& what) {
    if (!std::isfinite(v) || v < lo || v > hi)
        throw std::invalid_argument(what + " " + formatSignificant(v, 6) + " is outside " + formatSignificant(lo, 6) +
                                    " .. " + formatSignificant(hi, 6));
}

void validateRange(const SpeedRange& r, const char* axis) {
    const std::string name = std::string(axis) + " speed range";
    requireRange(r.minRadPerS, kMinCornerSpeedRadPerS, kMaxCornerSpeedRadPerS, name + " minimum (rad/s)");
    requireRange(r.maxRadPerS, r.minRadPerS, kMaxCornerSpeedRadPerS, name + " maximum (rad/s)");
}

}  // namespace

void validateCornerScenario(const CornerScenario& s) {
    validateFeedDrives(s.drives);
    validateCornerCost(s.cost);
    validatePulse(s.pulse);
    validateRange(s.xSpeeds, "X");
    validateRange(s.zSpeeds, "Z");
    requireRange(s.training.moves, 10, 100000, "training moves");
    requireRange(s.training.search.gridPoints, 3, 201, "amplitude grid points");
    requireRange(s.training.search.toleranceV, 1e-6, 0.05, "amplitude tolerance (V)");
    requireRange(s.training.search.maxSimulations, s.training.search.gridPoints + 3, 1000, "simulations per search");
    validateNetTraining(s.training.network);
    validateDriftMonitor(s.retraining.monitor);
    requireRange(s.retraining.oldSetWeight, 0.0, 1.0, "weight of the old training set");
    validateDriveIdentification(s.retraining.identification);
    requireRange(s.retraining.validationMoves, 5, 1000, "validation moves of a retraining");
    requireRange(s.machine.frictionScatter, 0.0, 0.3, "friction scatter per corner");
    requireRange(s.machine.outlierProbability, 0.0, 0.5, "share of corners hit by a load");
    requireRange(s.machine.outlierTorqueNm, 0.0, 100.0, "load torque of a miss (N·m)");
    requireRange(s.machine.outlierDurationS, 0.0, 0.5, "duration of a miss's load (s)");
    requireRange(s.evaluationMoves, 1, 100000, "work moves");
}

std::vector<CornerMove> drawCornerMoves(const SpeedRange& x, const SpeedRange& z, int count, unsigned long long seed) {
    if (count < 1 || count > 100000)
        throw std::invalid_argument("number of moves " + std::to_string(count) + " is outside 1 .. 100000");
    validateRange(x, "X");
    validateRange(z, "Z");
    std::mt19937_64 engine(splitMix64(seed));
    // 53-bit uniforms written out: std::uniform_real_distribution differs between standard libraries.
    const auto draw = [&engine](const SpeedRange& r) {
        return r.minRadPerS + (r.maxRadPerS - r.minRadPerS) * (static_cast<double>(engine() >> 11) * 0x1.0p-53);
    };
    std::vector<CornerMove> moves;
    moves.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        CornerMove m;
        m.x1RadPerS = draw(x);
        m.z1RadPerS = draw(z);
        m.x2RadPerS = draw(x);
        m.z2RadPerS = draw(z);
        moves.push_back(m);
    }
    return moves;
}

}  // namespace tt::core
