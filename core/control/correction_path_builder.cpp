#include "core/control/correction_path_builder.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

constexpr double kMaxSamples = 1'000'000.0;

std::string mm(double v) {
    return formatSignificant(v, 6) + " mm";
}

void checkRequest(const CorrectionPathRequest& r) {
    if (!std::isfinite(r.partLengthMm) || r.partLengthMm <= 0.0)
        throw std::invalid_argument("the part length must be a positive number of millimetres (got " +
                                    mm(r.partLengthMm) + ")");
    if (!std::isfinite(r.stepMm) || r.stepMm <= 0.0)
        throw std::invalid_argument("the path sampling step must be a positive number of millimetres (got " +
                                    mm(r.stepMm) + ")");
    if (r.partLengthMm / r.stepMm > kMaxSamples)
        throw std::invalid_argument("the path sampling step " + mm(r.stepMm) + " is too fine for a " +
                                    mm(r.partLengthMm) + " part (more than 1000000 samples)");
    if (r.pointZMm.size() != r.pointCorrectionMm.size())
        throw std::invalid_argument("the correction path needs one correction per control point (" +
                                    std::to_string(r.pointZMm.size()) + " points, " +
                                    std::to_string(r.pointCorrectionMm.size()) + " corrections)");
    for (std::size_t i = 0; i < r.pointZMm.size(); ++i) {
        const double z = r.pointZMm[i];
        if (!std::isfinite(z) || z < 0.0 || z > r.partLengthMm)
            throw std::invalid_argument("control point " + std::to_string(i + 1) + " at " + mm(z) +
                                        " lies outside the part (0 .. " + mm(r.partLengthMm) + ")");
        if (!std::isfinite(r.pointCorrectionMm[i]))
            throw std::invalid_argument("the correction at control point " + std::to_string(i + 1) +
                                        " is not a finite number");
    }
}

}  // namespace

CorrectionProfile::CorrectionProfile(const CorrectionPathRequest& request) {
    checkRequest(request);
    if (!request.pointZMm.empty())
        m_interpolant = PiecewiseCubic::make(request.method, request.pointZMm, request.pointCorrectionMm);
    if (request.diameterErrorModel) m_feedForward = request.diameterErrorModel->scaledBy(-0.5);
}

double CorrectionProfile::feedForwardMm(double zMm) const {
    return m_feedForward ? m_feedForward->value(zMm) : 0.0;
}

double CorrectionProfile::pointCorrectionPartMm(double zMm) const {
    return m_interpolant ? m_interpolant->value(zMm) : 0.0;
}

CorrectionPath buildCorrectionPath(const CorrectionPathRequest& request) {
    const CorrectionProfile profile(request);
    const double length = request.partLengthMm;
    const double step = request.stepMm;
    // Whole steps that stay clearly inside the part; the end is appended exactly once.
    auto steps = static_cast<std::size_t>(std::floor(length / step));
    if (static_cast<double>(steps) * step > length * (1.0 - 1e-12)) --steps;
    CorrectionPath path;
    path.zMm.reserve(steps + 2);
    path.xCorrectionMm.reserve(steps + 2);
    for (std::size_t k = 0; k <= steps; ++k) {
        const double z = static_cast<double>(k) * step;
        path.zMm.push_back(z);
        path.xCorrectionMm.push_back(profile.correctionMm(z));
    }
    path.zMm.push_back(length);
    path.xCorrectionMm.push_back(profile.correctionMm(length));
    return path;
}

}  // namespace tt::core
