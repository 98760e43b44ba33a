#include "core/loop/measurement_session.h"

#include <cmath>
#include <stdexcept>

namespace tt::core {

MeasurementSession::MeasurementSession(std::vector<double> pointXMm, double nominalDiameterMm, double plausibleWindowMm)
    : m_pointXMm(std::move(pointXMm)), m_nominalMm(nominalDiameterMm), m_windowMm(plausibleWindowMm) {
    if (m_pointXMm.empty()) throw std::invalid_argument("measurement session: there are no control points");
    for (const double x : m_pointXMm)
        if (!std::isfinite(x))
            throw std::invalid_argument("measurement session: a control point position is not a number");
    if (!(m_nominalMm > 0.0) || !std::isfinite(m_nominalMm))
        throw std::invalid_argument("measurement session: the nominal diameter must be a positive number of mm");
    if (!(m_windowMm > 0.0) || !std::isfinite(m_windowMm))
        throw std::invalid_argument("measurement session: the plausible window must be a positive number of mm");
    m_readings.resize(m_pointXMm.size());
}

std::optional<std::size_t> MeasurementSession::currentPoint() const {
    if (m_retaking) return m_retaking;
    for (std::size_t i = 0; i < m_readings.size(); ++i)
        if (!m_readings[i]) return i;
    return std::nullopt;
}

SessionAccept MeasurementSession::accept(const GaugeReading& reading) {
    const auto point = currentPoint();
    if (!point) return {false, 0, Notice{NoticeKind::AllPointsRead}};
    Notice refusal;
    refusal.point = static_cast<int>(*point) + 1;
    refusal.zMm = m_pointXMm[*point];
    if (!std::isfinite(reading.diameterMm)) {
        refusal.kind = NoticeKind::NotANumber;
        return {false, *point, refusal};
    }
    if (std::fabs(reading.diameterMm - m_nominalMm) > m_windowMm) {
        refusal.kind = NoticeKind::Implausible;
        refusal.value = reading.diameterMm;
        refusal.reference = m_nominalMm;
        refusal.limit = m_windowMm;
        return {false, *point, refusal};
    }
    m_readings[*point] = reading;
    m_retaking.reset();
    return {true, *point, {}};
}

void MeasurementSession::retake(std::size_t index) {
    m_readings.at(index).reset();
    m_retaking = index;
}

std::vector<double> MeasurementSession::diametersMm() const {
    if (!complete()) throw std::logic_error("measurement session: not every control point has a reading yet");
    std::vector<double> d;
    d.reserve(m_readings.size());
    for (const auto& r : m_readings)
        d.push_back(r->diameterMm);
    return d;
}

}  // namespace tt::core
