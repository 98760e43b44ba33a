#pragma once

namespace tt::app {

/// Starts the operator terminal (GUI). Handles --version, --help and the GUI options; exits 2
/// with a one-line reason on an unknown option.
int runGui(int argc, char** argv);

}  // namespace tt::app
