#pragma once

#include <optional>

#include "core/ports/clock.h"
#include "core/ports/correction_output.h"
#include "core/ports/deflection_probe.h"
#include "core/ports/drive_current.h"

namespace tt::core {

/// What a simulated boring pass knows after a PLC cycle and a machine does not: the truth, for the
/// operator's plots (bore error with and without the compensation along the same bore).
struct BoringPassTruth {
    double timeS = 0.0;                          ///< the pass's time at the end of the cycle, s
    double zMm = 0.0;                            ///< tool position along the bore (0 = entry face), mm
    bool cutting = false;                        ///< the tool is in the bore
    double deflectionMm = 0.0;                   ///< the bar's real tip deflection along X, mm
    double forceN = 0.0;                         ///< the real radial cutting force, N
    double diameterErrorMm = 0.0;                ///< bore diameter minus nominal where the tool cuts, mm
    std::optional<double> uncompensatedErrorMm;  ///< the same on the same pass without compensation (twin), mm
};

/// The boring station an in-process compensation runs on, as the one thread that runs the
/// compensation sees it (paper 001): the deflection source (the cross-feed drive read-out and/or
/// the probe mandrel), the CNC output that takes the dynamic X offset, the clock, and the PLC
/// cycle. A machine moves by itself and its devices are reached through thread-safe relays; a
/// simulated pass moves on by one PLC cycle when told (advanceCycle, before each compensation
/// cycle, so the two stay in lock-step at any speed) and tells the truth of the pass. Every call
/// comes from that one thread unless an implementation says otherwise.
class BoringStation {
public:
    virtual ~BoringStation() = default;
    /// The cross-feed drive read-out; null when the station has none.
    virtual DriveCurrentReadout* driveReadout() = 0;
    /// The probe mandrel; null when the station has none.
    virtual DeflectionProbe* probe() = 0;
    /// The CNC output that takes the dynamic X offset.
    virtual CorrectionOutput& output() = 0;
    /// The station's time (samples are stamped with it).
    virtual const Clock& clock() const = 0;
    /// Before each compensation cycle: a simulated pass moves on by one PLC cycle; a machine moves
    /// by itself (nothing to do).
    virtual void advanceCycle() {}
    /// A simulated pass is over (the tool left the bore); a machine never finishes by itself.
    virtual bool finished() const { return false; }
    /// The PLC cycle the station runs at when it sets it (a simulated pass), s; nullopt: a machine
    /// runs at whatever cycle the compensation is set to.
    virtual std::optional<double> plcCycleS() const { return std::nullopt; }
    /// Whether several PLC cycles may run back to back (a simulated pass runs ahead of real time in
    /// lock-step with the compensation); false: one cycle per PLC period of wall time.
    virtual bool runsAheadOfTime() const { return false; }
    /// The truth of the cycle just run; nullopt on a machine.
    virtual std::optional<BoringPassTruth> truth() const { return std::nullopt; }
    /// The offset the CNC confirmed last, mm, when the output answers a write later than it
    /// returns (a relay to a device in another thread); nullopt when every write is answered at once.
    virtual std::optional<double> confirmedOffsetMm() const { return std::nullopt; }
};

}  // namespace tt::core
