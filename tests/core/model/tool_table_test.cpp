// Tool-table fields as text (what the editor, the CSV files and the audit record use).
#include "core/model/tool_table.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "core/model/tool_table_csv.h"

namespace tt::core {
namespace {

TEST(ToolTable, FieldsRoundTripThroughText) {
    ToolRecord t = defaultTool("T12");
    setToolField(t, ToolField::Diameter, " 80,5 ");  // comma as decimal point from the keypad
    EXPECT_DOUBLE_EQ(t.section.diameterMm, 80.5);
    EXPECT_EQ(toolFieldText(t, ToolField::Diameter), "80.5");
    EXPECT_EQ(toolFieldText(t, ToolField::Width), "");  // not applicable to a round bar
    setToolField(t, ToolField::Section, "rectangular");
    EXPECT_DOUBLE_EQ(t.section.widthMm, 80.5);  // the size is kept
    setToolField(t, ToolField::Height, "60");
    EXPECT_EQ(toolFieldText(t, ToolField::Diameter), "");
    setToolField(t, ToolField::MeasuredStiffness, "2300");
    setToolField(t, ToolField::MeasuredOn, "2025-03-14");
    setToolField(t, ToolField::MeasuredBy, "I. Petrenko");
    EXPECT_TRUE(validateTool(t).empty());
    setToolField(t, ToolField::MeasuredStiffness, "");
    EXPECT_FALSE(t.measured);
    for (ToolField f : allToolFields())
        EXPECT_EQ(toolFieldFromKey(toolFieldKey(f)), f);
}

TEST(ToolTable, RefusesTextThatIsNotAValueWithTheUnit) {
    ToolRecord t = defaultTool("T1");
    auto message = [&](ToolField f, const std::string& text) {
        try {
            setToolField(t, f, text);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message(ToolField::Overhang, "abc"), "overhang l: 'abc' is not a number in mm");
    EXPECT_EQ(message(ToolField::YoungsModulus, "2e5x"), "Young's modulus E: '2e5x' is not a number in MPa");
    EXPECT_EQ(message(ToolField::Width, "40"), "width b: the section is round; set the diameter d");
    EXPECT_EQ(message(ToolField::MeasuredBy, "Anna"), "measured by: enter the measured stiffness first");
    EXPECT_EQ(message(ToolField::Id, "  "), "id: must not be empty");
    EXPECT_EQ(message(ToolField::Section, "square"), "section 'square' must be 'round' or 'rectangular'");
}

TEST(ToolTable, DiffListsChangedFieldsInOrder) {
    const ToolRecord a = defaultTool("T1");
    ToolRecord b = a;
    b.overhangMm = 250.0;
    b.currentToForceGainNPerA = 120.0;
    const std::vector<ToolFieldChange> d = diffTool(a, b);
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[0].field, ToolField::Overhang);
    EXPECT_EQ(d[0].before, "200");
    EXPECT_EQ(d[0].after, "250");
    EXPECT_EQ(d[1].field, ToolField::CurrentToForceGain);
}

TEST(ToolTableCsv, WritesAndReadsBackEveryColumn) {
    ToolRecord a = defaultTool("T1");
    a.name = "Bar, \"heavy\"";  // needs quoting
    ToolRecord b = defaultTool("T2");
    b.section = HolderSection::rectangular(40.0, 60.0);
    b.measured = MeasuredStiffness{16000.0, "2025-01-02", "Anna"};
    const std::vector<ToolCsvRow> rows = parseToolCsv(toolsToCsv({a, b}));
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_TRUE(rows[0].problems.empty());
    EXPECT_TRUE(diffTool(rows[0].tool, a).empty());
    EXPECT_TRUE(diffTool(rows[1].tool, b).empty());
    EXPECT_EQ(rows[1].line, 3);
}

TEST(ToolTableCsv, ReportsRowProblemsAndRefusesABadHeader) {
    const std::vector<ToolCsvRow> rows =
        parseToolCsv("id;overhang_mm;diameter_mm\n# a comment\nT1;300;40\nT2;abc;40\nT3;0;40\n");
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_TRUE(rows[0].problems.empty());
    ASSERT_EQ(rows[1].problems.size(), 1u);
    EXPECT_EQ(rows[1].problems[0], "overhang l: 'abc' is not a number in mm");
    EXPECT_EQ(rows[1].line, 4);
    EXPECT_EQ(rows[2].problems[0], "overhang l: 0 mm must be between 10 and 5000 mm");
    EXPECT_THROW(parseToolCsv("id,colour\nT1,red\n"), std::invalid_argument);
    EXPECT_THROW(parseToolCsv("name\nbar\n"), std::invalid_argument);
    EXPECT_THROW(parseToolCsv(""), std::invalid_argument);
    try {
        parseToolCsv("id\nT1\nT1\n");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "line 3: tool id 'T1' is already on line 2");
    }
}

}  // namespace
}  // namespace tt::core
