#include "core/sim/feed_drives/drive_identification.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/brent_minimum.h"
#include "core/common/operation_cancelled.h"
#include "core/common/text_format.h"
#include "core/control/corner_drift_monitor.h"

namespace tt::core {

namespace {

constexpr double kLogTolerance = 2e-3;  // 0.2 % on a factor
constexpr int kMaxEvaluations = 30;
constexpr double kStallMismatchMm = 1000.0;  // a corner a drive cannot run counts as 1 m off at every sample
constexpr double kBreakawayShare = 0.9;      // the model's static friction stays below 90 % of the peak torque
constexpr double kMissRms = 3.0;             // a corner this many times the median RMS difference off is a miss
constexpr double kMissFloorUm = 2.0;         // ... and at least this far off (the encoder's 1 µm steps)
constexpr std::size_t kMinKeptCorners = 3;   // the fit is redone without misses when this many corners are left

void requireBracket(double lo, double hi, const char* what) {
    if (!(lo >= 0.05 && lo <= 1.0) || !(hi >= 1.0 && hi <= 20.0))
        throw std::invalid_argument(std::string("identification bracket of the ") + what + " factor " +
                                    formatSignificant(lo, 4) + " .. " + formatSignificant(hi, 4) +
                                    " is outside 0.05 .. 1 (lower) and 1 .. 20 (upper)");
}

struct Mismatch {
    double sumMm2 = 0.0;
    long samples = 0;
};

// The X and Z encoder differences of one corner; a corner a drive cannot run is as far off as can be.
struct CornerMismatch {
    Mismatch x;
    Mismatch z;
};

CornerMismatch cornerMismatch(const FeedDrivesConfig& drives, const CornerCostSettings& cost,
                              const PulseSettings& pulse, const RecordedCorner& c, int traceEvery) {
    CornerSimulationOptions options;
    options.keepTrace = true;
    options.traceEvery = traceEvery;
    CornerMismatch m;
    const auto compare = [](const std::vector<double>& simulated, const std::vector<double>& recorded, Mismatch& out) {
        const std::size_t n = std::min(simulated.size(), recorded.size());
        for (std::size_t i = 0; i < n; ++i)
            out.sumMm2 += (simulated[i] - recorded[i]) * (simulated[i] - recorded[i]);
        out.samples = static_cast<long>(n);
    };
    try {
        const CornerTrace t = simulateCorner(drives, cost, c.move, pulse, c.amplitudeV, options).trace;
        compare(t.encoderXMm, c.trace.encoderXMm, m.x);
        compare(t.encoderZMm, c.trace.encoderZMm, m.z);
    } catch (const OperationCancelled&) {
        throw;
    } catch (const std::runtime_error&) {  // a drive stalled
        m.x = {kStallMismatchMm * kStallMismatchMm * static_cast<double>(c.trace.encoderXMm.size()),
               static_cast<long>(c.trace.encoderXMm.size())};
        m.z = {kStallMismatchMm * kStallMismatchMm * static_cast<double>(c.trace.encoderZMm.size()),
               static_cast<long>(c.trace.encoderZMm.size())};
    }
    return m;
}

Mismatch mismatch(const FeedDrivesConfig& drives, const CornerCostSettings& cost, const PulseSettings& pulse,
                  const std::vector<RecordedCorner>& corners, FeedAxis axis, int traceEvery) {
    Mismatch m;
    for (const RecordedCorner& c : corners) {
        const CornerMismatch one = cornerMismatch(drives, cost, pulse, c, traceEvery);
        const Mismatch& a = axis == FeedAxis::X ? one.x : one.z;
        m.sumMm2 += a.sumMm2;
        m.samples += a.samples;
    }
    return m;
}

double rmsUm(const Mismatch& m) {
    return 1e3 * std::sqrt(m.sumMm2 / static_cast<double>(std::max(m.samples, 1L)));
}

// The largest friction factor tried on `axis`: the bracket's, lowered to keep the drive's static friction
// below kBreakawayShare of its peak torque.
double frictionCeiling(const FeedDrivesConfig& nominal, FeedAxis axis, const DriveIdentificationSettings& s) {
    const FeedDriveAxisConfig& c = axisConfig(nominal, axis);
    if (c.staticFrictionNm <= 0.0) return s.frictionMax;
    return std::min(s.frictionMax, kBreakawayShare * c.torqueConstantNmPerA * c.currentLimitA / c.staticFrictionNm);
}

// What the searches of one identification share.
struct Records {
    const FeedDrivesConfig& nominal;
    const CornerCostSettings& cost;
    const PulseSettings& pulse;
    const std::vector<RecordedCorner>& corners;
    int traceEvery;
    int simulations = 0;

    double mismatchUm(const FeedDrivesFactors& factors, FeedAxis axis) {
        simulations += static_cast<int>(corners.size());
        return rmsUm(mismatch(scaledDrives(nominal, factors), cost, pulse, corners, axis, traceEvery));
    }

    // The mean over the corners of each corner's RMS difference on `axis`, µm: one corner a load hit
    // pulls on it less than on the RMS over all samples (least absolute deviations across corners).
    double meanCornerRmsUm(const FeedDrivesFactors& factors, FeedAxis axis) {
        const FeedDrivesConfig drives = scaledDrives(nominal, factors);
        double sum = 0.0;
        for (const RecordedCorner& c : corners) {
            const CornerMismatch m = cornerMismatch(drives, cost, pulse, c, traceEvery);
            sum += rmsUm(axis == FeedAxis::X ? m.x : m.z);
        }
        simulations += static_cast<int>(corners.size());
        return sum / static_cast<double>(corners.size());
    }

    // One factor of one drive by Brent's method on its logarithm within [lo, hi].
    double search(const FeedDrivesFactors& factors, FeedAxis axis, double DriveFactors::*which, double lo, double hi) {
        const auto f = [&](double logFactor) {
            FeedDrivesFactors trial = factors;
            axisFactors(trial, axis).*which = std::exp(logFactor);
            return meanCornerRmsUm(trial, axis);
        };
        return std::exp(minimiseBrent(f, std::log(lo), std::log(hi), kLogTolerance, kMaxEvaluations).x);
    }
};

FeedDrivesFactors clampedStart(const FeedDrivesConfig& nominal, const FeedDrivesFactors& start,
                               const DriveIdentificationSettings& settings) {
    FeedDrivesFactors f = start;
    for (FeedAxis axis : {FeedAxis::X, FeedAxis::Z}) {
        DriveFactors& a = axisFactors(f, axis);
        a.friction = std::clamp(a.friction, settings.frictionMin, frictionCeiling(nominal, axis, settings));
        a.inertia = std::clamp(a.inertia, settings.inertiaMin, settings.inertiaMax);
        a.velocityGain = std::clamp(a.velocityGain, settings.gainMin, settings.gainMax);
    }
    return f;
}

// Coordinate descent, Z first: the pulse fires on the Z encoder, so the X record depends on the Z drive
// (not the reverse when the pulse is on X). Per drive the gain first, the largest effect (it sets the
// following error); the inertia and the friction shape the transients at the corner.
void descend(Records& records, FeedDrivesFactors& factors, const DriveIdentificationSettings& s) {
    for (int sweep = 0; sweep < s.sweeps; ++sweep)
        for (FeedAxis axis : {FeedAxis::Z, FeedAxis::X}) {
            DriveFactors& a = axisFactors(factors, axis);
            a.velocityGain = records.search(factors, axis, &DriveFactors::velocityGain, s.gainMin, s.gainMax);
            a.inertia = records.search(factors, axis, &DriveFactors::inertia, s.inertiaMin, s.inertiaMax);
            a.friction = records.search(factors, axis, &DriveFactors::friction, s.frictionMin,
                                        frictionCeiling(records.nominal, axis, s));
        }
}

// RMS difference of each corner's X and Z encoder records from the simulation on `drives`, µm.
std::vector<double> cornerRmsUm(const FeedDrivesConfig& drives, const CornerCostSettings& cost,
                                const PulseSettings& pulse, const std::vector<RecordedCorner>& corners,
                                int traceEvery) {
    std::vector<double> out;
    for (const RecordedCorner& c : corners) {
        const CornerMismatch m = cornerMismatch(drives, cost, pulse, c, traceEvery);
        out.push_back(rmsUm({m.x.sumMm2 + m.z.sumMm2, m.x.samples + m.z.samples}));
    }
    return out;
}

}  // namespace

void validateDriveIdentification(const DriveIdentificationSettings& s) {
    requireBracket(s.frictionMin, s.frictionMax, "friction");
    requireBracket(s.inertiaMin, s.inertiaMax, "inertia");
    requireBracket(s.gainMin, s.gainMax, "velocity gain");
    if (s.sweeps < 1 || s.sweeps > 5)
        throw std::invalid_argument("identification sweeps " + std::to_string(s.sweeps) + " is outside 1 .. 5");
}

double encoderMismatchUm(const FeedDrivesConfig& drives, const CornerCostSettings& cost, const PulseSettings& pulse,
                         const std::vector<RecordedCorner>& corners, FeedAxis axis, int traceEvery) {
    return rmsUm(mismatch(drives, cost, pulse, corners, axis, traceEvery));
}

DriveEstimate identifyDrives(const FeedDrivesConfig& nominal, const FeedDrivesFactors& start,
                             const CornerCostSettings& cost, const PulseSettings& pulse,
                             const std::vector<RecordedCorner>& corners, const DriveIdentificationSettings& settings,
                             int traceEvery) {
    if (corners.empty()) throw std::invalid_argument("drive identification needs at least one recorded corner");
    validateDriveIdentification(settings);
    Records records{nominal, cost, pulse, corners, traceEvery};
    DriveEstimate e;
    e.factors = clampedStart(nominal, start, settings);
    descend(records, e.factors, settings);
    // Misses: corners the fitted drives cannot reproduce (a load hit them); the fit is redone without them.
    const std::vector<double> perCorner =
        cornerRmsUm(scaledDrives(nominal, e.factors), cost, pulse, corners, traceEvery);
    const double limitUm = std::max(kMissRms * median(perCorner), kMissFloorUm);
    std::vector<RecordedCorner> kept;
    for (std::size_t i = 0; i < corners.size(); ++i)
        if (perCorner[i] <= limitUm) kept.push_back(corners[i]);
    records.simulations += static_cast<int>(corners.size());
    if (kept.size() < corners.size() && kept.size() >= kMinKeptCorners) {
        Records again{nominal, cost, pulse, kept, traceEvery, records.simulations};
        descend(again, e.factors, settings);
        e.missesLeftOut = static_cast<int>(corners.size() - kept.size());
        records.simulations = again.simulations;
    } else {
        kept = corners;
    }
    Records final{nominal, cost, pulse, kept, traceEvery, records.simulations};
    e.xRmsUm = final.mismatchUm(e.factors, FeedAxis::X);
    e.zRmsUm = final.mismatchUm(e.factors, FeedAxis::Z);
    e.simulations = final.simulations;
    return e;
}

}  // namespace tt::core
