// trueturn: the operator terminal (GUI) by default; `trueturn <command>` runs the engine headless.

#include "app/cli/command.h"
#include "app/gui.h"

int main(int argc, char** argv) {
    const bool isCommand = argc > 1 && argv[1][0] != '-';
    return isCommand ? tt::cli::runCommand(argc, argv) : tt::app::runGui(argc, argv);
}
