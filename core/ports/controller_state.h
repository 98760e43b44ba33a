#pragma once

#include <string>
#include <vector>

namespace tt::core {

/// Serialisable controller state, so a run can be resumed after a restart.
struct ControllerState {
    std::string kind;            ///< "lqg", "ewma", "open"
    std::vector<double> values;  ///< the controller's own layout
};

}  // namespace tt::core
