#include "core/sim/shaft/plant_mismatch.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/text_format.h"
#include "core/control/run_to_run_plant.h"

namespace tt::core {

void PlantMismatch::validate(int modelDelay, std::size_t pointCount) const {
    if (!std::isfinite(gainFactor) || gainFactor < kMinPlantGainFactor || gainFactor > kMaxPlantGainFactor)
        throw std::invalid_argument("the plant gain factor must be in " + formatSignificant(kMinPlantGainFactor, 3) +
                                    " .. " + formatSignificant(kMaxPlantGainFactor, 3) + ", got " +
                                    formatSignificant(gainFactor, 4));
    if (delayParts && (*delayParts < modelDelay || *delayParts > kMaxDelay))
        throw std::invalid_argument("the plant delay must be " + std::to_string(modelDelay) + " .. " +
                                    std::to_string(kMaxDelay) + " parts (not shorter than the model's z = " +
                                    std::to_string(modelDelay) + "), got " + std::to_string(*delayParts));
    if (!step) return;
    if (step->atPart < 1) throw std::invalid_argument("the step must come at part 1 or later");
    if (!std::isfinite(step->sizeMm) || std::abs(step->sizeMm) > kMaxPlantStepMm || step->sizeMm == 0.0)
        throw std::invalid_argument("the step size must be a non-zero number of at most " +
                                    formatSignificant(kMaxPlantStepMm, 3) + " mm, got " +
                                    formatSignificant(step->sizeMm, 4));
    if (step->point && (*step->point < 0 || static_cast<std::size_t>(*step->point) >= pointCount))
        throw std::invalid_argument("the step's control point must be 1 .. " + std::to_string(pointCount) + ", got " +
                                    std::to_string(*step->point + 1));
}

MismatchedProcess::MismatchedProcess(std::unique_ptr<LathePartProcess> inner, int lagParts,
                                     std::optional<PlantStep> step, std::vector<double> pointZMm)
    : m_inner(std::move(inner)), m_lag(lagParts), m_step(std::move(step)), m_pointZ(std::move(pointZMm)) {
    if (!m_inner) throw std::invalid_argument("the mismatched plant needs a process");
    if (m_lag < 0) throw std::invalid_argument("the plant cannot act before the correction is sent");
    if (m_step && m_step->point && (*m_step->point < 0 || static_cast<std::size_t>(*m_step->point) >= m_pointZ.size()))
        throw std::invalid_argument("the step's control point does not exist");
}

TurnedPart MismatchedProcess::machine(const PartCorrection& correction) {
    m_sent.push_back(correction);
    while (m_sent.size() > static_cast<std::size_t>(m_lag) + 1)
        m_sent.pop_front();
    PartCorrection acting = m_sent.front();  // sent for part n - lag (or the oldest sent so far)
    acting.partNumber = correction.partNumber;
    TurnedPart part = m_inner->machine(acting);
    if (!m_step || correction.partNumber < m_step->atPart) return part;
    for (std::size_t i = 0; i < part.zMm.size(); ++i) {
        const bool here =
            !m_step->point || std::abs(part.zMm[i] - m_pointZ[static_cast<std::size_t>(*m_step->point)]) < 1e-9;
        if (here) part.diameterMm[i] += m_step->sizeMm;
    }
    return part;
}

}  // namespace tt::core
