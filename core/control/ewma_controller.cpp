#include "core/control/ewma_controller.h"

#include <cmath>
#include <stdexcept>

#include "core/common/text_format.h"
#include "core/control/run_to_run_checks.h"

namespace tt::core {

namespace {

constexpr double kEwmaStateFormat = 1.0;

}  // namespace

void EwmaOptions::validate() const {
    if (!std::isfinite(weight) || weight <= 0.0 || weight > 1.0)
        throw std::invalid_argument("EWMA controller: the weight must be in (0, 1]");
    if (!(deadBandMm >= 0.0) || !std::isfinite(deadBandMm))
        throw std::invalid_argument("EWMA controller: the dead band must be >= 0 mm");
    if (!(warningMm > 0.0) || !(alarmMm > 0.0))
        throw std::invalid_argument("EWMA controller: the warning and alarm bands must be > 0 mm");
    if (warningMm > alarmMm)
        throw std::invalid_argument("EWMA controller: the warning band must not exceed the alarm band");
    requireHistoryParts(historyParts, "EWMA controller");
    if (!std::isfinite(driftWeight) || driftWeight < 0.0 || driftWeight >= 1.0)
        throw std::invalid_argument("double EWMA controller: the drift weight must be in [0, 1)");
    if (driftHorizonParts < 1 || driftHorizonParts > 8)
        throw std::invalid_argument("double EWMA controller: the drift horizon must be 1 .. 8 parts");
}

EwmaController::EwmaController(const Eigen::VectorXd& gain, const CorrectionLimits& limits, const EwmaOptions& options)
    : m_gain(gain), m_limits(limits), m_options(options) {
    limits.validate();
    options.validate();
    if (gain.size() < 1 || !gain.allFinite() || (gain.array() <= 0.0).any())
        throw std::invalid_argument("EWMA controller: every point needs a positive gain");
    const std::size_t m = static_cast<std::size_t>(gain.size());
    const std::size_t h = static_cast<std::size_t>(options.historyParts);
    m_offset = Eigen::VectorXd::Zero(gain.size());
    m_drift = Eigen::VectorXd::Zero(gain.size());
    m_lastApplied = Eigen::VectorXd::Zero(gain.size());
    m_bands.assign(m, ToleranceBand::Ok);
    m_historyPart.assign(h, -1);
    m_historyApplied.assign(h * m, 0.0);
    m_historyMeasured.assign(h * m, 0);
}

std::size_t EwmaController::slot(std::int64_t part) const {
    return ringSlot(part, m_options.historyParts);
}

MeasurementVerdict EwmaController::addMeasurement(const PartMeasurement& measurement) {
    requireMeasurementSize(measurement, pointCount(), "EWMA controller");
    const std::size_t m = static_cast<std::size_t>(pointCount());
    const std::int64_t part = measurement.partNumber;
    const std::size_t s = slot(part);
    const MachinedParts machined{m_started, m_firstPart, m_lastPart, m_options.historyParts};
    if (const auto why = partRejection(machined, part, m_historyPart[s] == part))
        return rejectEveryPoint(pointCount(), *why);
    MeasurementVerdict verdict{std::vector<bool>(m, false), std::vector<Notice>(m)};
    for (std::size_t i = 0; i < m; ++i) {
        const Eigen::Index ii = static_cast<Eigen::Index>(i);
        const double v = measurement.deviationMm(ii);
        if (const auto why = valueRejection(v, m_historyMeasured[s * m + i] != 0, part)) {
            verdict.reasons[i] = *why;
            continue;
        }
        if (std::abs(v) >= m_options.alarmMm) {
            m_bands[i] = ToleranceBand::Alarm;
            verdict.reasons[i] = Notice{NoticeKind::AlarmBand, part};
            verdict.reasons[i].value = std::abs(v);
            verdict.reasons[i].limit = m_options.alarmMm;
            continue;
        }
        m_bands[i] = std::abs(v) >= m_options.warningMm ? ToleranceBand::Warning : ToleranceBand::Ok;
        const double uncorrected = v - m_gain(ii) * m_historyApplied[s * m + i];
        const double previous = m_offset(ii);
        m_offset(ii) = m_options.weight * uncorrected + (1.0 - m_options.weight) * previous;
        m_drift(ii) = m_options.driftWeight * (uncorrected - previous) + (1.0 - m_options.driftWeight) * m_drift(ii);
        m_historyMeasured[s * m + i] = 1;
        verdict.accepted[i] = true;
    }
    return verdict;
}

Eigen::VectorXd EwmaController::nextCorrection(std::int64_t partNumber) {
    requireNextPart(m_started, m_lastPart, partNumber, "EWMA controller");
    if (!m_started) {
        m_started = true;
        m_firstPart = partNumber;
    }
    Eigen::VectorXd candidate(m_gain.size());
    for (Eigen::Index i = 0; i < m_gain.size(); ++i) {
        // a + p predicts the next part (p -> D / lambda1 on a ramp of D per part, the offset's lag included);
        // each further part of the horizon adds the drift D = lambda1 p.
        const double expected = m_offset(i) + (1.0 + (m_options.driftHorizonParts - 1) * m_options.weight) * m_drift(i);
        const double predicted = expected + m_gain(i) * m_lastApplied(i);
        candidate(i) = std::abs(predicted) < m_options.deadBandMm ? m_lastApplied(i) : -expected / m_gain(i);
    }
    m_lastApplied = applyCorrectionLimits(candidate, m_lastApplied, m_limits).correctionMm;
    const std::size_t m = static_cast<std::size_t>(m_gain.size());
    const std::size_t s = slot(partNumber);
    m_historyPart[s] = partNumber;
    std::copy_n(m_lastApplied.data(), m, m_historyApplied.begin() + static_cast<std::ptrdiff_t>(s * m));
    std::fill_n(m_historyMeasured.begin() + static_cast<std::ptrdiff_t>(s * m), m, std::uint8_t{0});
    m_lastPart = partNumber;
    return m_lastApplied;
}

void EwmaController::correctionApplied(std::int64_t partNumber, const Eigen::VectorXd& appliedMm) {
    if (!m_started || partNumber != m_lastPart || appliedMm.size() != m_gain.size() || !appliedMm.allFinite()) return;
    const std::size_t m = static_cast<std::size_t>(m_gain.size());
    const std::size_t s = slot(partNumber);
    if (m_historyPart[s] == partNumber)
        std::copy_n(appliedMm.data(), m, m_historyApplied.begin() + static_cast<std::ptrdiff_t>(s * m));
    m_lastApplied = appliedMm;
}

std::uint16_t EwmaController::fingerprint() const {
    std::vector<double> config{m_options.weight,
                               m_options.deadBandMm,
                               m_options.warningMm,
                               m_options.alarmMm,
                               m_limits.maxAbsMm,
                               m_limits.maxStepMm,
                               static_cast<double>(m_options.historyParts)};
    config.insert(config.end(), m_gain.data(), m_gain.data() + m_gain.size());
    if (m_options.driftWeight > 0.0) {  // an EWMA's fingerprint stays what it was
        config.push_back(m_options.driftWeight);
        config.push_back(m_options.driftHorizonParts);
    }
    return configurationFingerprint(config);
}

ControllerState EwmaController::saveState() const {
    ControllerState s;
    s.kind = name();
    auto& v = s.values;
    v = {kEwmaStateFormat, static_cast<double>(fingerprint()), m_started ? 1.0 : 0.0, static_cast<double>(m_firstPart),
         static_cast<double>(m_lastPart)};
    v.insert(v.end(), m_offset.data(), m_offset.data() + m_offset.size());
    v.insert(v.end(), m_lastApplied.data(), m_lastApplied.data() + m_lastApplied.size());
    for (ToleranceBand b : m_bands)
        v.push_back(static_cast<double>(b));
    for (std::int64_t p : m_historyPart)
        v.push_back(static_cast<double>(p));
    v.insert(v.end(), m_historyApplied.begin(), m_historyApplied.end());
    for (std::uint8_t f : m_historyMeasured)
        v.push_back(f);
    if (m_options.driftWeight > 0.0) v.insert(v.end(), m_drift.data(), m_drift.data() + m_drift.size());
    return s;
}

void EwmaController::restoreState(const ControllerState& state) {
    if (state.kind != name())
        throw std::invalid_argument("cannot restore a '" + state.kind + "' controller state into the " + name() +
                                    " controller");
    const std::size_t m = static_cast<std::size_t>(m_gain.size());
    const std::size_t h = static_cast<std::size_t>(m_options.historyParts);
    const std::size_t expected = 5 + 3 * m + h + 2 * h * m + (m_options.driftWeight > 0.0 ? m : 0);
    const auto& v = state.values;
    if (v.size() != expected || v[0] != kEwmaStateFormat)
        throw std::invalid_argument("saved EWMA controller state has an unexpected size or format");
    if (v[1] != static_cast<double>(fingerprint()))
        throw std::invalid_argument("saved EWMA controller state belongs to a different configuration");
    for (double x : v)
        if (!std::isfinite(x)) throw std::invalid_argument("saved EWMA controller state contains a NaN or Inf");
    std::size_t i = 2;
    m_started = v[i++] != 0.0;
    m_firstPart = static_cast<std::int64_t>(v[i++]);
    m_lastPart = static_cast<std::int64_t>(v[i++]);
    for (std::size_t j = 0; j < m; ++j)
        m_offset(static_cast<Eigen::Index>(j)) = v[i++];
    for (std::size_t j = 0; j < m; ++j)
        m_lastApplied(static_cast<Eigen::Index>(j)) = v[i++];
    for (std::size_t j = 0; j < m; ++j)
        m_bands[j] = static_cast<ToleranceBand>(static_cast<int>(v[i++]));
    for (std::size_t j = 0; j < h; ++j)
        m_historyPart[j] = static_cast<std::int64_t>(v[i++]);
    for (std::size_t j = 0; j < h * m; ++j)
        m_historyApplied[j] = v[i++];
    for (std::size_t j = 0; j < h * m; ++j)
        m_historyMeasured[j] = v[i++] != 0.0 ? 1 : 0;
    for (std::size_t j = 0; j < m && i < v.size(); ++j)
        m_drift(static_cast<Eigen::Index>(j)) = v[i++];
}

OpenLoopController::OpenLoopController(int pointCount) : m_points(pointCount) {
    if (pointCount < 1) throw std::invalid_argument("open loop: at least one control point");
}

MeasurementVerdict OpenLoopController::addMeasurement(const PartMeasurement& measurement) {
    requireMeasurementSize(measurement, m_points, "open loop");
    const std::size_t m = static_cast<std::size_t>(m_points);
    MeasurementVerdict verdict{std::vector<bool>(m, false), std::vector<Notice>(m)};
    const bool machined = m_started && measurement.partNumber <= m_lastPart;
    for (std::size_t i = 0; i < m; ++i) {
        if (!machined) {
            verdict.reasons[i] = Notice{NoticeKind::NotMachinedYet, measurement.partNumber};
        } else if (const auto why = nonFiniteReason(measurement.deviationMm(static_cast<Eigen::Index>(i)))) {
            verdict.reasons[i] = *why;
        } else {
            verdict.accepted[i] = true;
        }
    }
    return verdict;
}

Eigen::VectorXd OpenLoopController::nextCorrection(std::int64_t partNumber) {
    requireNextPart(m_started, m_lastPart, partNumber, "open loop");
    m_started = true;
    m_lastPart = partNumber;
    return Eigen::VectorXd::Zero(m_points);
}

ControllerState OpenLoopController::saveState() const {
    return {name(), {static_cast<double>(m_points), m_started ? 1.0 : 0.0, static_cast<double>(m_lastPart)}};
}

void OpenLoopController::restoreState(const ControllerState& state) {
    if (state.kind != name() || state.values.size() != 3 || state.values[0] != m_points ||
        !std::isfinite(state.values[2]))
        throw std::invalid_argument("saved state is not an open-loop state with " + std::to_string(m_points) +
                                    " points");
    m_started = state.values[1] != 0.0;
    m_lastPart = static_cast<std::int64_t>(state.values[2]);
}

}  // namespace tt::core
