#include "core/model/tool_table.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

std::string number(double v) {
    return formatSignificant(v, 10);
}

struct FieldInfo {
    ToolField field;
    const char* key;
    const char* label;  ///< for messages
    const char* unit;   ///< for messages, empty for text fields
};

constexpr FieldInfo kFields[] = {
    {ToolField::Id, "id", "id", ""},
    {ToolField::Name, "name", "name", ""},
    {ToolField::Section, "section", "section", ""},
    {ToolField::Diameter, "diameter_mm", "diameter d", "mm"},
    {ToolField::Width, "width_mm", "width b", "mm"},
    {ToolField::Height, "height_mm", "height h", "mm"},
    {ToolField::Overhang, "overhang_mm", "overhang l", "mm"},
    {ToolField::Material, "material", "material", ""},
    {ToolField::YoungsModulus, "youngs_modulus_mpa", "Young's modulus E", "MPa"},
    {ToolField::MeasuredStiffness, "measured_stiffness_n_per_mm", "measured stiffness", "N/mm"},
    {ToolField::MeasuredOn, "measured_on", "measured on", ""},
    {ToolField::MeasuredBy, "measured_by", "measured by", ""},
    {ToolField::CurrentToForceGain, "kp_n_per_a", "k_p", "N/A"},
};

const FieldInfo& info(ToolField field) {
    for (const FieldInfo& f : kFields)
        if (f.field == field) return f;
    throw std::invalid_argument("unknown tool field");
}

double parseNumber(const std::string& raw, ToolField field) {
    std::string text = trim(raw);
    for (char& c : text)
        if (c == ',') c = '.';
    const FieldInfo& f = info(field);
    double value = 0.0;
    const char* begin = text.data();
    const char* end = text.data() + text.size();
    if (!text.empty() && *begin == '+') ++begin;
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value))
        throw std::invalid_argument(std::string(f.label) + ": '" + trim(raw) + "' is not a number in " + f.unit);
    return value;
}

MeasuredStiffness& measurement(ToolRecord& tool, ToolField field) {
    if (!tool.measured)
        throw std::invalid_argument(std::string(info(field).label) + ": enter the measured stiffness first");
    return *tool.measured;
}

}  // namespace

const std::vector<ToolField>& allToolFields() {
    static const std::vector<ToolField> fields = [] {
        std::vector<ToolField> out;
        for (const FieldInfo& f : kFields)
            out.push_back(f.field);
        return out;
    }();
    return fields;
}

std::string toolFieldKey(ToolField field) {
    return info(field).key;
}

ToolField toolFieldFromKey(const std::string& key) {
    std::string valid;
    for (const FieldInfo& f : kFields) {
        if (key == f.key) return f.field;
        valid += (valid.empty() ? "" : ", ") + std::string(f.key);
    }
    throw std::invalid_argument("unknown column '" + key + "'; the columns are " + valid);
}

std::string toolFieldText(const ToolRecord& tool, ToolField field) {
    const bool round = tool.section.shape == SectionShape::Round;
    switch (field) {
        case ToolField::Id:
            return tool.id;
        case ToolField::Name:
            return tool.name;
        case ToolField::Section:
            return toString(tool.section.shape);
        case ToolField::Diameter:
            return round ? number(tool.section.diameterMm) : std::string();
        case ToolField::Width:
            return round ? std::string() : number(tool.section.widthMm);
        case ToolField::Height:
            return round ? std::string() : number(tool.section.heightMm);
        case ToolField::Overhang:
            return number(tool.overhangMm);
        case ToolField::Material:
            return tool.material;
        case ToolField::YoungsModulus:
            return number(tool.youngsModulusMpa);
        case ToolField::MeasuredStiffness:
            return tool.measured ? number(tool.measured->stiffnessNPerMm) : std::string();
        case ToolField::MeasuredOn:
            return tool.measured ? tool.measured->measuredOn : std::string();
        case ToolField::MeasuredBy:
            return tool.measured ? tool.measured->measuredBy : std::string();
        case ToolField::CurrentToForceGain:
            return number(tool.currentToForceGainNPerA);
    }
    return {};
}

void setToolField(ToolRecord& tool, ToolField field, const std::string& raw) {
    const std::string text = trim(raw);
    switch (field) {
        case ToolField::Id:
            if (text.empty()) throw std::invalid_argument("id: must not be empty");
            tool.id = text;
            return;
        case ToolField::Name:
            tool.name = text;
            return;
        case ToolField::Section: {
            const SectionShape shape = sectionShapeFromString(text);
            if (shape == tool.section.shape) return;
            // Keep the size: a round bar of d becomes d × d and back.
            tool.section =
                shape == SectionShape::Round
                    ? HolderSection::round(tool.section.heightMm > 0 ? tool.section.heightMm : 40.0)
                    : HolderSection::rectangular(tool.section.diameterMm > 0 ? tool.section.diameterMm : 40.0,
                                                 tool.section.diameterMm > 0 ? tool.section.diameterMm : 40.0);
            return;
        }
        case ToolField::Diameter:
            if (tool.section.shape != SectionShape::Round)
                throw std::invalid_argument("diameter d: the section is rectangular; set width b and height h");
            tool.section.diameterMm = parseNumber(text, field);
            return;
        case ToolField::Width:
        case ToolField::Height:
            if (tool.section.shape != SectionShape::Rectangular)
                throw std::invalid_argument(std::string(info(field).label) +
                                            ": the section is round; set the diameter d");
            (field == ToolField::Width ? tool.section.widthMm : tool.section.heightMm) = parseNumber(text, field);
            return;
        case ToolField::Overhang:
            tool.overhangMm = parseNumber(text, field);
            return;
        case ToolField::Material:
            if (text.empty()) throw std::invalid_argument("material: must not be empty");
            tool.material = text;
            return;
        case ToolField::YoungsModulus:
            tool.youngsModulusMpa = parseNumber(text, field);
            return;
        case ToolField::MeasuredStiffness:
            if (text.empty()) {
                tool.measured.reset();
                return;
            }
            if (!tool.measured) tool.measured = MeasuredStiffness{};
            tool.measured->stiffnessNPerMm = parseNumber(text, field);
            return;
        case ToolField::MeasuredOn:
            if (text.empty() && !tool.measured) return;
            measurement(tool, field).measuredOn = text;
            return;
        case ToolField::MeasuredBy:
            if (text.empty() && !tool.measured) return;
            measurement(tool, field).measuredBy = text;
            return;
        case ToolField::CurrentToForceGain:
            tool.currentToForceGainNPerA = parseNumber(text, field);
            return;
    }
}

std::vector<ToolFieldChange> diffTool(const ToolRecord& before, const ToolRecord& after) {
    std::vector<ToolFieldChange> changes;
    for (ToolField f : allToolFields()) {
        std::string a = toolFieldText(before, f);
        std::string b = toolFieldText(after, f);
        if (a != b) changes.push_back({f, std::move(a), std::move(b)});
    }
    return changes;
}

ToolRecord defaultTool(const std::string& id) {
    ToolRecord t;
    t.id = id;
    t.section = HolderSection::round(40.0);
    t.overhangMm = 200.0;
    t.material = "Steel";
    t.youngsModulusMpa = 210'000.0;
    t.currentToForceGainNPerA = 100.0;
    return t;
}

}  // namespace tt::core
