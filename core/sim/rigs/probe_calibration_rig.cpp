#include "core/sim/rigs/probe_calibration_rig.h"

#include <cmath>
#include <stdexcept>

namespace tt::core {

ProbeCalibrationRig::ProbeCalibrationRig(InductiveProbe& probe, int plane, double referenceResolutionUm,
                                         double referenceNoiseUm, unsigned long long seed)
    : m_probe(probe), m_plane(plane), m_resolutionUm(referenceResolutionUm), m_noiseUm(referenceNoiseUm), m_rng(seed) {
    if (plane != 0 && plane != 1) throw std::invalid_argument("probe plane must be 0 (X) or 1 (Y)");
    if (!(referenceResolutionUm >= 0.0) || !(referenceNoiseUm >= 0.0))
        throw std::invalid_argument("reference resolution and noise must not be negative");
}

double ProbeCalibrationRig::fullScaleTipDeflectionMm() const {
    return m_probe.config().fullScaleGapMm / sensorToTipRatio(m_probe.config().sensorPositionFraction);
}

CalibrationPoint ProbeCalibrationRig::measure(double tipDeflectionMm, int readings) {
    if (readings < 1) throw std::invalid_argument("at least one reading per point is needed");
    const double x = m_plane == 0 ? tipDeflectionMm : 0.0;
    const double y = m_plane == 1 ? tipDeflectionMm : 0.0;
    m_probe.settle(x, y);
    const double period = 1.0 / m_probe.config().sampleRateHz;
    double sum = 0.0;
    for (int i = 0; i < readings; ++i) {
        m_probe.advance(period, x, y);
        m_timeS += period;
        sum += m_probe.convert(m_timeS)[static_cast<std::size_t>(m_plane)];
    }
    CalibrationPoint p;
    p.adcCode = sum / readings;
    double reference = tipDeflectionMm * 1000.0 + m_noiseUm * m_normal(m_rng);
    if (m_resolutionUm > 0.0) reference = std::round(reference / m_resolutionUm) * m_resolutionUm;
    p.referenceUm = reference;
    return p;
}

std::vector<CalibrationPoint> ProbeCalibrationRig::sweep(const ProbeCalibrationConfig& config) {
    if (config.points < 2) throw std::invalid_argument("a calibration sweep needs at least two points");
    const double span = config.spanFraction * fullScaleTipDeflectionMm();
    std::vector<CalibrationPoint> points;
    for (int i = 0; i < config.points; ++i) {
        const double deflection = -span + 2.0 * span * i / (config.points - 1);
        points.push_back(measure(deflection, config.readingsPerPoint));
    }
    return points;
}

}  // namespace tt::core
