#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/control/run_to_run_plant.h"
#include "core/sim/statistics/normal_stream.h"

namespace tt::core {

/// The random part of one part: the diameter deviation it would have without correction and the
/// gauge noise of its measurement, per control point (mm).
struct PartDraw {
    std::int64_t partNumber = 0;
    Eigen::VectorXd disturbanceMm;
    Eigen::VectorXd gaugeNoiseMm;
};

/// A machined and gauged part.
struct MachinedPart {
    std::int64_t partNumber = 0;
    Eigen::VectorXd trueDeviationMm;      ///< k_i u_i + d_i: what the part really is
    Eigen::VectorXd measuredDeviationMm;  ///< true deviation + gauge noise: what the gauge reports
};

/// Saved state of a StochasticPlant (disturbance states, last part, random generator).
struct StochasticPlantState {
    std::vector<double> values;
    std::string random;
};

/// The statistical run-to-run plant of paper 000, part by part: each control point's deviation is
/// `k_i u_i(p) + d_i(p)` where d_i is its disturbance model (shaping filters, AR(1), random walk, white)
/// and the gauge adds white noise. The disturbance does not depend on the corrections, so one draw
/// serves the open and the closed loop alike. Stationary components start from their stationary
/// distribution (no transient); a random walk starts at 0. Seeded, reproducible, resumable.
class StochasticPlant {
public:
    /// The plant's disturbance and gauge noise, drawn from the normal stream of `seed`.
    StochasticPlant(const RunToRunPlant& plant, std::uint64_t seed);

    /// Number of control points N.
    int pointCount() const { return static_cast<int>(m_gain.size()); }

    /// Draws part `partNumber` (must be the previous part + 1 after the first call). The returned
    /// reference stays valid until the next draw.
    const PartDraw& draw(std::int64_t partNumber);
    /// True deviation of a drawn part machined with radial corrections `correctionMm`: d + k .* u.
    Eigen::VectorXd deviationMm(const PartDraw& part, const Eigen::VectorXd& correctionMm) const;
    /// Draws, machines with `correctionMm` and gauges the next part.
    MachinedPart machine(std::int64_t partNumber, const Eigen::VectorXd& correctionMm);

    /// The complete state (resuming continues the same realisation).
    StochasticPlantState saveState() const;
    /// Restores a state saved by a plant of the same configuration; throws std::invalid_argument otherwise.
    void restoreState(const StochasticPlantState& state);

private:
    struct Component {
        int point = 0;
        std::size_t offset = 0;  // into m_state
        std::size_t order = 0;
        std::vector<double> A;  // row-major order x order
        std::vector<double> G;
        std::vector<double> C;
        double inputSigma = 0.0;
    };

    std::vector<Component> m_components;
    Eigen::VectorXd m_gain;
    Eigen::VectorXd m_gaugeSigma;
    std::vector<double> m_state;
    std::vector<double> m_scratch;
    NormalStream m_random;
    bool m_started = false;
    std::int64_t m_lastPart = 0;
    PartDraw m_draw;
};

}  // namespace tt::core
