#pragma once

namespace tt::core {

/// Time source of the engine. The simulator runs a scaled clock (one part = 6 min at speed 1);
/// devices and the GUI use the wall clock. Seconds since an arbitrary, fixed origin.
class Clock {
public:
    virtual ~Clock() = default;
    /// Current time, s.
    virtual double nowS() const = 0;
};

}  // namespace tt::core
