#pragma once

#include <chrono>

#include "core/ports/clock.h"

namespace tt::devices {

/// The wall clock of real devices: monotonic seconds since the clock was made.
class SteadyClock final : public core::Clock {
public:
    SteadyClock() : m_origin(std::chrono::steady_clock::now()) {}
    double nowS() const override {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_origin).count();
    }

private:
    std::chrono::steady_clock::time_point m_origin;
};

}  // namespace tt::devices
