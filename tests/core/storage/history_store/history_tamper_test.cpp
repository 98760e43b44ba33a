// A history file altered outside TrueTurn (issue 17, item 3): a tampered resume point must be refused
// before any arithmetic on it (last_part - delay + 1 overflowed for INT64_MIN; INT64_MAX + 1 for the
// next part).
#include <gtest/gtest.h>

#include <QSqlQuery>
#include <limits>
#include <string>

#include "core/storage/history_store.h"
#include "scratch_database.h"

namespace tt::storage {
namespace {

core::PartCompletionRecord partDone(std::int64_t part) {
    core::PartCompletionRecord r;
    r.partNumber = part;
    r.startedS = 400.0 * static_cast<double>(part - 1);
    r.finishedS = r.startedS + 360.0;
    r.controllerState = {"lqg", {static_cast<double>(part)}};
    return r;
}

class TamperedHistory : public ::testing::TestWithParam<std::int64_t> {};

TEST_P(TamperedHistory, AResumePointOutsideTheRunsPartsIsRefused) {
    test::ScratchDatabase scratch("sqlite");
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    SqlHistoryStore store(db);
    const std::int64_t run =
        store.beginRun({"paper-2012-group1", "lqg", 3, 27.0, 325.0, {0.0, 162.5, 325.0}, R"({"seed": 7})"});
    for (std::int64_t k = 1; k <= 4; ++k)
        store.recordPart(run, partDone(k));
    db.exec(QStringLiteral("UPDATE run_state SET last_part = ? WHERE run_id = ?"),
            {QVariant::fromValue<qlonglong>(GetParam()), QVariant::fromValue<qlonglong>(run)});
    try {
        store.resumePoint();
        ADD_FAILURE() << "a last_part of " << GetParam() << " was accepted";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("outside the run's parts 0 .. 4"), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(LastParts, TamperedHistory,
                         ::testing::Values(std::numeric_limits<std::int64_t>::min(), -1, 5,
                                           std::numeric_limits<std::int64_t>::max()));

}  // namespace
}  // namespace tt::storage
