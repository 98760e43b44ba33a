#include "core/auth/idle_logout.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace tt::core::auth {

IdleLogout::IdleLogout(int idleMinutes) : m_idleMinutes(idleMinutes) {
    if (idleMinutes < kMinIdleMinutes || idleMinutes > kMaxIdleMinutes)
        throw std::invalid_argument("the idle time before the automatic log-out must be between " +
                                    std::to_string(kMinIdleMinutes) + " and " + std::to_string(kMaxIdleMinutes) +
                                    " min (got " + std::to_string(idleMinutes) + " min)");
}

void IdleLogout::touch(std::int64_t nowMs) {
    m_lastActivityMs = std::max(m_lastActivityMs, nowMs);
}

std::int64_t IdleLogout::remainingMs(std::int64_t nowMs) const {
    const std::int64_t limitMs = static_cast<std::int64_t>(m_idleMinutes) * 60'000;
    return std::max<std::int64_t>(0, m_lastActivityMs + limitMs - nowMs);
}

bool IdleLogout::expired(std::int64_t nowMs) const {
    return remainingMs(nowMs) == 0;
}

}  // namespace tt::core::auth
