#pragma once

#include <memory>
#include <optional>
#include <stdexcept>

#include "core/control/in_process_compensation.h"
#include "core/ports/boring_station.h"
#include "core/sim/boring/boring_machine.h"

namespace tt::core {

/// What the operator (or a preset) chose for one in-process compensation run (paper 001).
struct BoringRunChoices {
    BoringMethod method = BoringMethod::Current;
    int plane = 0;                     ///< probe: the mandrel's bending plane that lies along X (0 or 1)
    double stiffnessNPerMm = 0.0;      ///< k_st of the tool (tool table), N/mm
    double currentToForceNPerA = 0.0;  ///< k_p of the cross feed (k_p calibration), N/A; current only
    CompensatorLimits limits;          ///< range and rate of the dynamic X offset
    double plcCycleS = 0.02;           ///< the PLC cycle the compensation runs at, 0.01 .. 0.1 s
    DitherEstimatorConfig estimator;   ///< thresholds; k_p and k_st are taken from the fields above
    double heldOffsetMm = 0.0;         ///< the offset the CNC already holds, mm: the run continues from it
};

/// The choices `scenario` makes for `method` (what `trueturn boring` runs): k_st computed from
/// the scenario's tool (tool table), k_p of its tool, its limits, PLC cycle and estimator
/// thresholds, plane 0 (X), nothing held.
BoringRunChoices boringChoices(const BoringScenario& scenario, BoringMethod method);

/// Why a run cannot be built, as a kind; the refusal carries the value and the limits it broke.
enum class BoringRunRefusal {
    NoStiffness,             ///< k_st is not above 0 (value: k_st)
    NoCurrentGain,           ///< the current method without k_p above 0 (value: k_p)
    NoDriveReadout,          ///< the current method on a station without a drive read-out
    NoProbe,                 ///< the probe method on a station without a probe mandrel
    BadPlane,                ///< the probe plane is not 0 or 1 (value: plane)
    OffsetLimitOutOfRange,   ///< the offset range limit, mm, outside min .. max
    RateLimitOutOfRange,     ///< the offset rate limit, mm/s, outside min .. max
    PlcCycleOutOfRange,      ///< the PLC cycle, s, outside min .. max
    PlcCycleNotTheStations,  ///< a simulated pass runs at another PLC cycle (value: chosen, min = max: the pass's)
    EstimatorSettings,       ///< the dither estimator refuses its thresholds
    HeldOffsetBeyondLimit,   ///< the CNC holds more than the range limit (value: held, max: limit)
};

/// A run refused with its kind and data; what() is a stable English sentence for the command line.
class BoringRunRefused : public std::invalid_argument {
public:
    BoringRunRefused(BoringRunRefusal kind, double value = 0.0, double min = 0.0, double max = 0.0);
    BoringRunRefusal kind() const { return m_kind; }
    double value() const { return m_value; }
    double min() const { return m_min; }
    double max() const { return m_max; }

private:
    BoringRunRefusal m_kind;
    double m_value;
    double m_min;
    double m_max;
};

/// One PLC cycle of a run.
struct BoringRunCycle {
    std::optional<CompensationCycle> compensation;  ///< what the compensation did; nullopt for the method None
    std::optional<BoringPassTruth> truth;           ///< the truth of a simulated pass; nullopt on a machine
};

/// A ready in-process compensation run on a boring station: the deflection source of the chosen
/// method (DitherForceEstimator on the drive read-out, or the probe mandrel's plane) and the
/// InProcessCompensator writing the limited offset to the station's CNC output every PLC cycle.
/// Used from the one thread that runs the station.
class BoringRun {
public:
    BoringRun(const BoringRunChoices& choices, BoringStation& station);
    ~BoringRun();
    BoringRun(const BoringRun&) = delete;
    BoringRun& operator=(const BoringRun&) = delete;

    /// One PLC cycle: a simulated station moves on by a cycle, then the compensation reads the
    /// source at the station's time, limits the offset and writes it. When the output refused the
    /// offset and answers later (a relay), the run continues from what the CNC confirmed.
    BoringRunCycle cycle();
    /// What the part program cuts (the current method refuses tapers and contours).
    void setSegment(SegmentKind kind);
    /// The offset last written to the CNC (or held), mm.
    double offsetMm() const;
    double plcCycleS() const { return m_choices.plcCycleS; }
    const BoringRunChoices& choices() const { return m_choices; }
    BoringStation& station() { return m_station; }
    /// A simulated pass is over.
    bool finished() const { return m_station.finished(); }

private:
    BoringRunChoices m_choices;
    BoringStation& m_station;
    std::unique_ptr<DeflectionSource> m_source;
    CurrentDeflectionSource* m_current = nullptr;
    std::unique_ptr<InProcessCompensator> m_compensator;
};

/// The one run builder (GUI, command line and tests): checks the choices against the station and
/// makes the run, continuing from `choices.heldOffsetMm`. The station must outlive the run.
/// Throws BoringRunRefused with the kind and data of the first problem.
std::unique_ptr<BoringRun> buildBoringRun(const BoringRunChoices& choices, BoringStation& station);

}  // namespace tt::core
