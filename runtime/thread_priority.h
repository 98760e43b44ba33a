#pragma once

namespace tt::runtime {

/// Asks the system to run the calling thread before the other work of the terminal and of the machine: the
/// lowest real-time priority (SCHED_FIFO 1; the compensation's cycle and the device thread's pumps take
/// microseconds, so they never starve anything), else a nice level of −10, else nothing changes (the system
/// does not allow it: the thread runs at the normal priority).
void preferThisThread();

}  // namespace tt::runtime
