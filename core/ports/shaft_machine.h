#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/ports/clock.h"
#include "core/ports/correction_output.h"
#include "core/ports/diameter_gauge.h"
#include "core/ports/machine_cycle.h"

namespace tt::core {

/// The true diameter error along a finished part (diameter minus nominal), which only a simulated
/// machine knows.
struct TrueProfile {
    std::int64_t partNumber = 0;
    std::vector<double> zMm;
    std::vector<double> errorMm;
};

/// The machine a shaft run-to-run run goes on (paper 000's outer loop), as one object: its part
/// cycle, its CNC output, its diameter gauge and its time. The built-in simulated lathe
/// (core/run/simulated_lathe.h) and the real lathe's devices joined through relays
/// (core/loop/relayed_lathe.h) implement it; the run builder, the loop and the pages use only this
/// interface and its capabilities (the virtuals with a default), never the concrete class.
/// Used from one thread (the loop's) except where a method says otherwise.
class ShaftMachine {
public:
    virtual ~ShaftMachine() = default;

    virtual MachineCycle& cycle() = 0;
    virtual CorrectionOutput& output() = 0;
    /// The machine's automatic gauge (a real lathe without one reports it not ready).
    virtual DiameterGauge& gauge() = 0;
    /// The machine's time (thread-safe).
    virtual const Clock& clock() const = 0;

    // ---- capabilities (a machine without one keeps the default) ----

    /// When the machine will next do something by itself, s of its clock; +infinity for a machine whose
    /// time is the wall clock (it is polled).
    virtual double nextEventTimeS() const { return std::numeric_limits<double>::infinity(); }
    /// Moves a machine that lives in simulated time on to `timeS` at once (never backwards); false
    /// when its time is the wall clock.
    virtual bool jumpTo(double timeS) {
        (void)timeS;
        return false;
    }
    /// Diameters typed by hand (true) or from the gauge: a simulated operator stops measuring; a real
    /// gauge's readings taken meanwhile are dropped. Returns how many readings were dropped.
    virtual std::size_t setManualEntry(bool manual) {
        (void)manual;
        return 0;
    }
    /// The true profile of a part that came off the machine, when the machine knows it (simulated).
    virtual std::optional<TrueProfile> trueProfile(std::int64_t partNumber) const {
        (void)partNumber;
        return std::nullopt;
    }
    /// Problems worth an alarm since the last call (a real CNC unreachable, a write it refused), each in words
    /// naming the device and what failed; the runtime stores them as alarms of the run (kind "machine").
    virtual std::vector<std::string> takeIncidents() { return {}; }
    /// All diameters of the part are in: a simulated station forgets it.
    virtual void partMeasured(std::int64_t partNumber) { (void)partNumber; }
    /// Fault switch: the gauge answers nothing for `seconds` of the machine's time; false when the
    /// machine has no such switch.
    virtual bool silenceGauge(double seconds) {
        (void)seconds;
        return false;
    }
    /// The operator confirms each part (the Part finished button): the part on the machine now, if any
    /// (thread-safe; none for a machine that reports its own cycle end).
    virtual std::optional<std::int64_t> partOnMachine() const { return std::nullopt; }
    /// The operator confirms the part on the machine is finished; returns its number, or none when no part
    /// is on it or the machine reports its own cycle end (thread-safe).
    virtual std::optional<std::int64_t> confirmPartFinished() { return std::nullopt; }
    /// Resume: a part machined and stored before the interruption, with the corrections it really got and
    /// when it came off the machine. A simulated machine machines it again so that its process continues
    /// exactly where it stopped (its parts depend on the corrections they received), and its time moves on
    /// to the part's finish; a real machine has nothing to do.
    virtual void replayPart(const PartCorrection& applied, double finishedS) {
        (void)applied;
        (void)finishedS;
    }
    /// Resume: a part machined before the interruption, with the corrections it really got, is back
    /// on the rack waiting to be measured (a simulated station re-creates it; on a real lathe the
    /// operator puts it there).
    virtual void restorePart(const PartCorrection& applied) { (void)applied; }
    /// The diameter the CNC output writes its programs for, when it is set up for one, mm.
    virtual std::optional<double> outputNominalDiameterMm() const { return std::nullopt; }
};

}  // namespace tt::core
