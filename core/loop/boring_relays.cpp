#include "core/loop/boring_relays.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace tt::core {

template <class Sample>
SampleRelay<Sample>::SampleRelay(std::size_t maxQueued) : m_maxQueued(maxQueued) {
    if (maxQueued == 0) throw std::invalid_argument("a sample relay must keep at least one sample");
}

template <class Sample>
DeviceHealth SampleRelay<Sample>::health() const {
    std::lock_guard lock(m_mutex);
    return m_health;
}

template <class Sample>
std::optional<Sample> SampleRelay<Sample>::take() {
    std::lock_guard lock(m_mutex);
    if (m_samples.empty()) return std::nullopt;
    Sample s = m_samples.front();
    m_samples.pop_front();
    return s;
}

template <class Sample>
void SampleRelay<Sample>::publishHealth(DeviceHealth health) {
    std::lock_guard lock(m_mutex);
    m_health = std::move(health);
}

template <class Sample>
void SampleRelay<Sample>::deliver(const Sample& sample) {
    std::lock_guard lock(m_mutex);
    if (m_samples.size() == m_maxQueued) {
        m_samples.pop_front();
        ++m_dropped;
    }
    m_samples.push_back(sample);
}

template <class Sample>
std::size_t SampleRelay<Sample>::pending() const {
    std::lock_guard lock(m_mutex);
    return m_samples.size();
}

template <class Sample>
std::uint64_t SampleRelay<Sample>::dropped() const {
    std::lock_guard lock(m_mutex);
    return m_dropped;
}

template class SampleRelay<DriveSample>;
template class SampleRelay<ProbeSample>;

OffsetRelay::OffsetRelay(const Clock& clock, double maxWaitS) : m_clock(clock), m_maxWaitS(maxWaitS) {
    if (!std::isfinite(maxWaitS) || maxWaitS <= 0.0)
        throw std::invalid_argument("an offset relay must wait more than 0 s for its device");
}

OffsetRelay::~OffsetRelay() = default;

DeviceHealth OffsetRelay::health() const {
    const double now = m_clock.nowS();
    std::lock_guard lock(m_mutex);
    if (m_closed) return {DeviceState::Disconnected, {}};
    if (m_pendingSinceS && now - *m_pendingSinceS > m_maxWaitS) return {DeviceState::Connecting, {}};
    return m_health;
}

OutputResult OffsetRelay::sendPartCorrection(const PartCorrection&) {
    return {false, "this output takes the dynamic X offset only"};
}

OutputResult OffsetRelay::sendDynamicOffset(double xOffsetMm) {
    const double now = m_clock.nowS();
    std::lock_guard lock(m_mutex);
    if (m_closed) return {false, {}};
    if (m_refusal) {
        OutputResult refused{false, *m_refusal};
        m_refusal.reset();
        return refused;
    }
    m_pending = xOffsetMm;
    if (!m_pendingSinceS) m_pendingSinceS = now;
    if (m_listener) m_listener();
    return {true, {}};
}

std::optional<double> OffsetRelay::confirmedOffsetMm() const {
    std::lock_guard lock(m_mutex);
    return m_confirmed;
}

void OffsetRelay::publishHealth(DeviceHealth health) {
    std::lock_guard lock(m_mutex);
    m_health = std::move(health);
}

void OffsetRelay::setRequestListener(std::function<void()> listener) {
    std::lock_guard lock(m_mutex);
    if (!m_closed) m_listener = std::move(listener);
}

std::optional<double> OffsetRelay::takePending() {
    std::lock_guard lock(m_mutex);
    if (m_closed) return std::nullopt;
    m_pendingSinceS.reset();
    return std::exchange(m_pending, std::nullopt);
}

void OffsetRelay::reply(double xOffsetMm, const OutputResult& result) {
    std::lock_guard lock(m_mutex);
    if (result.ok)
        m_confirmed = xOffsetMm;
    else
        m_refusal = result.message;
}

void OffsetRelay::close() {
    std::lock_guard lock(m_mutex);
    m_closed = true;
    m_pending.reset();
    m_pendingSinceS.reset();
    m_listener = nullptr;
}

bool OffsetRelay::closed() const {
    std::lock_guard lock(m_mutex);
    return m_closed;
}

RelayedBoringStation::RelayedBoringStation(const Clock& clock, bool withDrive, bool withProbe, double maxOffsetWaitS)
    : m_clock(clock),
      m_drive(withDrive ? std::make_unique<DriveRelay>() : nullptr),
      m_probe(withProbe ? std::make_unique<ProbeRelay>() : nullptr),
      m_output(clock, maxOffsetWaitS) {}

RelayedBoringStation::~RelayedBoringStation() = default;

}  // namespace tt::core
