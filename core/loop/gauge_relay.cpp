#include "core/loop/gauge_relay.h"

#include <stdexcept>
#include <utility>

namespace tt::core {

GaugeRelay::GaugeRelay(const Clock& loopClock, std::size_t maxQueued) : m_clock(loopClock), m_maxQueued(maxQueued) {
    if (maxQueued == 0) throw std::invalid_argument("a gauge relay must keep at least one reading");
}

DeviceHealth GaugeRelay::health() const {
    std::lock_guard lock(m_mutex);
    return m_health;
}

void GaugeRelay::requestReading() {
    std::lock_guard lock(m_mutex);
    ++m_requests;
}

std::optional<GaugeReading> GaugeRelay::takeReading() {
    std::lock_guard lock(m_mutex);
    if (m_readings.empty()) return std::nullopt;
    GaugeReading r = m_readings.front();
    m_readings.pop_front();
    return r;
}

void GaugeRelay::publishHealth(DeviceHealth health) {
    std::lock_guard lock(m_mutex);
    m_health = std::move(health);
}

void GaugeRelay::deliver(double diameterMm) {
    const double now = m_clock.nowS();
    std::lock_guard lock(m_mutex);
    if (m_readings.size() == m_maxQueued) {
        m_readings.pop_front();
        ++m_dropped;
    }
    m_readings.push_back({diameterMm, now});
}

int GaugeRelay::takeRequests() {
    std::lock_guard lock(m_mutex);
    return std::exchange(m_requests, 0);
}

std::size_t GaugeRelay::discardPending() {
    std::lock_guard lock(m_mutex);
    const std::size_t n = m_readings.size();
    m_readings.clear();
    return n;
}

std::size_t GaugeRelay::pending() const {
    std::lock_guard lock(m_mutex);
    return m_readings.size();
}

std::uint64_t GaugeRelay::dropped() const {
    std::lock_guard lock(m_mutex);
    return m_dropped;
}

}  // namespace tt::core
