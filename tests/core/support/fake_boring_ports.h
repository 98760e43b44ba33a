#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/ports/correction_output.h"
#include "core/ports/deflection_probe.h"
#include "core/ports/drive_current.h"

namespace tt::core::test {

/// A source port (probe mandrel, drive read-out) whose samples and health the test sets.
template <class Port, class Sample>
struct FakeSource final : Port {
    DeviceHealth status{DeviceState::Ready, {}};
    std::deque<Sample> queue;
    DeviceHealth health() const override { return status; }
    std::optional<Sample> takeSample() override {
        if (queue.empty()) return std::nullopt;
        const Sample s = queue.front();
        queue.pop_front();
        return s;
    }
};

using FakeProbe = FakeSource<DeflectionProbe, ProbeSample>;
using FakeDrive = FakeSource<DriveCurrentReadout, DriveSample>;

/// A CNC output that keeps the offsets it took, or refuses them.
struct FakeOutput final : CorrectionOutput {
    DeviceHealth status{DeviceState::Ready, {}};
    bool refuse = false;
    std::vector<double> sent;
    DeviceHealth health() const override { return status; }
    OutputResult sendPartCorrection(const PartCorrection&) override { return {true, {}}; }
    OutputResult sendDynamicOffset(double mm) override {
        if (refuse) return {false, "register write not acknowledged"};
        sent.push_back(mm);
        return {true, {}};
    }
};

/// A probe sample of `deflectionMm` in plane 1 (X) at `timeS`; raw codes only when not `linearised`.
inline ProbeSample probeSample(double timeS, double deflectionMm, bool linearised = true) {
    ProbeSample s;
    s.timeS = timeS;
    s.deflectionMm = {deflectionMm, 0.0};
    s.adcCode = {2048, 2048};
    s.linearised = linearised;
    return s;
}

}  // namespace tt::core::test
