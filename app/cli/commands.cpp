#include "app/cli/command.h"

namespace tt::cli {

// One factory per command, each in its own cmd_<name>.cpp.
Command makeFitProfileCommand();

const std::vector<Command>& commands() {
    static const std::vector<Command> all = {
        makeFitProfileCommand(),
    };
    return all;
}

}  // namespace tt::cli
