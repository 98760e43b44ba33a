#include "ui/boring/boring_trace.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace tt::ui {

namespace {

constexpr double kWindowS = 30.0;    ///< the offset chart shows the last 30 s
constexpr double kBoreStepMm = 0.1;  ///< the bore chart keeps a point every 0.1 mm of the bore

double nan() {
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

void BoringTrace::reset(double heldOffsetMm, double boreLengthMm, double gaugeMarginMm) {
    m_stats = BoringRunStats{};
    m_stats.offsetMm = heldOffsetMm;
    m_boreLengthMm = boreLengthMm;
    m_gaugeMarginMm = gaugeMarginMm;
    for (auto* v : {&m_timeS, &m_measuredMm, &m_offsetMm, &m_trueMm, &m_zMm, &m_errorMm, &m_twinErrorMm})
        v->clear();
    m_startS = 0.0;
    m_lastBoreZ = -1e9;
    m_hasTruth = false;
}

void BoringTrace::record(const core::BoringRunCycle& cycle, bool holding) {
    if (cycle.compensation) {
        const core::CompensationCycle& c = *cycle.compensation;
        const double previous = m_stats.offsetMm;
        ++m_stats.cycles;
        if (holding) ++m_stats.holdingCycles;
        if (c.sent) ++m_stats.sentCycles;
        m_stats.offsetMm = c.step.offsetMm;
        m_stats.largestOffsetMm = std::max(m_stats.largestOffsetMm, std::abs(c.step.offsetMm));
        m_stats.largestStepMm = std::max(m_stats.largestStepMm, std::abs(c.step.offsetMm - previous));
        m_stats.deflectionMm = c.reading.deflectionMm;
        m_stats.forceN = c.reading.forceN;

        if (m_timeS.size() > 1 && m_timeS.back() - m_timeS.front() > kWindowS) {
            const auto drop = static_cast<std::ptrdiff_t>(m_timeS.size() / 10 + 1);
            for (auto* v : {&m_timeS, &m_measuredMm, &m_offsetMm, &m_trueMm})
                v->erase(v->begin(),
                         v->begin() + std::min<std::ptrdiff_t>(drop, static_cast<std::ptrdiff_t>(v->size())));
        }
        if (m_stats.cycles == 1) m_startS = c.timeS;
        m_timeS.push_back(c.timeS);
        m_measuredMm.push_back(c.reading.deflectionMm.value_or(nan()));
        m_offsetMm.push_back(c.step.offsetMm);
        m_trueMm.push_back(cycle.truth ? cycle.truth->deflectionMm : nan());
    }
    if (cycle.truth) recordTruth(*cycle.truth);
}

void BoringTrace::recordTruth(const core::BoringPassTruth& t) {
    m_hasTruth = true;
    m_stats.zMm = t.zMm;
    if (!t.cutting) return;
    const double twin = t.uncompensatedErrorMm.value_or(nan());
    if (t.zMm - m_lastBoreZ >= kBoreStepMm) {
        m_lastBoreZ = t.zMm;
        m_zMm.push_back(t.zMm);
        m_errorMm.push_back(t.diameterErrorMm);
        m_twinErrorMm.push_back(twin);
    }
    // Gauged as `trueturn boring` does: from the margin inside each end of the bore.
    if (t.zMm >= m_gaugeMarginMm && t.zMm <= m_boreLengthMm - m_gaugeMarginMm) {
        m_stats.boreErrorMaxMm = std::max(m_stats.boreErrorMaxMm.value_or(0.0), std::abs(t.diameterErrorMm));
        if (t.uncompensatedErrorMm)
            m_stats.uncompensatedMaxMm =
                std::max(m_stats.uncompensatedMaxMm.value_or(0.0), std::abs(*t.uncompensatedErrorMm));
    }
}

}  // namespace tt::ui
