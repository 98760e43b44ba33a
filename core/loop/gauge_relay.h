#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>

#include "core/ports/clock.h"
#include "core/ports/diameter_gauge.h"

namespace tt::core {

/// A gauge micrometer that lives in another thread (the GUI's, whose event loop runs its serial port),
/// seen by the loop's thread as a DiameterGauge. The device's side delivers each reading and publishes the
/// device's health whenever it changes; the loop's side takes the readings in the order they were delivered
/// and sees that health, so a gauge that is unplugged or goes silent pauses the loop exactly as a gauge in
/// the loop's own thread would. Requests for a reading go the other way. Readings are stamped with the
/// loop's clock when delivered (the device's clock may have another origin). Thread-safe; no call waits for
/// more than a short lock.
class GaugeRelay final : public DiameterGauge {
public:
    /// `loopClock`: the loop's time (thread-safe, outlives the relay). At most `maxQueued` (> 0) readings
    /// wait; beyond that the oldest is dropped and counted. Throws std::invalid_argument for 0.
    explicit GaugeRelay(const Clock& loopClock, std::size_t maxQueued = 256);

    // ---- the loop's side ----
    /// The device's health as last published (Connecting "waiting for the gauge" before the first).
    DeviceHealth health() const override;
    /// Counted; the device's side passes it on (takeRequests()).
    void requestReading() override;
    /// The oldest delivered reading not yet taken.
    std::optional<GaugeReading> takeReading() override;

    // ---- the device's side ----
    /// The device's current health.
    void publishHealth(DeviceHealth health);
    /// A reading the device produced, mm.
    void deliver(double diameterMm);
    /// Requests made by the loop since the last call.
    int takeRequests();
    /// Drops the readings not yet taken (e.g. taken while diameters were typed by hand); returns how many.
    std::size_t discardPending();
    /// Readings waiting for the loop.
    std::size_t pending() const;
    /// Readings dropped because the loop did not take them in time.
    std::uint64_t dropped() const;

private:
    const Clock& m_clock;
    const std::size_t m_maxQueued;
    mutable std::mutex m_mutex;
    DeviceHealth m_health{DeviceState::Connecting, "waiting for the gauge"};
    std::deque<GaugeReading> m_readings;
    int m_requests = 0;
    std::uint64_t m_dropped = 0;
};

}  // namespace tt::core
