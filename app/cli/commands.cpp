#include "app/cli/command.h"

namespace tt::cli {

// One factory per command, each in its own cmd_<name>.cpp.

const std::vector<Command>& commands() {
    static const std::vector<Command> all = {};
    return all;
}

}  // namespace tt::cli
