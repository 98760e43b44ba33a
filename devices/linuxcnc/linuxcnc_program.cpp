#include "devices/linuxcnc/linuxcnc_program.h"

#include "core/control/correction_path_builder.h"
#include "core/control/profile_interpolation.h"

namespace tt::devices::linuxcnc {

ParametricProgramJob programJob(const core::LoopConfig& loop, const ProgramOptions& options) {
    core::validateLoopConfig(loop);
    core::CorrectionPathRequest request;
    request.pointZMm = loop.pointZMm;
    request.pointCorrectionMm.assign(loop.pointZMm.size(), 0.0);
    request.method = loop.interpolation;
    request.diameterErrorModel = loop.systematicModel;
    request.partLengthMm = loop.partLengthMm;
    request.stepMm = loop.pathStepMm;
    // With every point correction zero the path is the feed-forward alone.
    const core::CorrectionPath feedForward = core::buildCorrectionPath(request);

    ParametricProgramJob job;
    job.pointZMm = loop.pointZMm;
    job.pathZMm = feedForward.zMm;
    if (loop.systematicModel) job.feedForwardMm = feedForward.xCorrectionMm;
    job.nominalDiameterMm = loop.nominalDiameterMm;
    if (loop.interpolation == core::InterpolationMethod::NaturalSpline) {
        job.slopes = ParametricSlopes::Weights;
        const std::size_t n = loop.pointZMm.size();
        job.slopeWeights.assign(n, std::vector<double>(n, 0.0));
        for (std::size_t j = 0; j < n; ++j) {
            std::vector<double> unit(n, 0.0);
            unit[j] = 1.0;
            const std::vector<double> slopes = core::PiecewiseCubic::naturalSpline(loop.pointZMm, unit).knotSlopes();
            for (std::size_t k = 0; k < n; ++k)
                job.slopeWeights[k][j] = slopes[k];
        }
    }
    job.firstParameter = options.firstParameter;
    job.conventions = options.conventions;
    job.feed = options.feed;
    job.feedPerMinute = options.feedPerMinute;
    job.spindleRpm = options.spindleRpm;
    job.toolNumber = options.toolNumber;
    if (options.firstParameter == 0) job.wearTool = options.wearTool;
    job.zOriginMm = options.zOriginMm;
    job.zDirection = options.zDirection;
    job.clearanceMm = options.clearanceMm;
    job.largestTotalMm = options.largestTotalMm;
    job.programNumber = options.programNumber;
    job.notes = options.notes;
    return job;
}

}  // namespace tt::devices::linuxcnc
