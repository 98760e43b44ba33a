#include "core/model/tool_table_csv.h"

#include <map>
#include <sstream>
#include <stdexcept>

namespace tt::core {

namespace {

// Splits one CSV record (no embedded newlines) honouring "quoted, fields" and "" escapes.
std::vector<std::string> splitRecord(std::string_view line, char separator, int lineNumber) {
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                field += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == separator) {
            fields.push_back(field);
            field.clear();
        } else if (c != '\r') {
            field += c;
        }
    }
    if (quoted) throw std::invalid_argument("line " + std::to_string(lineNumber) + ": a quote is not closed");
    fields.push_back(field);
    for (std::string& f : fields) {
        const auto first = f.find_first_not_of(" \t");
        f = first == std::string::npos ? std::string() : f.substr(first, f.find_last_not_of(" \t") - first + 1);
    }
    return fields;
}

std::string quoted(const std::string& text) {
    if (text.find_first_of(",;\"\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

// The order in which fields are set: the section before its dimensions, the measured stiffness
// before its date and author.
int setOrder(ToolField f) {
    switch (f) {
        case ToolField::Section:
            return 0;
        case ToolField::MeasuredOn:
        case ToolField::MeasuredBy:
            return 2;
        default:
            return 1;
    }
}

}  // namespace

std::vector<ToolCsvRow> parseToolCsv(std::string_view text) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    std::vector<ToolCsvRow> rows;
    std::vector<ToolField> columns;
    char separator = ',';
    std::map<std::string, int> seen;
    int lineNumber = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        const std::size_t end = text.find('\n', pos);
        const std::string_view line =
            text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
        pos = end == std::string_view::npos ? text.size() : end + 1;
        ++lineNumber;
        if (line.find_first_not_of(" \t\r") == std::string_view::npos || line.front() == '#') continue;
        if (columns.empty()) {
            separator =
                line.find(';') != std::string_view::npos && line.find(',') == std::string_view::npos ? ';' : ',';
            for (const std::string& key : splitRecord(line, separator, lineNumber))
                columns.push_back(toolFieldFromKey(key));
            bool hasId = false;
            for (ToolField f : columns)
                hasId = hasId || f == ToolField::Id;
            if (!hasId)
                throw std::invalid_argument("line " + std::to_string(lineNumber) + ": the header needs an id column");
            continue;
        }
        const std::vector<std::string> fields = splitRecord(line, separator, lineNumber);
        ToolCsvRow row;
        row.line = lineNumber;
        row.tool = defaultTool("");
        if (fields.size() != columns.size()) {
            row.problems.push_back("expected " + std::to_string(columns.size()) + " columns, got " +
                                   std::to_string(fields.size()));
        } else {
            for (int pass = 0; pass < 3; ++pass) {
                for (std::size_t i = 0; i < columns.size(); ++i) {
                    if (setOrder(columns[i]) != pass) continue;
                    if (fields[i].empty() && columns[i] != ToolField::Id && columns[i] != ToolField::MeasuredStiffness)
                        continue;  // keep the default / not applicable to the section
                    try {
                        setToolField(row.tool, columns[i], fields[i]);
                    } catch (const std::invalid_argument& e) {
                        row.problems.push_back(e.what());
                    }
                }
            }
            if (row.problems.empty())
                for (const std::string& p : validateTool(row.tool))
                    row.problems.push_back(p);
        }
        if (!row.tool.id.empty()) {
            const auto [it, inserted] = seen.emplace(row.tool.id, lineNumber);
            if (!inserted)
                throw std::invalid_argument("line " + std::to_string(lineNumber) + ": tool id '" + row.tool.id +
                                            "' is already on line " + std::to_string(it->second));
        }
        rows.push_back(std::move(row));
    }
    if (columns.empty())
        throw std::invalid_argument("the file is empty: expected a header such as id,name,section,...");
    return rows;
}

std::string toolsToCsv(const std::vector<ToolRecord>& tools) {
    std::ostringstream out;
    bool first = true;
    for (ToolField f : allToolFields()) {
        out << (first ? "" : ",") << toolFieldKey(f);
        first = false;
    }
    out << '\n';
    for (const ToolRecord& t : tools) {
        first = true;
        for (ToolField f : allToolFields()) {
            out << (first ? "" : ",") << quoted(toolFieldText(t, f));
            first = false;
        }
        out << '\n';
    }
    return out.str();
}

}  // namespace tt::core
