// The adaptive loop's records in the history (schema module "adaptation"), on SQLite and PostgreSQL: stored and read
// back exactly, in order, and folded into the audit trail with the models before and after.
#include <gtest/gtest.h>

#include <cmath>

#include "core/storage/adaptation_json.h"
#include "core/storage/audit_store.h"
#include "core/storage/history_store.h"
#include "scratch_database.h"

namespace tt::storage {
namespace {

core::PlantModelRecord model(double gain, int lag, bool identified) {
    core::PlantModelRecord m;
    m.delayParts = 2 + lag;
    m.lagParts = lag;
    m.source = identified ? "parts 1 .. 1000 of the run" : "the preset's model";
    m.criterion = identified ? "bic" : "";
    for (int i = 0; i < 2; ++i) {
        core::PointModelRecord p;
        p.gain = gain + 0.01 * i;
        p.ar = {0.9215};
        p.ma = {0.246, -0.01};
        p.noiseVarianceMm2 = 1.29e-4;
        if (identified) {
            p.gainStdErr = 0.05;
            p.arStdErr = {0.01};
            p.maStdErr = {0.02, 0.03};
            p.meanMm = -0.002;
        }
        m.points.push_back(p);
    }
    if (identified) m.innovationCorrelation = {1.0, 0.8, 0.8, 1.0};
    return m;
}

class AdaptationStoreTest : public ::testing::TestWithParam<std::string> {};

TEST_P(AdaptationStoreTest, StoresWhatTheLoopDidAndReadsItBack) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    SqlHistoryStore store(db);
    EXPECT_EQ(db.schemaVersion(QStringLiteral("adaptation")), 1);
    const std::int64_t run = store.beginRun({"paper-2012", "lqg", 2, 27.0, 325.0, {0.0, 325.0}, "{}"});
    core::AdaptationRecord fallback;
    fallback.kind = core::adaptation_kind::kFallback;
    fallback.partNumber = 215;
    fallback.timeS = 77400.0;
    fallback.reason = "the correlation test ...";
    fallback.fallback = "ewma 0.32";
    fallback.fallbackWeight = 0.32;
    fallback.modelBefore = model(2.0, 0, false);
    fallback.margins.gain = 3.1;
    fallback.margins.extraPartsTolerated = 1;
    fallback.applied = true;
    fallback.notice = core::Notice(core::NoticeKind::FallbackEngaged, 215, 213);
    fallback.notice.value = 0.32;
    store.recordAdaptation(run, fallback);
    core::AdaptationRecord adapted;
    adapted.kind = core::adaptation_kind::kAdapted;
    adapted.partNumber = 240;
    adapted.reason = "identified from parts 1 .. 1000 of the run by the BIC";
    adapted.modelBefore = model(2.0, 0, false);
    adapted.modelAfter = model(3.9, 1, true);
    adapted.margins = {2.2, 0.1, 41.0, 1.4, 0};
    adapted.applied = true;
    adapted.notice = core::Notice(core::NoticeKind::ControllerAdapted, 240);
    adapted.notice.value = 3;
    adapted.notice.reference = 2.2;
    adapted.notice.cause = "parts 1 .. 1000 of the run";
    store.recordAdaptation(run, adapted);

    const std::vector<core::AdaptationRecord> back = store.adaptations(run);
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[0].kind, "fallback");
    EXPECT_EQ(back[0].partNumber, 215);
    EXPECT_DOUBLE_EQ(back[0].timeS, 77400.0);
    EXPECT_EQ(back[0].fallback, "ewma 0.32");
    EXPECT_DOUBLE_EQ(back[0].fallbackWeight, 0.32);
    EXPECT_FALSE(back[0].modelAfter);
    EXPECT_DOUBLE_EQ(back[0].margins.gain, 3.1);
    EXPECT_TRUE(std::isnan(back[0].margins.phaseDeg));
    EXPECT_EQ(back[0].notice.kind, core::NoticeKind::FallbackEngaged);
    EXPECT_EQ(back[0].notice.otherPart, 213);
    const core::AdaptationRecord& a = back[1];
    ASSERT_TRUE(a.modelAfter);
    EXPECT_EQ(a.modelAfter->delayParts, 3);
    EXPECT_EQ(a.modelAfter->lagParts, 1);
    EXPECT_EQ(a.modelAfter->criterion, "bic");
    ASSERT_EQ(a.modelAfter->points.size(), 2u);
    EXPECT_DOUBLE_EQ(a.modelAfter->points[1].gain, 3.91);
    EXPECT_DOUBLE_EQ(a.modelAfter->points[0].gainStdErr, 0.05);
    EXPECT_EQ(a.modelAfter->points[0].ma, (std::vector<double>{0.246, -0.01}));
    EXPECT_EQ(a.modelAfter->innovationCorrelation, (std::vector<double>{1.0, 0.8, 0.8, 1.0}));
    EXPECT_TRUE(std::isnan(a.modelBefore.points[0].gainStdErr));
    EXPECT_DOUBLE_EQ(a.margins.phaseDeg, 41.0);
    EXPECT_EQ(a.notice.kind, core::NoticeKind::ControllerAdapted);
    EXPECT_EQ(a.notice.cause, "parts 1 .. 1000 of the run");
    EXPECT_TRUE(store.adaptations(run + 1).empty());

    // The audit trail reads them as controller changes by the adaptive loop, the model before and after in words.
    AuditStore audit(db);
    AuditFilter filter;
    filter.category = audit_category::kController;
    const std::vector<AuditRecord> trail = audit.query(filter);
    ASSERT_EQ(trail.size(), 2u);
    EXPECT_EQ(trail[0].changedBy, kAdaptiveLoopName);
    EXPECT_EQ(trail[0].change.field, QStringLiteral("adaptation: adapted"));
    EXPECT_TRUE(trail[0].change.subject.contains(QStringLiteral("part 240")));
    EXPECT_TRUE(trail[0].change.before.contains(QStringLiteral("gain 2")));
    EXPECT_TRUE(trail[0].change.after.contains(QStringLiteral("gain 3.9 ± 0.05"))) << qPrintable(trail[0].change.after);
    EXPECT_TRUE(trail[0].change.after.contains(QStringLiteral("delay 3 parts (lag 1)")));
    EXPECT_EQ(trail[1].change.field, QStringLiteral("adaptation: fallback"));
}

// The JSON of a model round-trips (the history's stored text).
TEST(AdaptationJson, ModelRoundTrip) {
    const core::PlantModelRecord m = model(1.9, 1, true);
    const core::PlantModelRecord back = plantModelFromJson(plantModelJson(m));
    EXPECT_EQ(back.delayParts, m.delayParts);
    EXPECT_EQ(back.source, m.source);
    ASSERT_EQ(back.points.size(), 2u);
    EXPECT_EQ(back.points[0].arStdErr, m.points[0].arStdErr);
    EXPECT_DOUBLE_EQ(back.points[0].meanMm, -0.002);
    EXPECT_THROW(plantModelFromJson(QJsonObject{}), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Backends, AdaptationStoreTest, ::testing::ValuesIn(test::backends()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace tt::storage
