#pragma once

#include <QByteArray>
#include <QString>
#include <string>

#include "app/cli/command.h"

namespace tt::cli {

/// The whole input file `path` a command reads (CSV, JSON); throws UsageError "cannot read <path>:
/// <reason>" (exit 2: the user named a file that cannot be read).
QByteArray readInputFile(const QString& path);

/// Writes `bytes` to the output file `path` (created or truncated); throws std::runtime_error
/// "cannot write <path>: <reason>" (exit 1: the work failed).
void writeOutputFile(const QString& path, const QByteArray& bytes);

/// Bad contents of the input file `path` (a bad row, too few points, ...): UsageError "<path>: <what>".
UsageError inputError(const QString& path, const std::string& what);

}  // namespace tt::cli
