#include "core/loop/operator_cycle.h"

#include <string>

namespace tt::core {

DeviceHealth OperatorCycle::health() const {
    return {DeviceState::Ready, "the operator confirms each finished part"};
}

OutputResult OperatorCycle::startPart(std::int64_t partNumber) {
    std::lock_guard lock(m_mutex);
    if (m_onMachine)
        return {false, "part " + std::to_string(*m_onMachine) + " is still on the machine; press Part finished first"};
    m_onMachine = partNumber;
    return {true, {}};
}

std::optional<FinishedPart> OperatorCycle::takeFinishedPart() {
    std::lock_guard lock(m_mutex);
    if (m_finished.empty()) return std::nullopt;
    FinishedPart part = m_finished.front();
    m_finished.pop_front();
    return part;
}

std::optional<std::int64_t> OperatorCycle::partOnMachine() const {
    std::lock_guard lock(m_mutex);
    return m_onMachine;
}

std::optional<std::int64_t> OperatorCycle::finishPart() {
    const double now = m_clock.nowS();
    std::lock_guard lock(m_mutex);
    if (!m_onMachine) return std::nullopt;
    const std::int64_t part = *m_onMachine;
    m_finished.push_back({part, now});
    m_onMachine.reset();
    return part;
}

}  // namespace tt::core
