#include "core/sim/rigs/known_load_rig.h"

#include <cmath>
#include <stdexcept>

namespace tt::core {

namespace {
constexpr double kStepS = 1.0e-4;
}

KnownLoadRig::KnownLoadRig(const CrossFeedDriveConfig& drive, const DitherConfig& dither, double plcCycleS,
                           unsigned long long seed)
    : m_drive(drive, seed), m_dither(dither), m_cycleS(plcCycleS), m_nextSampleS(plcCycleS) {
    if (!std::isfinite(plcCycleS) || plcCycleS < 0.01 || plcCycleS > 0.1)
        throw std::invalid_argument("the PLC cycle must be within 10 .. 100 ms");
}

void KnownLoadRig::setLoadN(double loadN) {
    if (!std::isfinite(loadN)) throw std::invalid_argument("the load must be a number");
    m_loadN = loadN;
}

void KnownLoadRig::advance(double seconds) {
    const double end = m_timeS + seconds;
    while (m_timeS + kStepS <= end + 1e-12) {
        m_timeS += kStepS;
        const DitherState d = m_dither.at(m_timeS);
        m_drive.step(kStepS, {d.positionMm, d.velocityMmPerS, d.accelerationMmPerS2}, -m_loadN);
        if (m_timeS >= m_nextSampleS - 1e-12) {
            m_samples.push_back(m_drive.sample(m_timeS));
            m_nextSampleS += m_cycleS;
            if (m_samples.size() > 10000) m_samples.pop_front();
        }
    }
}

std::optional<DriveSample> KnownLoadRig::takeSample() {
    if (m_samples.empty()) return std::nullopt;
    DriveSample s = m_samples.front();
    m_samples.pop_front();
    return s;
}

}  // namespace tt::core
