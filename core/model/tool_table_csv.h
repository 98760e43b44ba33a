#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/model/tool_table.h"

namespace tt::core {

/// One row of an imported tool-table CSV file.
struct ToolCsvRow {
    int line = 0;                       ///< line number in the file
    ToolRecord tool;                    ///< the row (defaults for columns the file does not have)
    std::vector<std::string> problems;  ///< parse and validation problems; empty when importable
};

/// Reads a tool table from CSV: a header of field keys (toolFieldKey: id, name, section,
/// diameter_mm, ..., kp_n_per_a; `id` required, others optional, any order), ',' or ';'
/// separated, fields may be quoted ("..." with "" for a quote). Rows that cannot be read are
/// returned with their problems, so a preview can show them. Throws std::invalid_argument for a
/// file without a usable header (naming the unknown column) or with two rows of the same id.
std::vector<ToolCsvRow> parseToolCsv(std::string_view text);

/// Writes tools as CSV with every column (what parseToolCsv reads back unchanged).
std::string toolsToCsv(const std::vector<ToolRecord>& tools);

}  // namespace tt::core
