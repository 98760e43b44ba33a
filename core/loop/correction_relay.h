#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <variant>

#include "core/ports/correction_output.h"

namespace tt::core {

/// A correction output (the CNC: a G-code file, PLC registers) that lives in another thread, seen by the
/// loop's thread as a CorrectionOutput. Each write of the loop is queued for the device's side, which performs
/// it on the real output and replies with the output's own result; the loop's call waits for that reply at
/// most `replyTimeout`, so the loop learns whether its corrections reached the CNC (and holds the last ones
/// when they did not) without ever waiting on a device in its own thread. The health is the device's as
/// last published. Thread-safe.
class CorrectionRelay final : public CorrectionOutput {
public:
    /// One write the loop asked for.
    struct Request {
        std::uint64_t id = 0;
        std::variant<PartCorrection, double> write;  ///< a part's corrections, or a dynamic X offset (mm)
    };

    /// `replyTimeout` > 0: how long a write waits for the device's side. Throws std::invalid_argument.
    explicit CorrectionRelay(std::chrono::milliseconds replyTimeout = std::chrono::seconds(5));
    ~CorrectionRelay() override;

    // ---- the loop's side ----
    /// The device's health as last published; Disconnected with the reason once closed.
    DeviceHealth health() const override;
    /// Queues the write, waits for the device's result. Refused at once when closed; refused when no reply
    /// comes in time (with whether it may have reached the CNC).
    OutputResult sendPartCorrection(const PartCorrection& correction) override;
    OutputResult sendDynamicOffset(double xOffsetMm) override;

    // ---- the device's side ----
    /// The output's health as the device's side sees it; what health() reports from now on.
    void publishHealth(DeviceHealth health);
    /// Called with the relay's lock held whenever a write is queued (from the loop's thread): it must only
    /// post a notification (e.g. a queued call into the device's thread), never call back into the relay.
    void setRequestListener(std::function<void()> listener);
    /// The oldest queued write; the device's side must reply() to it.
    std::optional<Request> takeRequest();
    /// The output's result for request `id`; a reply the loop no longer waits for is ignored.
    void reply(std::uint64_t id, OutputResult result);
    /// The device is gone (run over, page closed): a waiting write and every later one is refused with
    /// `reason`, and the listener is dropped (after close() returns it is never called again).
    void close(const std::string& reason);
    /// Whether close() was called.
    bool closed() const;

private:
    OutputResult forward(std::variant<PartCorrection, double> write, const std::string& what);

    const std::chrono::milliseconds m_timeout;
    mutable std::mutex m_mutex;
    std::condition_variable m_replied;
    DeviceHealth m_health{DeviceState::Connecting, "waiting for the CNC output"};
    std::deque<Request> m_queue;
    std::set<std::uint64_t> m_taken;  ///< taken by the device's side, reply not yet in
    std::map<std::uint64_t, OutputResult> m_replies;
    std::uint64_t m_nextId = 1;
    std::optional<std::string> m_closedReason;
    std::function<void()> m_listener;
};

}  // namespace tt::core
