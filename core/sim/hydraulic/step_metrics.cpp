#include "core/sim/hydraulic/step_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tt::core {

StepMetrics stepMetrics(const std::vector<double>& timesS, const std::vector<double>& values, double eventTimeS,
                        double bandFraction) {
    if (timesS.size() != values.size()) throw std::invalid_argument("step metrics: times and values differ in size");
    if (!(bandFraction > 0.0 && bandFraction < 1.0))
        throw std::invalid_argument("step metrics: the settling band must be a fraction between 0 and 1");
    std::size_t first = 0;
    while (first < timesS.size() && timesS[first] < eventTimeS)
        ++first;
    if (first + 1 >= timesS.size()) throw std::invalid_argument("step metrics: no samples after the event");

    StepMetrics m;
    m.finalValue = values.back();
    std::size_t peak = first;
    for (std::size_t k = first; k < values.size(); ++k)
        if (std::abs(values[k] - m.finalValue) > std::abs(values[peak] - m.finalValue)) peak = k;
    m.peakDeviation = values[peak] - m.finalValue;
    m.peakTimeS = timesS[peak] - eventTimeS;
    const double magnitude = std::abs(m.peakDeviation);
    // A swing at the level of the integration error (a load step of 0 N) is no transient.
    double scale = 0.0;
    for (std::size_t k = first; k < values.size(); ++k)
        scale = std::max(scale, std::abs(values[k]));
    if (magnitude <= 1e-7 * scale) {
        m.peakDeviation = 0.0;
        m.peakTimeS = 0.0;
        m.settled = true;
        return m;
    }
    const double direction = m.peakDeviation > 0.0 ? 1.0 : -1.0;
    double past = 0.0;
    for (std::size_t k = peak; k < values.size(); ++k)
        past = std::max(past, -direction * (values[k] - m.finalValue));
    m.overshootPct = 100.0 * past / magnitude;

    const double band = bandFraction * magnitude;
    std::size_t lastOutside = first;
    bool anyOutside = false;
    for (std::size_t k = first; k < values.size(); ++k)
        if (std::abs(values[k] - m.finalValue) > band) {
            lastOutside = k;
            anyOutside = true;
        }
    const double windowS = timesS.back() - eventTimeS;
    if (anyOutside && lastOutside + 1 < timesS.size()) {
        // Linear interpolation between the last sample outside the band and the next one inside it.
        const double a = std::abs(values[lastOutside] - m.finalValue);
        const double b = std::abs(values[lastOutside + 1] - m.finalValue);
        const double fraction = a > b ? (a - band) / (a - b) : 0.0;
        m.settlingS = timesS[lastOutside] - eventTimeS + fraction * (timesS[lastOutside + 1] - timesS[lastOutside]);
    }
    m.settled = m.settlingS <= 0.8 * windowS;
    return m;
}

}  // namespace tt::core
