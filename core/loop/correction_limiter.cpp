#include "core/loop/correction_limiter.h"

#include <cmath>
#include <stdexcept>

namespace tt::core {

CorrectionLimiter::CorrectionLimiter(CorrectionLimits limits, std::vector<double> pointZMm)
    : m_limits(limits), m_pointZ(std::move(pointZMm)), m_last(m_pointZ.size(), 0.0) {}

void CorrectionLimiter::setLastApplied(std::vector<double> appliedMm) {
    if (appliedMm.size() != m_pointZ.size()) throw std::invalid_argument("one applied correction per point is needed");
    m_last = std::move(appliedMm);
}

LimiterOutcome CorrectionLimiter::apply(const Eigen::VectorXd& computedMm) {
    if (static_cast<std::size_t>(computedMm.size()) != m_pointZ.size())
        throw std::invalid_argument("the controller returned " + std::to_string(computedMm.size()) +
                                    " corrections for " + std::to_string(m_pointZ.size()) + " points");
    LimiterOutcome out;
    out.appliedMm.resize(m_pointZ.size());
    for (std::size_t i = 0; i < m_pointZ.size(); ++i) {
        const double asked = computedMm(static_cast<Eigen::Index>(i));
        Notice note;
        note.point = static_cast<int>(i) + 1;
        note.zMm = m_pointZ[i];
        note.value = asked;
        if (!std::isfinite(asked)) {
            out.appliedMm[i] = m_last[i];
            note.kind = NoticeKind::CorrectionHeld;
            note.reference = m_last[i];
            out.notes.push_back(note);
            continue;
        }
        const Eigen::VectorXd one = Eigen::VectorXd::Constant(1, asked);
        const Eigen::VectorXd last = Eigen::VectorXd::Constant(1, m_last[i]);
        const double v = applyCorrectionLimits(one, last, m_limits).correctionMm(0);
        if (v != asked) {
            note.kind = NoticeKind::CorrectionLimited;
            note.reference = v;
            out.notes.push_back(note);
        }
        out.appliedMm[i] = v;
    }
    m_last = out.appliedMm;
    return out;
}

}  // namespace tt::core
