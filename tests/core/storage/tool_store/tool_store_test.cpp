// The tool stiffness table over SQL, on SQLite and PostgreSQL: edits applied in one transaction
// with an audit entry per changed field (who, when, old, new); a bad edit stores nothing.
#include "core/storage/tool_store.h"

#include <gtest/gtest.h>

#include <QSqlQuery>

#include "core/model/tool_table.h"
#include "scratch_database.h"

namespace tt::storage {
namespace {

core::ToolRecord bar(const std::string& id, double diameterMm, double overhangMm) {
    core::ToolRecord t = core::defaultTool(id);
    t.name = "Boring bar " + id;
    t.section = core::HolderSection::round(diameterMm);
    t.overhangMm = overhangMm;
    t.currentToForceGainNPerA = 150.0;
    return t;
}

qint64 count(Database& db, const char* table) {
    QSqlQuery q = db.exec(QStringLiteral("SELECT COUNT(*) FROM ") + QString::fromLatin1(table));
    return q.next() ? q.value(0).toLongLong() : -1;
}

class ToolStoreTest : public ::testing::TestWithParam<std::string> {};

TEST_P(ToolStoreTest, SeedsTheMaterialsAndStoresToolsExactly) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    ToolStore store(db);
    EXPECT_EQ(db.schemaVersion(QStringLiteral("tools")), 1);
    const std::vector<core::Material> materials = store.materials();
    ASSERT_EQ(materials.size(), core::defaultMaterials().size());
    EXPECT_EQ(materials.front().name, "Cemented carbide");  // ordered by name
    core::ToolRecord measured = bar("T12", 80.0, 800.0);
    measured.measured = core::MeasuredStiffness{2300.0, "2025-03-14", "I. Petrenko"};
    core::ToolRecord shank = core::defaultTool("T03");
    shank.section = core::HolderSection::rectangular(40.0, 60.0);
    store.apply({{std::nullopt, measured}, {std::nullopt, shank}}, QStringLiteral("O. Kovalenko"));
    const std::vector<core::ToolRecord> tools = store.tools();
    ASSERT_EQ(tools.size(), 2u);
    EXPECT_EQ(tools[0].id, "T03");
    EXPECT_EQ(tools[0].section.shape, core::SectionShape::Rectangular);
    EXPECT_DOUBLE_EQ(tools[0].section.heightMm, 60.0);
    EXPECT_FALSE(tools[0].measured);
    EXPECT_TRUE(core::diffTool(tools[1], measured).empty());
    EXPECT_DOUBLE_EQ(core::effectiveStiffnessNPerMm(tools[1]), 2300.0);
}

TEST_P(ToolStoreTest, AuditsEveryAppliedFieldWithWhoWhenOldAndNew) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    ToolStore store(db);
    store.apply({{std::nullopt, bar("T1", 40.0, 400.0)}}, QStringLiteral("Anna"));
    core::ToolRecord longer = bar("T1", 40.0, 450.0);
    longer.currentToForceGainNPerA = 160.0;
    const std::vector<ToolAuditEntry> entries = store.apply({{std::string("T1"), longer}}, QStringLiteral("Boris"));
    ASSERT_EQ(entries.size(), 2u);
    EXPECT_EQ(entries[0].subject, QStringLiteral("T1"));
    EXPECT_EQ(entries[0].field, QStringLiteral("overhang_mm"));
    EXPECT_EQ(entries[0].before, QStringLiteral("400"));
    EXPECT_EQ(entries[0].after, QStringLiteral("450"));
    EXPECT_EQ(entries[1].field, QStringLiteral("kp_n_per_a"));
    EXPECT_EQ(entries[0].changedBy, QStringLiteral("Boris"));
    EXPECT_FALSE(entries[0].changedAt.isEmpty());
    // Rename and remove are audited too; the newest entries come first.
    store.apply({{std::string("T1"),
                  [&] {
                      core::ToolRecord t = longer;
                      t.id = "T1A";
                      return t;
                  }()}},
                QStringLiteral("Boris"));
    store.apply({{std::string("T1A"), std::nullopt}}, QStringLiteral("Chen"));
    const std::vector<ToolAuditEntry> log = store.audit();
    EXPECT_EQ(log.front().changedBy, QStringLiteral("Chen"));
    EXPECT_TRUE(log.front().after.isEmpty());
    bool renamed = false;
    for (const ToolAuditEntry& e : log)
        renamed = renamed || (e.field == QStringLiteral("id") && e.before == QStringLiteral("T1") &&
                              e.after == QStringLiteral("T1A"));
    EXPECT_TRUE(renamed);
    EXPECT_TRUE(store.tools().empty());
}

TEST_P(ToolStoreTest, ABadEditStoresNothing) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    ToolStore store(db);
    store.apply({{std::nullopt, bar("T1", 40.0, 400.0)}}, QStringLiteral("Anna"));
    const qint64 audited = count(db, "tool_audit");
    // A valid change together with an invalid new tool: neither is stored.
    core::ToolRecord invalid = bar("T2", 40.0, 0.0);
    EXPECT_THROW(
        store.apply({{std::string("T1"), bar("T1", 50.0, 400.0)}, {std::nullopt, invalid}}, QStringLiteral("Anna")),
        std::invalid_argument);
    // Two tools with one id, detected inside the transaction: rolled back.
    EXPECT_THROW(store.apply({{std::string("T1"), bar("T1", 50.0, 400.0)}, {std::nullopt, bar("T1", 60.0, 300.0)}},
                             QStringLiteral("Anna")),
                 std::invalid_argument);
    EXPECT_THROW(store.apply({{std::string("T9"), bar("T9", 50.0, 400.0)}}, QStringLiteral("Anna")),
                 std::invalid_argument);
    EXPECT_THROW(store.apply({{std::nullopt, bar("T5", 50.0, 400.0)}}, QStringLiteral("  ")), std::invalid_argument);
    ASSERT_EQ(store.tools().size(), 1u);
    EXPECT_DOUBLE_EQ(store.tools()[0].section.diameterMm, 40.0);
    EXPECT_EQ(count(db, "tool_audit"), audited);
}

TEST_P(ToolStoreTest, EditsTheMaterialsListWithAudit) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    ToolStore store(db);
    store.saveMaterial({"Steel", 205'000.0}, QStringLiteral("Anna"));
    store.saveMaterial({"Titanium alloy", 114'000.0}, QStringLiteral("Anna"));
    store.removeMaterial("Grey cast iron", QStringLiteral("Anna"));
    const std::vector<core::Material> m = store.materials();
    ASSERT_EQ(m.size(), core::defaultMaterials().size());
    EXPECT_EQ(m[1].name, "Steel");
    EXPECT_DOUBLE_EQ(m[1].youngsModulusMpa, 205'000.0);
    const std::vector<ToolAuditEntry> log = store.audit();
    ASSERT_EQ(log.size(), 3u);
    EXPECT_EQ(log[2].subject, QStringLiteral("material Steel"));
    EXPECT_EQ(log[2].before, QStringLiteral("210000"));
    EXPECT_EQ(log[2].after, QStringLiteral("205000"));
    EXPECT_THROW(store.saveMaterial({"Foam", 10.0}, QStringLiteral("Anna")), std::invalid_argument);
    EXPECT_THROW(store.removeMaterial("Unobtainium", QStringLiteral("Anna")), std::invalid_argument);
}

TEST_P(ToolStoreTest, KeepsTheTableAcrossReopening) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    {
        Database db(scratch.config());
        ToolStore store(db);
        store.apply({{std::nullopt, bar("T7", 63.0, 630.0)}}, QStringLiteral("Anna"));
    }
    Database db(scratch.config());
    ToolStore store(db);
    ASSERT_EQ(store.tools().size(), 1u);
    EXPECT_DOUBLE_EQ(store.tools()[0].section.diameterMm, 63.0);
    EXPECT_EQ(store.materials().size(), core::defaultMaterials().size());  // seeded once
}

INSTANTIATE_TEST_SUITE_P(Backends, ToolStoreTest, ::testing::ValuesIn(test::backends()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tt::storage
