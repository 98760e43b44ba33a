#include "core/control/dither_current_difference.h"

namespace tt::core {

namespace {

StrokeProblem problemOf(DitherRefusal refusal) {
    switch (refusal) {
        case DitherRefusal::None:
            return StrokeProblem::None;
        case DitherRefusal::NotCylindrical:
            return StrokeProblem::NotCylindrical;
        case DitherRefusal::SlideNotMoving:
            return StrokeProblem::SlideNotMoving;
        case DitherRefusal::WindowTooShort:
            return StrokeProblem::WindowTooShort;
        case DitherRefusal::WaitingForStrokes:
            return StrokeProblem::WaitingForStrokes;
    }
    return StrokeProblem::WaitingForStrokes;
}

}  // namespace

DitherEstimatorConfig DitherCurrentDifference::unit(DitherEstimatorConfig tuning) {
    tuning.currentToForceNPerA = 1.0;  // the "force" is ΔI in A
    tuning.stiffnessNPerMm = 1.0;
    return tuning;
}

DitherCurrentDifference::DitherCurrentDifference(DitherEstimatorConfig tuning) : m_estimator(unit(tuning)) {}

StrokePairReading DitherCurrentDifference::update(const DriveSample& sample) {
    const DitherUpdate u = m_estimator.update(sample);
    StrokePairReading r;
    r.newPair = u.newEstimate && u.estimate.has_value();
    if (r.newPair) r.currentDifferenceA = u.estimate->forceN;
    r.problem = problemOf(u.refusal);
    return r;
}

}  // namespace tt::core
