#pragma once

#include "core/common/notice.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/ports/diameter_gauge.h"

namespace tt::core {

/// Outcome of offering a reading to a measurement session.
struct SessionAccept {
    bool accepted = false;
    std::size_t pointIndex = 0;  ///< the control point the reading went to (when accepted)
    Notice refusal;              ///< why it was refused (kind None when accepted)
};

/// Collects the diameters of one finished part at its control points (paper 000: five points
/// measured with a 0.001 mm micrometer). Gauge readings arrive in order and are assigned to the
/// points in order; the operator sees which point is next and its axial position x, and can
/// re-take any point. A reading outside the plausible window around the nominal diameter is
/// refused (wrong spot, wrong part, wrong unit) and the point stays open.
class MeasurementSession {
public:
    /// `pointXMm`: axial positions of the control points, mm from the part's left end, in the
    /// order they are measured (non-empty, finite). `nominalDiameterMm` > 0.
    /// `plausibleWindowMm` > 0: readings farther than this from the nominal are refused.
    /// Throws std::invalid_argument otherwise.
    MeasurementSession(std::vector<double> pointXMm, double nominalDiameterMm, double plausibleWindowMm = 1.0);

    /// Number of control points to measure.
    std::size_t pointCount() const { return m_pointXMm.size(); }
    /// Axial position of point `index`, mm (throws std::out_of_range).
    double pointXMm(std::size_t index) const { return m_pointXMm.at(index); }
    /// The point the next reading goes to; nullopt when every point has a reading.
    std::optional<std::size_t> currentPoint() const;
    /// Every point has a reading.
    bool complete() const { return !currentPoint().has_value(); }

    /// Assigns `reading` to the current point and moves on to the next open point.
    SessionAccept accept(const GaugeReading& reading);
    /// Clears point `index` and makes it the current point, so the next reading re-takes it
    /// (throws std::out_of_range).
    void retake(std::size_t index);

    /// Reading of point `index`, if taken.
    const std::optional<GaugeReading>& reading(std::size_t index) const { return m_readings.at(index); }
    /// Diameters at the points in point order, mm. Throws std::logic_error while incomplete.
    std::vector<double> diametersMm() const;

private:
    std::vector<double> m_pointXMm;
    double m_nominalMm;
    double m_windowMm;
    std::vector<std::optional<GaugeReading>> m_readings;
    std::optional<std::size_t> m_retaking;
};

}  // namespace tt::core
