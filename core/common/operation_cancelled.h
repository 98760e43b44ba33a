#pragma once

#include <stdexcept>

namespace tt::core {

/// Thrown by long engine work (training, studies) when its progress callback asks it to stop; the
/// caller keeps what it had before the work started.
class OperationCancelled : public std::runtime_error {
public:
    OperationCancelled() : std::runtime_error("cancelled") {}
};

}  // namespace tt::core
