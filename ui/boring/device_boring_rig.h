#pragma once

#include <memory>

#include "core/ports/clock.h"
#include "ui/boring/boring_rig.h"
#include "ui/boring/compensation_loop.h"

namespace tt::devices {
class Device;
}

namespace tt::ui {

/// The compensation on configured devices (devices plugin API): the drive-current read-out or the
/// probe mandrel as the source, a CNC output that takes the dynamic X offset, the devices' clock.
/// Runs in the thread the devices live in (the GUI thread). The devices must outlive the rig.
class DeviceBoringRig final : public BoringRig {
public:
    /// Throws std::invalid_argument when the source device lacks the port the settings need, the
    /// output device has no correction output, or the settings are refused (CompensationLoop).
    DeviceBoringRig(devices::Device& source, devices::Device& output, const core::Clock& clock,
                    const BoringRunSettings& settings, double heldOffsetMm);

    BoringCycleView cycle() override;
    double plcCycleS() const override { return m_loop->plcCycleS(); }
    void setSegment(core::SegmentKind kind) override { m_loop->setSegment(kind); }
    double offsetMm() const override { return m_loop->offsetMm(); }
    core::OutputResult zeroOffset() override;

private:
    core::CorrectionOutput& m_output;
    const core::Clock& m_clock;
    std::unique_ptr<CompensationLoop> m_loop;
};

}  // namespace tt::ui
