#include "core/sim/boring/inductive_probe.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tt::core {

double sensorToTipRatio(double s) {
    if (!std::isfinite(s) || s <= 0.0 || s > 1.0)
        throw std::invalid_argument("sensor position must be within the overhang (0 .. 1]");
    return s * s * (3.0 - s) / 2.0;
}

InductiveProbe::InductiveProbe(const InductiveProbeConfig& config, unsigned long long seed)
    : m_config(config), m_rng(seed) {
    if (config.adcBits < kMinAdcBits || config.adcBits > kMaxAdcBits)
        throw std::invalid_argument("probe ADC resolution must be 10 .. 16 bits");
    const std::size_t n = config.bridgeCoefficients.size();
    if (n < 3 || n > 5) throw std::invalid_argument("the bridge characteristic must be a polynomial of degree 2 .. 4");
    for (double c : config.bridgeCoefficients)
        if (!std::isfinite(c)) throw std::invalid_argument("bridge coefficients must be numbers");
    if (!(config.fullScaleGapMm > 0.0)) throw std::invalid_argument("probe full-scale gap must be above 0 mm");
    if (!(config.sampleRateHz > 0.0)) throw std::invalid_argument("probe sample rate must be above 0 Hz");
    if (!(config.filterTimeConstantS > 0.0))
        throw std::invalid_argument("probe filter time constant must be above 0 s");
    if (!(config.noiseRms >= 0.0)) throw std::invalid_argument("probe noise must not be negative");
    if (!(config.supplyVariation >= 0.0 && config.supplyVariation < 0.5))
        throw std::invalid_argument("probe supply variation must be within 0 .. 0.5");
    sensorToTipRatio(config.sensorPositionFraction);
}

double InductiveProbe::bridgeRatio(double u) const {
    double r = 0.0;
    for (auto it = m_config.bridgeCoefficients.rbegin(); it != m_config.bridgeCoefficients.rend(); ++it)
        r = r * u + *it;
    return std::clamp(r, -1.0, 1.0);
}

double InductiveProbe::fullScaleCode() const {
    return std::ldexp(1.0, m_config.adcBits) - 1.0;
}

double InductiveProbe::normalisedGap(double tipDeflectionMm) const {
    return tipDeflectionMm * sensorToTipRatio(m_config.sensorPositionFraction) / m_config.fullScaleGapMm;
}

double InductiveProbe::staticCode(double tipDeflectionMm) const {
    return (1.0 + bridgeRatio(normalisedGap(tipDeflectionMm))) / 2.0 * fullScaleCode();
}

void InductiveProbe::advance(double dtS, double tipDeflectionXmm, double tipDeflectionYmm) {
    const double ux = normalisedGap(tipDeflectionXmm) + m_config.crossTalk * normalisedGap(tipDeflectionYmm);
    const double uy = normalisedGap(tipDeflectionYmm) + m_config.crossTalk * normalisedGap(tipDeflectionXmm);
    const double alpha = 1.0 - std::exp(-dtS / m_config.filterTimeConstantS);
    m_filtered[0] += alpha * (bridgeRatio(ux) - m_filtered[0]);
    m_filtered[1] += alpha * (bridgeRatio(uy) - m_filtered[1]);
}

void InductiveProbe::settle(double tipDeflectionXmm, double tipDeflectionYmm) {
    advance(50.0 * m_config.filterTimeConstantS, tipDeflectionXmm, tipDeflectionYmm);
}

std::array<std::int32_t, 2> InductiveProbe::convert(double timeS) {
    // The bridge output and the ADC reference both scale with the supply; the amplifier noise
    // does not, so only the noise grows when the supply sags.
    const double supply =
        1.0 + m_config.supplyVariation * std::sin(2.0 * std::numbers::pi * timeS / m_config.supplyVariationPeriodS);
    std::array<std::int32_t, 2> codes{};
    for (std::size_t p = 0; p < 2; ++p) {
        const double outputV = supply * m_filtered[p] + m_config.noiseRms * m_normal(m_rng);
        const double referenceV = supply;
        const double code = (1.0 + outputV / referenceV) / 2.0 * fullScaleCode();
        codes[p] = static_cast<std::int32_t>(std::clamp(std::round(code), 0.0, fullScaleCode()));
    }
    return codes;
}

void InductiveProbe::setTable(int plane, std::optional<LinearisationTable> table) {
    if (plane != 0 && plane != 1) throw std::invalid_argument("probe plane must be 0 (X) or 1 (Y)");
    if (table && table->entries.size() != static_cast<std::size_t>(fullScaleCode()) + 1)
        throw std::invalid_argument("the table does not match the probe's ADC resolution");
    m_tables[static_cast<std::size_t>(plane)] = std::move(table);
}

const std::optional<LinearisationTable>& InductiveProbe::table(int plane) const {
    return m_tables.at(static_cast<std::size_t>(plane));
}

}  // namespace tt::core
