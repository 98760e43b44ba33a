#pragma once

#include <cstdint>

namespace tt::core::auth {

/// After how many failed log-ins in a row a user is locked out, and for how long. Limits:
/// 1 .. kMaxFailuresLimit failures, kMinLockSeconds .. kMaxLockSeconds.
struct LockoutPolicy {
    int maxFailures = 5;
    std::int64_t lockSeconds = 300;
};
inline constexpr int kMaxFailuresLimit = 20;
inline constexpr std::int64_t kMinLockSeconds = 10;
inline constexpr std::int64_t kMaxLockSeconds = 24 * 3600;

/// Throws std::invalid_argument when a value of `policy` is outside its limits (naming it).
void checkPolicy(const LockoutPolicy& policy);

/// One user's failed log-ins: how many in a row, and until when (Unix seconds) they are locked out
/// (0 = not locked).
struct LockoutState {
    int failures = 0;
    std::int64_t lockedUntilS = 0;
};

/// Whether the user may not try now (`nowS` Unix seconds, from the caller's clock).
bool isLocked(const LockoutState& state, std::int64_t nowS);
/// The state after a failed log-in at `nowS`: one more failure; at the policy's count the user is
/// locked until nowS + lockSeconds and the count starts again.
LockoutState afterFailure(LockoutState state, const LockoutPolicy& policy, std::int64_t nowS);
/// The state after a successful log-in (nothing counted, not locked).
LockoutState afterSuccess();
/// Failed attempts left before the lock-out (0 when locked).
int attemptsLeft(const LockoutState& state, const LockoutPolicy& policy, std::int64_t nowS);

}  // namespace tt::core::auth
