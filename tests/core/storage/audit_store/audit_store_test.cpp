// The audit trail over SQL, on SQLite and PostgreSQL: own records, tool changes and calibrations
// folded into one trail with who, when, old and new; the filter; the CSV export.
#include "core/storage/audit_store.h"

#include <gtest/gtest.h>

#include "audit_filter_of.h"
#include "core/model/tool_table.h"
#include "core/storage/calibration_store.h"
#include "core/storage/tool_store.h"
#include "scratch_database.h"

namespace tt::storage {
namespace {

using test::filterOf;

class AuditStoreTest : public ::testing::TestWithParam<std::string> {};

TEST_P(AuditStoreTest, ToolChangesCalibrationsAndSettingsInOneTrailNewestFirst) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    AuditStore audit(db);
    ToolStore tools(db);
    CalibrationStore calibration(db);
    core::ToolRecord t = core::defaultTool("T7");
    t.overhangMm = 300.0;
    tools.apply({{std::nullopt, t}}, QStringLiteral("Olga"));
    t.overhangMm = 350.0;
    tools.apply({{std::string("T7"), t}}, QStringLiteral("Olga"));
    KpCalibrationRecord kp;
    kp.createdBy = QStringLiteral("Boris");
    kp.drive = QStringLiteral("X");
    kp.kpNPerA = 150.0;
    kp.pointsCsv = QStringLiteral("load_n,current_difference_a\n100,0.667\n");
    kp.appliedTo = QStringLiteral("");
    calibration.saveKp(kp);
    kp.kpNPerA = 152.5;
    calibration.saveKp(kp);
    audit.record({audit_category::kController, QStringLiteral("controller"), QStringLiteral("ewma_lambda"),
                  QStringLiteral("0.3"), QStringLiteral("0.4")},
                 QStringLiteral("Olga"), QStringLiteral("engineer"));

    const std::vector<AuditRecord> all = audit.query();
    ASSERT_FALSE(all.empty());
    const std::vector<AuditRecord> controller = audit.query(filterOf(audit_category::kController));
    ASSERT_EQ(controller.size(), 1u);
    EXPECT_EQ(controller[0].role.toStdString(), "engineer");
    EXPECT_EQ(controller[0].change.before.toStdString(), "0.3");
    EXPECT_EQ(controller[0].change.after.toStdString(), "0.4");
    // Newest first across the sources (records of one millisecond in any order).
    for (std::size_t i = 1; i < all.size(); ++i)
        EXPECT_GE(all[i - 1].changedAt, all[i].changedAt);

    const std::vector<AuditRecord> overhang = audit.query(filterOf(audit_category::kTool, QStringLiteral("overhang")));
    ASSERT_EQ(overhang.size(), 2u);
    EXPECT_EQ(overhang[0].change.subject, QStringLiteral("T7"));
    EXPECT_EQ(overhang[0].change.before, QStringLiteral("300"));
    EXPECT_EQ(overhang[0].change.after, QStringLiteral("350"));
    EXPECT_EQ(overhang[0].changedBy, QStringLiteral("Olga"));
    EXPECT_EQ(overhang[1].change.before, QString());  // the tool was added

    const std::vector<AuditRecord> kps = audit.query(filterOf(audit_category::kCalibration));
    ASSERT_EQ(kps.size(), 2u);
    EXPECT_EQ(kps[0].change.subject, QStringLiteral("drive X"));
    EXPECT_EQ(kps[0].change.before, QStringLiteral("150"));
    EXPECT_EQ(kps[0].change.after, QStringLiteral("152.5"));
    EXPECT_EQ(kps[1].change.before, QString());

    // The time filter: nothing before the first record, everything up to a time after the last.
    EXPECT_TRUE(audit.query(filterOf({}, {}, {}, all.back().changedAt)).empty());
    EXPECT_EQ(audit.query(filterOf({}, {}, all.back().changedAt, QStringLiteral("9999"))).size(), all.size());
    EXPECT_EQ(audit.query(filterOf({}, {}, {}, {}, 1)).size(), 1u);
    EXPECT_THROW(audit.query(filterOf({}, {}, {}, {}, 0)), std::invalid_argument);
}

TEST(AuditCsv, QuotesAndNeutralisesFormulas) {
    // RFC 4180: a cell with a comma, quote or line break is quoted, quotes doubled; CRLF line ends.
    AuditRecord r{1,
                  QStringLiteral("2026-11-25T23:40:00.000Z"),
                  QStringLiteral("Olga"),
                  QStringLiteral("engineer"),
                  {audit_category::kSetting, QStringLiteral("terminal"), QStringLiteral("note"),
                   QStringLiteral("a, \"b\""), QStringLiteral("=1+1")}};
    EXPECT_EQ(
        auditCsv({r}),
        QStringLiteral("when_utc,who,role,category,subject,field,old_value,new_value\r\n"
                       "2026-11-25T23:40:00.000Z,Olga,engineer,setting,terminal,note,\"a, \"\"b\"\"\",'=1+1\r\n"));
}

TEST_P(AuditStoreTest, LongValuesAreCutAndEmptyFieldsRefused) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    AuditStore audit(db);
    const AuditRecord r = audit.record({audit_category::kSetting, QStringLiteral("s"), QStringLiteral("f"), QString(),
                                        QString(10000, QLatin1Char('x'))},
                                       QStringLiteral("Olga"), QString());
    EXPECT_EQ(r.change.after.size(), kMaxAuditValueChars - 40 + QStringLiteral("… (10000 characters)").size());
    EXPECT_THROW(
        audit.record({audit_category::kSetting, QString(), QStringLiteral("f"), {}, {}}, QStringLiteral("O"), {}),
        std::invalid_argument);
    EXPECT_THROW(
        audit.record({audit_category::kSetting, QStringLiteral("s"), QStringLiteral("f"), {}, {}}, QString(), {}),
        std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Backends, AuditStoreTest, ::testing::ValuesIn(test::backends()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tt::storage
