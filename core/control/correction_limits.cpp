#include "core/control/correction_limits.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tt::core {

void CorrectionLimits::validate() const {
    if (std::isnan(maxAbsMm) || maxAbsMm <= 0.0)
        throw std::invalid_argument("correction limits: the absolute range must be > 0 mm");
    if (std::isnan(maxStepMm) || maxStepMm <= 0.0)
        throw std::invalid_argument("correction limits: the change per part must be > 0 mm");
}

LimitedCorrection applyCorrectionLimits(const Eigen::VectorXd& candidateMm, const Eigen::VectorXd& previousMm,
                                        const CorrectionLimits& limits) {
    LimitedCorrection out{candidateMm, Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(candidateMm.size(), false)};
    for (Eigen::Index i = 0; i < candidateMm.size(); ++i) {
        double u = candidateMm(i);
        u = std::clamp(u, previousMm(i) - limits.maxStepMm, previousMm(i) + limits.maxStepMm);
        u = std::clamp(u, -limits.maxAbsMm, limits.maxAbsMm);
        out.limited(i) = u != candidateMm(i);
        out.correctionMm(i) = u;
    }
    return out;
}

std::optional<Notice> nonFiniteReason(double valueMm) {
    if (std::isnan(valueMm)) return Notice{NoticeKind::NotMeasured};
    if (std::isinf(valueMm)) return Notice{NoticeKind::NotFinite};
    return std::nullopt;
}

}  // namespace tt::core
