#include "core/auth/lockout.h"

#include <stdexcept>
#include <string>

namespace tt::core::auth {

void checkPolicy(const LockoutPolicy& policy) {
    if (policy.maxFailures < 1 || policy.maxFailures > kMaxFailuresLimit)
        throw std::invalid_argument("failed log-ins before the lock-out must be between 1 and " +
                                    std::to_string(kMaxFailuresLimit) + " (got " + std::to_string(policy.maxFailures) +
                                    ")");
    if (policy.lockSeconds < kMinLockSeconds || policy.lockSeconds > kMaxLockSeconds)
        throw std::invalid_argument("the lock-out must last between " + std::to_string(kMinLockSeconds) + " and " +
                                    std::to_string(kMaxLockSeconds) + " s (got " + std::to_string(policy.lockSeconds) +
                                    " s)");
}

bool isLocked(const LockoutState& state, std::int64_t nowS) {
    return state.lockedUntilS > nowS;
}

LockoutState afterFailure(LockoutState state, const LockoutPolicy& policy, std::int64_t nowS) {
    if (isLocked(state, nowS)) return state;  // an attempt while locked is not counted and extends nothing
    state.lockedUntilS = 0;
    if (++state.failures >= policy.maxFailures) {
        state.failures = 0;
        state.lockedUntilS = nowS + policy.lockSeconds;
    }
    return state;
}

LockoutState afterSuccess() {
    return {};
}

int attemptsLeft(const LockoutState& state, const LockoutPolicy& policy, std::int64_t nowS) {
    if (isLocked(state, nowS)) return 0;
    return policy.maxFailures - state.failures;
}

}  // namespace tt::core::auth
