#pragma once

#include <cstdint>

namespace tt::core::auth {

/// Limits of the idle log-out setting, minutes.
inline constexpr int kMinIdleMinutes = 1;
inline constexpr int kMaxIdleMinutes = 480;
inline constexpr int kDefaultIdleMinutes = 10;

/// The automatic log-out after the terminal has been idle (no key, touch or click) for a set time.
/// Time comes from the caller (milliseconds of a monotonic clock), so tests inject it.
class IdleLogout {
public:
    /// Throws std::invalid_argument when `idleMinutes` is outside kMinIdleMinutes .. kMaxIdleMinutes.
    explicit IdleLogout(int idleMinutes);
    /// The user did something at `nowMs`.
    void touch(std::int64_t nowMs);
    /// Whether the user must be logged out at `nowMs` (idle for the whole set time).
    bool expired(std::int64_t nowMs) const;
    /// Milliseconds left before the log-out (0 when expired).
    std::int64_t remainingMs(std::int64_t nowMs) const;
    /// The set time, minutes.
    int idleMinutes() const { return m_idleMinutes; }

private:
    int m_idleMinutes;
    std::int64_t m_lastActivityMs = 0;
};

}  // namespace tt::core::auth
