#include "core/sim/feed_drives/corner_cost.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

void requireRange(double v, double lo, double hi, const char* what) {
    if (!std::isfinite(v) || v < lo || v > hi)
        throw std::invalid_argument(std::string(what) + " " + formatSignificant(v, 6) + " is outside " +
                                    formatSignificant(lo, 6) + " .. " + formatSignificant(hi, 6));
}

}  // namespace

void validateCornerCost(const CornerCostSettings& s) {
    requireRange(s.beforeS, 0.001, 1.0, "control interval before the corner t1 (s)");
    requireRange(s.afterS, 0.001, 1.0, "control interval after the corner t2 (s)");
    requireRange(s.maxWeight, 0.0, 100.0, "weight of the largest error k1");
    requireRange(s.meanWeight, 0.0, 100.0, "weight of the mean error k2");
    if (s.maxWeight + s.meanWeight <= 0.0) throw std::invalid_argument("weights k1 and k2 are both zero");
}

void CornerCostAccumulator::add(double zMm, double errorMm) {
    if (zMm < m_zStartMm || zMm > m_zEndMm) return;
    m_max = std::max(m_max, errorMm);
    m_sum += errorMm;
    ++m_count;
}

CornerCost CornerCostAccumulator::result() const {
    CornerCost c;
    if (m_count == 0) return c;
    c.maxErrorMm = m_max;
    c.meanErrorMm = m_sum / static_cast<double>(m_count);
    c.cost = m_settings.maxWeight * c.maxErrorMm + m_settings.meanWeight * c.meanErrorMm;
    return c;
}

}  // namespace tt::core
