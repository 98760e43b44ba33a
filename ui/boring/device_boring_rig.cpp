#include "ui/boring/device_boring_rig.h"

#include <stdexcept>

#include "devices/api/device.h"

namespace tt::ui {

namespace {

core::CorrectionOutput& outputOf(devices::Device& device) {
    if (!device.correctionOutput()) throw std::invalid_argument("the chosen CNC output takes no offsets");
    return *device.correctionOutput();
}

}  // namespace

DeviceBoringRig::DeviceBoringRig(devices::Device& source, devices::Device& output, const core::Clock& clock,
                                 const BoringRunSettings& settings, double heldOffsetMm)
    : m_output(outputOf(output)), m_clock(clock) {
    m_loop = std::make_unique<CompensationLoop>(settings, source.driveCurrentReadout(), source.deflectionProbe(),
                                                m_output, heldOffsetMm);
}

BoringCycleView DeviceBoringRig::cycle() {
    return {m_loop->cycle(m_clock.nowS()), std::nullopt};
}

core::OutputResult DeviceBoringRig::zeroOffset() {
    return m_output.sendDynamicOffset(0.0);
}

}  // namespace tt::ui
