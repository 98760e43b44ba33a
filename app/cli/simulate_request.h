#pragma once

// `trueturn simulate`'s options that describe the run, turned into the one run request the Run page, a stored
// run and `--request FILE.json` also give (runtime/run/run_request.h).
#include <QString>
#include <optional>

#include "app/cli/command.h"
#include "runtime/run/run_request.h"

namespace tt::cli {

class CommandParser;

/// --preset, --delay, --parts, --warmup, --seed, --controller, --ewma-weight, --speed, --machine and the
/// plant, integral-action and mismatch options.
void addRunRequestOptions(CommandParser& parser);

/// The first option given that describes the run (a resumed run and a run from --request keep their own);
/// none when none is given.
std::optional<QString> runOptionGiven(const CommandParser& parser);

/// The run request the options make (with `database`, the --db value, and validated). Throws UsageError naming
/// the option.
runtime::RunRequest requestFromOptions(const CommandParser& parser, const QString& database);

/// A refused request field in the user's terms: the option that sets it ("--plant-gain: ...") when the
/// request came from options, else the field of `source` ("--request: plant_mismatch.gain_factor: ...").
UsageError usageErrorOf(const runtime::RunRequestError& error, const QString& source = QString());

}  // namespace tt::cli
