#pragma once

#include <memory>

#include "core/control/in_process_compensation.h"
#include "core/ports/correction_output.h"
#include "core/ports/deflection_probe.h"
#include "core/ports/drive_current.h"
#include "ui/boring/boring_rig.h"

namespace tt::ui {

/// The deflection source and the in-process compensator of one run, over the engine's ports
/// (issue 6 item 6): way 1 (DitherForceEstimator on the drive read-out, k_p and k_st from the
/// tool) or way 2 (the probe mandrel's linearised deflection in the chosen plane).
class CompensationLoop {
public:
    /// `readout` is needed for the current source, `probe` for the probe source; the ports and the
    /// output must outlive the loop. `heldOffsetMm` is what the CNC holds already (the run
    /// continues from it). Throws std::invalid_argument with the reason in the operator's terms:
    /// missing port, k_st or (current) k_p not above 0, limits or PLC cycle out of range.
    CompensationLoop(const BoringRunSettings& settings, core::DriveCurrentReadout* readout,
                     core::DeflectionProbe* probe, core::CorrectionOutput& output, double heldOffsetMm = 0.0);

    /// One PLC cycle at Clock time `nowS`.
    core::CompensationCycle cycle(double nowS);
    /// What the part program cuts (current source; the probe does not care).
    void setSegment(core::SegmentKind kind);
    /// The offset last written to the CNC (or held), mm.
    double offsetMm() const { return m_compensator->offsetMm(); }
    double plcCycleS() const { return m_compensator->plcCycleS(); }

private:
    std::unique_ptr<core::DeflectionSource> m_source;
    core::CurrentDeflectionSource* m_current = nullptr;
    std::unique_ptr<core::InProcessCompensator> m_compensator;
};

}  // namespace tt::ui
