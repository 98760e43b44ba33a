#pragma once

#include <optional>
#include <vector>

#include "core/run/boring_run.h"

namespace tt::ui {

/// What a run has done so far, for the operator's numbers and for tests.
struct BoringRunStats {
    int cycles = 0;
    int holdingCycles = 0;
    int sentCycles = 0;                        ///< cycles whose offset the CNC took
    double offsetMm = 0.0;                     ///< the offset the CNC holds now, mm
    double largestOffsetMm = 0.0;              ///< largest |offset| sent, mm
    double largestStepMm = 0.0;                ///< largest change of the offset in one cycle, mm
    std::optional<double> deflectionMm;        ///< the source's latest deflection, mm
    std::optional<double> forceN;              ///< the source's latest force, N
    std::optional<double> boreErrorMaxMm;      ///< simulated pass: max |diameter error| gauged so far
    std::optional<double> uncompensatedMaxMm;  ///< the same on the twin pass without compensation
    double zMm = 0.0;                          ///< simulated pass: where the tool is
};

/// The cycles of one run as the Boring tab plots and counts them: the deflection measured, the
/// offset applied and (a simulated pass) the real deflection over the last 30 s; the bore error
/// with and without compensation along the bore (a point every 0.1 mm), gauged from `margin` inside
/// each end of the bore as `trueturn boring` does.
class BoringTrace {
public:
    /// Forgets everything; a new run starting from the offset `heldOffsetMm` the CNC holds, on a
    /// bore of `boreLengthMm` gauged from `gaugeMarginMm` inside each end.
    void reset(double heldOffsetMm, double boreLengthMm, double gaugeMarginMm);
    /// Counts and keeps one PLC cycle; `holding` as the operator is told.
    void record(const core::BoringRunCycle& cycle, bool holding);

    const BoringRunStats& stats() const { return m_stats; }
    /// Plot series (NaN: no value at that cycle).
    const std::vector<double>& timeS() const { return m_timeS; }
    const std::vector<double>& measuredMm() const { return m_measuredMm; }
    const std::vector<double>& offsetMm() const { return m_offsetMm; }
    const std::vector<double>& trueMm() const { return m_trueMm; }
    double startS() const { return m_startS; }
    const std::vector<double>& boreZMm() const { return m_zMm; }
    const std::vector<double>& boreErrorMm() const { return m_errorMm; }
    const std::vector<double>& boreTwinErrorMm() const { return m_twinErrorMm; }
    /// Whether any cycle told the real deflection (a simulated pass).
    bool hasTruth() const { return m_hasTruth; }
    /// Sets the offset the CNC holds (zeroed while stopped), mm.
    void setOffsetMm(double offsetMm) { m_stats.offsetMm = offsetMm; }

private:
    void recordTruth(const core::BoringPassTruth& truth);

    BoringRunStats m_stats;
    double m_boreLengthMm = 0.0;
    double m_gaugeMarginMm = 0.0;
    std::vector<double> m_timeS, m_measuredMm, m_offsetMm, m_trueMm;
    double m_startS = 0.0;
    std::vector<double> m_zMm, m_errorMm, m_twinErrorMm;
    double m_lastBoreZ = -1e9;
    bool m_hasTruth = false;
};

}  // namespace tt::ui
