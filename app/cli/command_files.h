#pragma once

#include <QByteArray>
#include <QString>
#include <string>

#include "app/cli/command.h"
#include "core/common/bounded_input.h"

namespace tt::cli {

/// The whole input file `path` a command reads (CSV, JSON) within `limits` (core/common/bounded_input.h:
/// tables 16 MiB, 1000000 lines of at most 4096 characters; documents 16 MiB); throws UsageError
/// "<path>: cannot read: <reason>" or "<path>: is larger than the limit of ... bytes" (exit 2).
QByteArray readInputFile(const QString& path, const core::InputLimits& limits = core::kTableLimits);

/// Writes `bytes` to the output file `path` (created or truncated); throws std::runtime_error
/// "cannot write <path>: <reason>" (exit 1: the work failed).
void writeOutputFile(const QString& path, const QByteArray& bytes);

/// Bad contents of the input file `path` (a bad row, too few points, ...): UsageError "<path>: <what>".
UsageError inputError(const QString& path, const std::string& what);

}  // namespace tt::cli
