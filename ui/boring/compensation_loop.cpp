#include "ui/boring/compensation_loop.h"

#include <cmath>
#include <stdexcept>

namespace tt::ui {

CompensationLoop::CompensationLoop(const BoringRunSettings& settings, core::DriveCurrentReadout* readout,
                                   core::DeflectionProbe* probe, core::CorrectionOutput& output, double heldOffsetMm) {
    if (!(settings.stiffnessNPerMm > 0.0) || !std::isfinite(settings.stiffnessNPerMm))
        throw std::invalid_argument("the tool has no stiffness: enter its section and overhang on the Tools page");
    if (settings.source == BoringSource::Current) {
        if (!readout) throw std::invalid_argument("no drive current read-out is chosen");
        if (!(settings.currentToForceNPerA > 0.0) || !std::isfinite(settings.currentToForceNPerA))
            throw std::invalid_argument(
                "the tool has no current-to-force gain k_p: calibrate it on the Calibration page");
        core::DitherEstimatorConfig config = settings.estimator;
        config.currentToForceNPerA = settings.currentToForceNPerA;
        config.stiffnessNPerMm = settings.stiffnessNPerMm;
        auto current = std::make_unique<core::CurrentDeflectionSource>(*readout, config);
        m_current = current.get();
        m_source = std::move(current);
    } else {
        if (!probe) throw std::invalid_argument("no probe mandrel is chosen");
        m_source = std::make_unique<core::ProbeDeflectionSource>(*probe, settings.plane, std::nullopt,
                                                                 settings.stiffnessNPerMm);
    }
    m_compensator =
        std::make_unique<core::InProcessCompensator>(*m_source, output, settings.limits, settings.plcCycleS);
    m_compensator->resumeFrom(heldOffsetMm);
}

core::CompensationCycle CompensationLoop::cycle(double nowS) {
    return m_compensator->cycle(nowS);
}

void CompensationLoop::setSegment(core::SegmentKind kind) {
    if (m_current) m_current->estimator().setSegment(kind);
}

}  // namespace tt::ui
