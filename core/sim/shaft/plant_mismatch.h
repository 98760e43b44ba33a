#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "core/sim/shaft/lathe_part_process.h"

namespace tt::core {

/// A step in the simulated plant (a tool change, a new blank batch): from part `atPart` on, every part
/// is `sizeMm` larger in diameter at one control point or along the whole part.
struct PlantStep {
    std::int64_t atPart = 1;   ///< first part with the step (>= 1)
    double sizeMm = 0.0;       ///< diameter change, mm (|size| <= 1 mm)
    std::optional<int> point;  ///< 0-based control point; none: the whole part
};

/// How the simulated plant differs from the model the controller was designed on (`trueturn simulate
/// --plant-gain --plant-delay --step-at --step-mm --step-point`, the presets' "plant_mismatch" section).
/// The controller never sees it: only the simulated lathe changes.
struct PlantMismatch {
    double gainFactor = 1.0;        ///< true k_i = gainFactor x the model's k_i (0.1 .. 10)
    std::optional<int> delayParts;  ///< the plant's delay z (>= the model's, <= kMaxDelay); none: the model's
    std::optional<PlantStep> step;  ///< a step disturbance; none: no step

    /// Any difference from the model at all.
    bool any() const { return gainFactor != 1.0 || delayParts || step; }
    /// Throws std::invalid_argument naming the value and its limit (the model's delay and point count).
    void validate(int modelDelay, std::size_t pointCount) const;
};

/// Largest and smallest plant gain factor, largest step, mm.
inline constexpr double kMinPlantGainFactor = 0.1;
inline constexpr double kMaxPlantGainFactor = 10.0;
inline constexpr double kMaxPlantStepMm = 1.0;

/// A part process whose corrections act later than the model says and that carries a step: part n is
/// machined with the corrections sent for part n - lag (the oldest sent before that), and from the
/// step's part on its diameter is shifted by the step at the step's control point (or everywhere).
class MismatchedProcess final : public LathePartProcess {
public:
    /// `lagParts` >= 0 extra parts of delay; `pointZMm` the control points (the step's point is one).
    /// Throws std::invalid_argument for a null process, a negative lag or a bad step point.
    MismatchedProcess(std::unique_ptr<LathePartProcess> inner, int lagParts, std::optional<PlantStep> step,
                      std::vector<double> pointZMm);

    TurnedPart machine(const PartCorrection& correction) override;
    double nominalDiameterMm() const override { return m_inner->nominalDiameterMm(); }
    double partLengthMm() const override { return m_inner->partLengthMm(); }
    /// The process without the mismatch.
    LathePartProcess& inner() { return *m_inner; }

private:
    std::unique_ptr<LathePartProcess> m_inner;
    int m_lag = 0;
    std::optional<PlantStep> m_step;
    std::vector<double> m_pointZ;
    std::deque<PartCorrection> m_sent;  ///< the last lag + 1 corrections sent, oldest first
};

}  // namespace tt::core
