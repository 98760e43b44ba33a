#pragma once

#include <limits>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/common/notice.h"

namespace tt::core {

/// Limits on the radial cutter corrections a run-to-run controller may command, per control point
/// (what the CNC's tool-offset table and the process allow).
struct CorrectionLimits {
    double maxAbsMm = std::numeric_limits<double>::infinity();   ///< |u| <= maxAbsMm (radial, mm)
    double maxStepMm = std::numeric_limits<double>::infinity();  ///< |u(p) - u(p-1)| <= maxStepMm per part

    /// Throws std::invalid_argument unless both limits are > 0 (infinity = no limit).
    void validate() const;
};

/// The limited correction and which points were limited.
struct LimitedCorrection {
    Eigen::VectorXd correctionMm;
    Eigen::Array<bool, Eigen::Dynamic, 1> limited;
};

/// Applies the step limit around `previousMm`, then the absolute range, point by point.
LimitedCorrection applyCorrectionLimits(const Eigen::VectorXd& candidateMm, const Eigen::VectorXd& previousMm,
                                        const CorrectionLimits& limits);

/// Why a measured value cannot be used at all: NotMeasured for NaN, NotFinite for +-Inf; nothing for a
/// finite value.
std::optional<Notice> nonFiniteReason(double valueMm);

}  // namespace tt::core
