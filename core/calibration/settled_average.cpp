#include "core/calibration/settled_average.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tt::core {

SettledAverage::SettledAverage(double settleS, int count, double windowS)
    : m_settleS(settleS), m_target(count), m_windowS(windowS) {
    if (!std::isfinite(settleS) || settleS < 0.0 || settleS > 60.0)
        throw std::invalid_argument("the settling time must be within 0 .. 60 s");
    if (count < 1 || count > 100000) throw std::invalid_argument("the values averaged must be within 1 .. 100000");
    if (!(windowS > 0.0)) throw std::invalid_argument("the averaging window must be longer than 0 s");
}

void SettledAverage::start() {
    m_phase = Phase::HoldStill;
    m_started = false;
    m_sum = 0.0;
    m_count = 0;
}

void SettledAverage::stop() {
    m_phase = Phase::Idle;
    m_started = false;
}

void SettledAverage::observe(double timeS) {
    if (!running() || !std::isfinite(timeS)) return;
    if (!m_started) {
        m_started = true;
        m_startS = timeS;
    }
    m_lastS = std::max(m_lastS, timeS);
    if (m_phase == Phase::HoldStill && timeS >= m_startS + m_settleS) m_phase = Phase::Averaging;
    if (m_phase == Phase::Averaging && timeS >= m_startS + m_settleS + m_windowS) m_phase = Phase::Done;
}

void SettledAverage::add(double timeS, double value) {
    observe(timeS);
    if (m_phase != Phase::Averaging || !std::isfinite(value)) return;
    m_sum += value;
    if (++m_count >= m_target) m_phase = Phase::Done;
}

HoldPhase SettledAverage::holdPhase() const {
    switch (m_phase) {
        case Phase::HoldStill:
            return HoldPhase::HoldStill;
        case Phase::Averaging:
            return HoldPhase::Averaging;
        case Phase::Idle:
        case Phase::Done:
            break;
    }
    return HoldPhase::Idle;
}

double SettledAverage::progress() const {
    if (m_phase == Phase::Done) return 1.0;
    if (!running() || !m_started) return 0.0;
    const double settled = m_settleS > 0.0 ? std::clamp((m_lastS - m_startS) / m_settleS, 0.0, 1.0) : 1.0;
    double averaged = static_cast<double>(m_count) / m_target;
    if (std::isfinite(m_windowS))
        averaged = std::max(averaged, std::clamp((m_lastS - m_startS - m_settleS) / m_windowS, 0.0, 1.0));
    // The settling counts for a fifth of the step.
    return 0.2 * settled + 0.8 * std::min(averaged, 1.0);
}

}  // namespace tt::core
