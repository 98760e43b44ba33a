// The run history over SQL, on SQLite and PostgreSQL: what the loop stores, how a part is one
// transaction, and where an interrupted run continues.
#include "core/storage/history_store.h"

#include <gtest/gtest.h>

#include <QSqlQuery>
#include <cmath>
#include <limits>

#include "scratch_database.h"

namespace tt::storage {
namespace {

core::RunDescription paperRun(int delay) {
    return {"paper-2012-group1", "lqg", delay, 27.0, 325.0, {0.0, 27.5, 162.5, 262.5, 325.0}, R"({"seed": 7})"};
}

core::PartMeasurementRecord measured(std::int64_t part, double base) {
    core::PartMeasurementRecord m{part, 400.0 * static_cast<double>(part), {}};
    const double z[] = {0.0, 27.5, 162.5, 262.5, 325.0};
    for (int i = 0; i < 5; ++i)
        m.points.push_back({i, z[i], 27.0 + base + 0.001 * i, 27.0, true, ""});
    return m;
}

core::PartCompletionRecord finished(std::int64_t part, std::optional<core::PartMeasurementRecord> used = std::nullopt) {
    core::PartCompletionRecord r;
    r.partNumber = part;
    r.startedS = 400.0 * static_cast<double>(part - 1);
    r.finishedS = r.startedS + 360.0;
    const double z[] = {0.0, 27.5, 162.5, 262.5, 325.0};
    for (int i = 0; i < 5; ++i)
        r.corrections.push_back(
            {i, z[i], -0.01 * static_cast<double>(part) - 0.1 / 3.0, -0.01 * static_cast<double>(part)});
    r.usedMeasurement = std::move(used);
    r.controllerState = {"lqg",
                         {static_cast<double>(part), 1.0 / 3.0, std::numeric_limits<double>::quiet_NaN(), -1e-300}};
    return r;
}

qint64 count(Database& db, const char* table) {
    QSqlQuery q = db.exec(QStringLiteral("SELECT COUNT(*) FROM ") + QString::fromLatin1(table));
    return q.next() ? q.value(0).toLongLong() : -1;
}

class HistoryStoreTest : public ::testing::TestWithParam<std::string> {};

TEST_P(HistoryStoreTest, StoresRunsPartsCorrectionsAndMeasurementsExactly) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    SqlHistoryStore store(db);
    EXPECT_EQ(db.schemaVersion(QStringLiteral("history")), 5)
        << "version 3 keeps the tolerance verdicts, 4 the covering index of the readings by point, 5 the plant-wide "
           "history's keys";
    const std::int64_t run = store.beginRun(paperRun(2));
    store.recordPart(run, finished(1));
    store.recordMeasurement(run, measured(1, 0.012));
    store.recordPart(run, finished(2));
    auto m2 = measured(2, 0.0);
    m2.points[3].measuredMm = 29.0;
    m2.points[3].accepted = false;
    m2.points[3].reason = "rejected: reading 29.000 mm is more than 0.500 mm from the nominal 27.000 mm";
    m2.points[3].rejection = core::Notice(core::NoticeKind::Implausible, 2);
    m2.points[3].rejection.value = 29.0;
    m2.points[3].rejection.reference = 27.0;
    m2.points[3].rejection.limit = 0.5;
    m2.points[4].measuredMm.reset();
    m2.points[4].accepted = false;
    m2.points[4].reason = "not measured";
    store.recordMeasurement(run, m2);

    const auto runs = store.runs();
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_EQ(runs[0].status, "running");
    EXPECT_EQ(runs[0].partCount, 2);
    EXPECT_EQ(runs[0].lastPartNumber, 2);
    EXPECT_EQ(runs[0].description.pointZMm, paperRun(2).pointZMm);
    EXPECT_EQ(runs[0].description.settingsJson, R"({"seed": 7})");
    EXPECT_FALSE(runs[0].startedAt.empty());

    const auto parts = store.parts(run);
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_EQ(parts[0].corrections[2].computedMm, -0.01 - 0.1 / 3.0) << "doubles round-trip exactly";
    EXPECT_EQ(parts[1].corrections[4].appliedMm, -0.02);
    ASSERT_TRUE(parts[1].measurement.has_value());
    const auto& p = parts[1].measurement->points;
    EXPECT_EQ(*p[0].measuredMm, 27.0);
    EXPECT_FALSE(p[3].accepted);
    EXPECT_EQ(p[3].reason, m2.points[3].reason);
    // The kind and numbers come back, so the page words the reason in the operator's language.
    EXPECT_EQ(p[3].rejection.kind, core::NoticeKind::Implausible);
    EXPECT_EQ(p[3].rejection.point, 4);
    EXPECT_EQ(p[3].rejection.value, 29.0);
    EXPECT_EQ(p[3].rejection.limit, 0.5);
    EXPECT_EQ(p[3].rejection.reference, 27.0);
    EXPECT_FALSE(p[4].rejection) << "stored without a kind: only its words";
    EXPECT_FALSE(p[4].measuredMm.has_value());
    EXPECT_EQ(p[4].reason, "not measured");
    EXPECT_EQ(parts[1].measurement->timeS, 800.0);

    store.finishRun(run, "complete");
    EXPECT_EQ(store.runs()[0].status, "complete");
    EXPECT_FALSE(store.runs()[0].finishedAt.empty());
}

// Version 3: each reading's tolerance verdict and limits, apart from "accepted", and the machine of a run.
TEST_P(HistoryStoreTest, StoresTheToleranceVerdictsApartFromAcceptedAndTheMachine) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    SqlHistoryStore store(db);
    core::RunDescription description = paperRun(1);
    description.machine = "lathe-7";
    const std::int64_t run = store.beginRun(description);
    store.recordPart(run, finished(1));
    auto m = measured(1, 0.0);
    const core::ToleranceZone h9{27.0, 0.0, -0.052};
    m.points[0].tolerance = h9;
    m.points[0].verdict = core::ToleranceVerdict::Scrap;  // accepted all the same: a plausible reading
    m.points[1].tolerance = h9;
    m.points[1].verdict = core::ToleranceVerdict::Rework;
    store.recordMeasurement(run, m);
    EXPECT_EQ(store.runs()[0].description.machine, "lathe-7");
    const auto& p = store.parts(run)[0].measurement->points;
    EXPECT_EQ(p[0].verdict, core::ToleranceVerdict::Scrap);
    EXPECT_TRUE(p[0].accepted);
    EXPECT_EQ(p[1].verdict, core::ToleranceVerdict::Rework);
    ASSERT_TRUE(p[1].tolerance);
    EXPECT_NEAR(p[1].tolerance->upperLimitMm(), 27.0, 1e-12);
    EXPECT_NEAR(p[1].tolerance->lowerLimitMm(), 26.948, 1e-12);
    EXPECT_FALSE(p[2].verdict) << "no tolerance: no verdict";
    EXPECT_FALSE(p[2].tolerance);
    EXPECT_EQ(store.parts(run)[0].measurement->verdict(), core::ToleranceVerdict::Scrap);
}

TEST_P(HistoryStoreTest, APartIsOneTransaction) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    SqlHistoryStore store(db);
    const std::int64_t run = store.beginRun(paperRun(1));
    store.recordPart(run, finished(1));
    // Part 2 refers to the measurement of a part that does not exist: nothing of part 2 may remain.
    EXPECT_THROW(store.recordPart(run, finished(2, measured(7, 0.0))), StorageError);
    EXPECT_EQ(count(db, "parts"), 1);
    EXPECT_EQ(count(db, "corrections"), 5);
    EXPECT_EQ(store.resumePoint()->lastPartNumber, 1) << "the controller state of part 2 was not stored either";
    // The same part twice is refused and leaves the first intact.
    EXPECT_THROW(store.recordPart(run, finished(1)), StorageError);
    EXPECT_EQ(count(db, "parts"), 1);
    EXPECT_EQ(count(db, "corrections"), 5);
    EXPECT_THROW(store.recordMeasurement(run, measured(3, 0.0)), StorageError) << "a measurement of an unknown part";
}

TEST_P(HistoryStoreTest, TheControllersVerdictsReplaceTheStoredOnes) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    SqlHistoryStore store(db);
    const std::int64_t run = store.beginRun(paperRun(1));
    store.recordPart(run, finished(1));
    store.recordMeasurement(run, measured(1, 0.3));
    auto judged = measured(1, 0.3);
    judged.points[2].accepted = false;
    judged.points[2].reason = "rejected by the controller: 6.1 sigma from the prediction";
    store.recordPart(run, finished(2, judged));
    const auto parts = store.parts(run);
    EXPECT_FALSE(parts[0].measurement->points[2].accepted);
    EXPECT_EQ(parts[0].measurement->points[2].reason, judged.points[2].reason);
    EXPECT_EQ(count(db, "measurements"), 5);
}

TEST_P(HistoryStoreTest, ResumePointHasTheStateTheNextPartAndThePendingParts) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    SqlHistoryStore store(db);
    EXPECT_FALSE(store.resumePoint().has_value()) << "no run yet";
    const std::int64_t run = store.beginRun(paperRun(3));
    EXPECT_FALSE(store.resumePoint().has_value()) << "no part yet";
    for (std::int64_t k = 1; k <= 9; ++k) {
        store.recordPart(run, finished(k, k > 3 ? std::optional(measured(k - 3, 0.01)) : std::nullopt));
        if (k <= 7) store.recordMeasurement(run, measured(k, 0.01));  // parts 8 and 9 not measured yet
    }
    const auto resume = store.resumePoint();
    ASSERT_TRUE(resume.has_value());
    EXPECT_EQ(resume->run.runId, run);
    EXPECT_EQ(resume->lastPartNumber, 9);
    EXPECT_EQ(resume->controllerState.kind, "lqg");
    ASSERT_EQ(resume->controllerState.values.size(), 4u);
    EXPECT_EQ(resume->controllerState.values[1], 1.0 / 3.0);
    EXPECT_TRUE(std::isnan(resume->controllerState.values[2]));
    EXPECT_EQ(resume->controllerState.values[3], -1e-300);
    // z = 3: the measurements of parts 7, 8, 9 are not used yet; 7 is stored, 8 and 9 wait for the gauge.
    ASSERT_EQ(resume->pendingParts.size(), 3u);
    EXPECT_EQ(resume->pendingParts[0].partNumber, 7);
    EXPECT_TRUE(resume->pendingParts[0].measurement.has_value());
    EXPECT_FALSE(resume->pendingParts[1].measurement.has_value());
    EXPECT_FALSE(resume->pendingParts[2].measurement.has_value());
    EXPECT_EQ(resume->pendingParts[2].corrections.size(), 5u);
    EXPECT_THROW(store.resumePoint(run + 5), StorageError);
}

TEST_P(HistoryStoreTest, AlarmsAreKeptInOrder) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    SqlHistoryStore store(db);
    const std::int64_t run = store.beginRun(paperRun(1));
    store.recordAlarm(run, {std::nullopt, 10.0, "gauge-silent", "the gauge does not answer"});
    store.recordAlarm(run, {std::int64_t{4}, 20.0, "measurement-rejected", "part 4, point 3: rejected"});
    const auto alarms = store.alarms(run);
    ASSERT_EQ(alarms.size(), 2u);
    EXPECT_FALSE(alarms[0].partNumber.has_value());
    EXPECT_EQ(alarms[1].partNumber, 4);
    EXPECT_EQ(alarms[1].kind, "measurement-rejected");
}

TEST_P(HistoryStoreTest, DeletingARunRemovesEverythingOfIt) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    SqlHistoryStore store(db);
    const std::int64_t run = store.beginRun(paperRun(1));
    store.recordPart(run, finished(1));
    store.recordMeasurement(run, measured(1, 0.0));
    store.recordAlarm(run, {std::int64_t{1}, 1.0, "x", "y"});
    db.exec(QStringLiteral("DELETE FROM runs WHERE id = ?"), {static_cast<qlonglong>(run)});
    for (const char* table : {"parts", "corrections", "measurements", "run_state", "alarms", "run_points"})
        EXPECT_EQ(count(db, table), 0) << table;
}

INSTANTIATE_TEST_SUITE_P(Backends, HistoryStoreTest, ::testing::ValuesIn(test::backends()));

TEST(ControllerValues, RoundTripExactlyAndRefuseDamage) {
    const std::vector<double> v = {0.1, -2.5e-17, 1e300, std::numeric_limits<double>::infinity(), 123456789.123456789};
    EXPECT_EQ(decodeControllerValues(encodeControllerValues(v)), v);
    EXPECT_TRUE(decodeControllerValues("").empty());
    EXPECT_THROW(decodeControllerValues("0.5 x 2"), StorageError);
}

}  // namespace
}  // namespace tt::storage
