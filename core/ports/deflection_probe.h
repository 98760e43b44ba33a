#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "core/ports/device_health.h"

namespace tt::core {

/// One sample of the probe mandrel (paper 001, way 2): the inductive sensor inside the
/// boring bar, two bending planes.
struct ProbeSample {
    double timeS = 0.0;                     ///< arrival time (Clock), s
    std::array<std::int32_t, 2> adcCode{};  ///< raw ADC code per bending plane
    std::array<double, 2> deflectionMm{};   ///< linearised deflection per plane, mm
    bool linearised = false;                ///< false: the mandrel has no valid table, use adcCode
};

/// The deflection probe inside the boring bar.
class DeflectionProbe {
public:
    virtual ~DeflectionProbe() = default;
    virtual DeviceHealth health() const = 0;
    /// The oldest sample not yet taken, if any (never blocks).
    virtual std::optional<ProbeSample> takeSample() = 0;
};

}  // namespace tt::core
