#include "core/loop/correction_relay.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

std::string secondsText(std::chrono::milliseconds ms) {
    return formatFixed(static_cast<double>(ms.count()) / 1000.0, 1) + " s";
}

}  // namespace

CorrectionRelay::CorrectionRelay(std::chrono::milliseconds replyTimeout) : m_timeout(replyTimeout) {
    if (replyTimeout.count() <= 0) throw std::invalid_argument("the CNC output's reply timeout must be positive");
}

CorrectionRelay::~CorrectionRelay() {
    close("the CNC output is no longer connected to the loop");
}

DeviceHealth CorrectionRelay::health() const {
    std::lock_guard lock(m_mutex);
    if (m_closedReason) return {DeviceState::Disconnected, *m_closedReason};
    return m_health;
}

OutputResult CorrectionRelay::sendPartCorrection(const PartCorrection& correction) {
    return forward(correction, "the corrections for part " + std::to_string(correction.partNumber));
}

OutputResult CorrectionRelay::sendDynamicOffset(double xOffsetMm) {
    return forward(xOffsetMm, "the X offset of " + formatFixed(xOffsetMm, 4) + " mm");
}

OutputResult CorrectionRelay::forward(std::variant<PartCorrection, double> write, const std::string& what) {
    std::unique_lock lock(m_mutex);
    if (m_closedReason) return {false, *m_closedReason + "; not sent: " + what};
    const std::uint64_t id = m_nextId++;
    m_queue.push_back({id, std::move(write)});
    if (m_listener) m_listener();
    m_replied.wait_for(lock, m_timeout, [&] { return m_replies.count(id) > 0 || m_closedReason.has_value(); });
    if (auto it = m_replies.find(id); it != m_replies.end()) {
        OutputResult result = std::move(it->second);
        m_replies.erase(it);
        return result;
    }
    // No reply: withdraw the write. Still queued means it never reached the output.
    const auto queued = std::find_if(m_queue.begin(), m_queue.end(), [id](const Request& r) { return r.id == id; });
    const bool neverSent = queued != m_queue.end();
    if (neverSent) m_queue.erase(queued);
    m_taken.erase(id);
    if (m_closedReason)
        return {false, *m_closedReason + (neverSent ? "; not sent: " + what
                                                    : "; not confirmed: " + what + " (check on the CNC what arrived)")};
    if (neverSent)
        return {false, "not sent: the CNC output did not take " + what + " within " + secondsText(m_timeout)};
    return {false, "the CNC output did not confirm " + what + " within " + secondsText(m_timeout) +
                       " (check on the CNC what arrived)"};
}

void CorrectionRelay::publishHealth(DeviceHealth health) {
    std::lock_guard lock(m_mutex);
    m_health = std::move(health);
}

void CorrectionRelay::setRequestListener(std::function<void()> listener) {
    std::lock_guard lock(m_mutex);
    if (!m_closedReason) m_listener = std::move(listener);
}

std::optional<CorrectionRelay::Request> CorrectionRelay::takeRequest() {
    std::lock_guard lock(m_mutex);
    if (m_queue.empty() || m_closedReason) return std::nullopt;
    Request r = std::move(m_queue.front());
    m_queue.pop_front();
    m_taken.insert(r.id);
    return r;
}

void CorrectionRelay::reply(std::uint64_t id, OutputResult result) {
    {
        std::lock_guard lock(m_mutex);
        if (m_taken.erase(id) == 0) return;  // the loop gave up waiting for it
        m_replies[id] = std::move(result);
    }
    m_replied.notify_all();
}

void CorrectionRelay::close(const std::string& reason) {
    {
        std::lock_guard lock(m_mutex);
        if (!m_closedReason) m_closedReason = reason;
        m_listener = {};  // waiting writes withdraw their own requests
    }
    m_replied.notify_all();
}

bool CorrectionRelay::closed() const {
    std::lock_guard lock(m_mutex);
    return m_closedReason.has_value();
}

}  // namespace tt::core
