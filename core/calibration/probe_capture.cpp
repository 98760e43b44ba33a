#include "core/calibration/probe_capture.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/calibration/linearisation_table.h"

namespace tt::core {

bool saturatedCode(double code, int adcBits) {
    return code <= 0.0 || code >= std::ldexp(1.0, adcBits) - 1.0;
}

ProbeCapture::ProbeCapture(const ProbeCaptureConfig& config, int plane, int adcBits)
    : m_config(config), m_plane(plane), m_bits(adcBits), m_average(config.settleS, config.samplesPerPoint) {
    if (plane != 0 && plane != 1) throw std::invalid_argument("the bending plane must be 0 (X) or 1 (Y)");
    if (adcBits < kMinAdcBits || adcBits > kMaxAdcBits)
        throw std::invalid_argument("ADC resolution " + std::to_string(adcBits) + " bits is outside " +
                                    std::to_string(kMinAdcBits) + " .. " + std::to_string(kMaxAdcBits));
    if (config.liveWindow < 1 || config.liveWindow > 10000 || config.minLiveSamples < 1 ||
        config.minLiveSamples > config.liveWindow)
        throw std::invalid_argument("the live window must hold 1 .. 10000 samples, at least the minimum shown");
    if (!(config.noSampleTimeoutS > 0.0) || config.noSampleTimeoutS > 600.0)
        throw std::invalid_argument("the sample timeout must be within 0 .. 600 s");
}

void ProbeCapture::start(double referenceUm) {
    if (running()) throw std::logic_error("a capture is already running");
    if (!std::isfinite(referenceUm)) throw std::invalid_argument("the reference reading must be a number");
    m_point = ProbePoint{referenceUm, 0.0, 0, false, 0, 0};
    m_quietS = 0.0;
    m_average.start();
}

std::optional<ProbeCaptureResult> ProbeCapture::abort() {
    return running() ? finish(CaptureProblem::Aborted) : std::nullopt;
}

std::optional<ProbeCaptureResult> ProbeCapture::loadChanged() {
    m_live.clear();
    return running() ? finish(CaptureProblem::LoadChanged) : std::nullopt;
}

std::optional<ProbeCaptureResult> ProbeCapture::pump(DeflectionProbe& port, double elapsedS) {
    const DeviceHealth health = port.health();
    if (!health.ready()) {
        m_live.clear();
        return running() ? finish(CaptureProblem::NotReady, health.message) : std::nullopt;
    }
    bool any = false;
    while (const std::optional<ProbeSample> s = port.takeSample()) {
        any = true;
        const std::int32_t code = s->adcCode[static_cast<std::size_t>(m_plane)];
        m_live.push_back(code);
        if (static_cast<int>(m_live.size()) > m_config.liveWindow) m_live.pop_front();
        if (!running()) continue;
        m_average.observe(s->timeS);  // the bar holds still until settleS has passed
        if (m_average.phase() != SettledAverage::Phase::Averaging) continue;
        m_point.lowestCode = m_point.samples == 0 ? code : std::min(m_point.lowestCode, code);
        m_point.highestCode = m_point.samples == 0 ? code : std::max(m_point.highestCode, code);
        ++m_point.samples;
        m_average.add(s->timeS, static_cast<double>(code));
        if (m_average.phase() == SettledAverage::Phase::Done) return finish(CaptureProblem::None);
    }
    if (!running()) return std::nullopt;
    m_quietS = any ? 0.0 : m_quietS + std::max(0.0, std::isfinite(elapsedS) ? elapsedS : 0.0);
    if (m_quietS >= m_config.noSampleTimeoutS) return finish(CaptureProblem::NoSamples);
    return std::nullopt;
}

std::optional<ProbeCaptureResult> ProbeCapture::finish(CaptureProblem problem, std::string message) {
    ProbeCaptureResult r;
    r.problem = problem;
    r.deviceMessage = std::move(message);
    r.point = m_point;
    if (problem == CaptureProblem::None) {
        r.point.adcCode = m_average.mean();
        r.point.saturated = saturatedCode(r.point.lowestCode, m_bits) || saturatedCode(r.point.highestCode, m_bits);
    }
    m_average.stop();
    return r;
}

std::optional<double> ProbeCapture::liveCode() const {
    if (static_cast<int>(m_live.size()) < m_config.minLiveSamples) return std::nullopt;
    double sum = 0.0;
    for (std::int32_t c : m_live)
        sum += c;
    return sum / static_cast<double>(m_live.size());
}

bool ProbeCapture::liveSaturated() const {
    return std::any_of(m_live.begin(), m_live.end(), [this](std::int32_t c) { return saturatedCode(c, m_bits); });
}

}  // namespace tt::core
