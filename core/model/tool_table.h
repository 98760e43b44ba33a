#pragma once

#include <string>
#include <vector>

#include "core/model/tool_stiffness.h"

namespace tt::core {

/// The editable fields of a tool-table row, in table and CSV column order.
enum class ToolField {
    Id,
    Name,
    Section,
    Diameter,
    Width,
    Height,
    Overhang,
    Material,
    YoungsModulus,
    MeasuredStiffness,
    MeasuredOn,
    MeasuredBy,
    CurrentToForceGain,
};

/// Every field, in order.
const std::vector<ToolField>& allToolFields();

/// Stable key of a field, used as the CSV column and in the audit record ("diameter_mm").
std::string toolFieldKey(ToolField field);
/// The field with that key; throws std::invalid_argument naming the valid keys.
ToolField toolFieldFromKey(const std::string& key);

/// The field's value as text, as stored and shown ("80", "round", "" when it does not apply:
/// width of a round bar, measured values when there is no measurement). Numbers with up to 10
/// significant digits, '.' as decimal point.
std::string toolFieldText(const ToolRecord& tool, ToolField field);

/// Sets the field from text (trimmed; ',' accepted as the decimal point). An empty measured
/// stiffness removes the measurement; measured date/by need a measured stiffness. Throws
/// std::invalid_argument in the user's terms ("overhang l: 'abc' is not a number in mm").
/// Range checks are validateTool's job, so a half-entered row can still be edited.
void setToolField(ToolRecord& tool, ToolField field, const std::string& text);

/// One field that differs between two versions of a tool (for the audit record).
struct ToolFieldChange {
    ToolField field = ToolField::Id;
    std::string before;
    std::string after;
};

/// The fields whose text differs, in field order.
std::vector<ToolFieldChange> diffTool(const ToolRecord& before, const ToolRecord& after);

/// A new tool with sensible defaults (steel round bar D40, overhang 200 mm, k_p 100 N/A).
ToolRecord defaultTool(const std::string& id);

}  // namespace tt::core
