// A terminal's journal and its forwarder, with the plant database on SQLite and on PostgreSQL: every part,
// reading, verdict, correction, alarm and run end reaches the plant database once and equal to the journal; a
// batch sent again inserts nothing; readings wait until the controller's verdicts are in; a full journal refuses
// the next part and takes parts again once they are sent; the forwarder thread retries while the plant is away.
#include <gtest/gtest.h>
#include <cmath>

#include <QDeadlineTimer>
#include <QDir>
#include <QElapsedTimer>
#include <QSqlQuery>
#include <QThread>

#include "core/storage/journal_batch.h"
#include "core/storage/plant_forwarder.h"
#include "core/storage/plant_forwarder_thread.h"
#include "journal_support.h"
#include "scratch_database.h"

namespace tt::storage {
namespace {

qint64 scalar(Database& db, const QString& sql) {
    QSqlQuery q = db.exec(sql);
    return q.next() ? q.value(0).toLongLong() : -1;
}

JournalOptions journalIn(const QString& folder, const QString& machine = QStringLiteral("m1")) {
    JournalOptions o;
    o.path = QDir(folder).filePath(machine + QStringLiteral("-journal.sqlite"));
    o.machine = machine;
    o.plant = QStringLiteral("the plant of the test");
    return o;
}

/// Sends everything the journal holds with batches of `batchParts`; returns the batches sent.
int forwardAll(const JournalOptions& journal, const DatabaseConfig& plant, int batchParts) {
    ForwarderSettings settings;
    settings.batchParts = batchParts;
    PlantForwarder forwarder(journal.path, plant, journal.machine, journal.limitBytes, settings);
    int batches = 0;
    while (forwarder.sendBatch())
        ++batches;
    EXPECT_EQ(forwarder.backlogParts(), 0);
    return batches;
}

class PlantJournalTest : public ::testing::TestWithParam<std::string> {};

TEST_P(PlantJournalTest, EveryPartReachesThePlantOnceAndEqualToTheJournal) {
    test::ScratchDatabase plant(GetParam());
    TT_REQUIRE_BACKEND(plant);
    const JournalOptions options = journalIn(plant.folder());
    HistoryJournal journal(options);
    const std::int64_t run = journal.beginRun(test::plantRun("m1"));
    test::writeParts(journal, run, 1, 120);
    journal.finishRun(run, "complete");
    EXPECT_EQ(journal.backlogParts(), 120);
    // 120 parts in batches of 7 parts: 18 batches (the last with the run's end).
    EXPECT_EQ(forwardAll(options, plant.config(), 7), 18);
    EXPECT_EQ(journal.backlogParts(), 0);

    Database db(plant.config());
    SqlHistoryStore plantHistory(db);
    const std::optional<std::int64_t> plantRun = test::runByUid(db, test::uidOf(journal.database(), run));
    ASSERT_TRUE(plantRun);
    test::expectSameRun(journal, run, plantHistory, *plantRun);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM parts")), 120);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM measurements")), 600);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM corrections")), 600);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM alarms")), 2);
    const core::RunSummary summary = plantHistory.runs().front();
    EXPECT_EQ(summary.status, "complete") << "the run's end arrives as a row (the plant's roles never update)";
    EXPECT_EQ(summary.description.machine, "m1");
    EXPECT_EQ(summary.partCount, 120);
    // The controller's verdict (point 3 of parts 10, 20, .., 110 rejected; part 120's readings were never used) is
    // what the plant holds.
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM measurements WHERE accepted = 0")), 11);
    // The terminal's report: nothing left to send.
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT backlog_parts FROM plant_terminal_status WHERE machine = 'm1'")), 0);
}

TEST_P(PlantJournalTest, ABatchSentAgainInsertsNothingTwice) {
    test::ScratchDatabase plant(GetParam());
    TT_REQUIRE_BACKEND(plant);
    const JournalOptions options = journalIn(plant.folder());
    HistoryJournal journal(options);
    const std::int64_t run = journal.beginRun(test::plantRun("m1"));
    test::writeParts(journal, run, 1, 60);
    journal.finishRun(run, "stopped");
    const JournalBatch batch = readJournalBatch(journal.database(), 0, 1000);
    ASSERT_EQ(batch.parts.size(), 60u);
    Database db(plant.config());
    db.migrate(historySchema());
    const auto counts = [&db] {
        std::vector<qint64> n;
        for (const char* table : {"runs", "run_points", "parts", "corrections", "measurements", "alarms", "run_ends"})
            n.push_back(scalar(db, QStringLiteral("SELECT COUNT(*) FROM ") + QLatin1String(table)));
        return n;
    };
    writePlantBatch(db, batch);
    const std::vector<qint64> once = counts();
    EXPECT_EQ(once, (std::vector<qint64>{1, 5, 60, 300, 300, 1, 1}));
    // The commit's answer lost: the forwarder sends the same batch again, and a later batch overlapping it.
    writePlantBatch(db, batch);
    writePlantBatch(db, readJournalBatch(journal.database(), batch.firstSeq + 10, 1000));
    EXPECT_EQ(counts(), once);
    // The natural keys are unique constraints of the plant database: a second reading of a point is refused.
    EXPECT_THROW(db.exec(QStringLiteral("INSERT INTO measurements (part_id, point_index, z_mm, measured_mm, nominal_mm,"
                                        " accepted, reason, measured_s) SELECT part_id, point_index, z_mm, measured_mm,"
                                        " nominal_mm, accepted, reason, measured_s FROM measurements LIMIT 1")),
                 StorageError);
    EXPECT_THROW(db.exec(QStringLiteral("INSERT INTO parts (run_id, part_number, started_s, finished_s, recorded_at)"
                                        " SELECT run_id, part_number, started_s, finished_s, recorded_at FROM parts"
                                        " LIMIT 1")),
                 StorageError);
}

TEST_P(PlantJournalTest, AReadingIsSentOnceTheControllerHasJudgedIt) {
    test::ScratchDatabase plant(GetParam());
    TT_REQUIRE_BACKEND(plant);
    const JournalOptions options = journalIn(plant.folder());
    HistoryJournal journal(options);
    const std::int64_t run = journal.beginRun(test::plantRun("m1"));
    test::writeParts(journal, run, 1, 10);  // the diameters of part 10 are in, not yet used by part 11
    forwardAll(options, plant.config(), 100);
    Database db(plant.config());
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM parts")), 10);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(DISTINCT part_id) FROM measurements")), 9);
    // Part 11 used them (point 3 rejected by the controller): now they go, with that verdict.
    core::PartMeasurementRecord used = test::plantMeasurement(10);
    used.points[2].accepted = false;
    used.points[2].reason = "rejected by the controller: outside the gate";
    journal.recordPart(run, test::plantPart(11, used));
    forwardAll(options, plant.config(), 100);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(DISTINCT part_id) FROM measurements")), 10);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM measurements m JOIN parts p ON p.id = m.part_id"
                                        " WHERE p.part_number = 10 AND m.accepted = 0")),
              1);
    // A run killed and never resumed: its last readings go once another run begins.
    journal.recordMeasurement(run, test::plantMeasurement(11));
    journal.beginRun(test::plantRun("m1"));
    forwardAll(options, plant.config(), 100);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(DISTINCT part_id) FROM measurements")), 11);
}

TEST_P(PlantJournalTest, AFullJournalRefusesTheNextPartAndTakesPartsAgainOnceThePlantHasThem) {
    test::ScratchDatabase plant(GetParam());
    TT_REQUIRE_BACKEND(plant);
    JournalOptions options = journalIn(plant.folder());
    options.limitBytes = 1 << 20;  // the smallest bound, 1 MiB
    HistoryJournal journal(options);
    const std::int64_t run = journal.beginRun(test::plantRun("m1"));
    std::int64_t parts = 0;
    // Filled in one transaction (one disk flush instead of two per part: the test's time, not what it checks).
    journal.database().transaction([&] {
        while (!journal.refusesNextPart() && parts < 20000) {
            ++parts;
            test::writeParts(journal, run, parts, parts);
        }
    });
    const core::Notice refusal = journal.refusesNextPart();
    ASSERT_EQ(refusal.kind, core::NoticeKind::HistoryFull) << parts << " parts did not fill 1 MiB";
    EXPECT_GE(refusal.value, refusal.limit);
    EXPECT_NE(refusal.cause.find("limit 1 MiB"), std::string::npos) << refusal.cause;
    EXPECT_GT(parts, 100);
    // The plant database takes them: the parts it holds are deleted from the journal down to half the bound,
    // the parts a resume needs stay.
    forwardAll(options, plant.config(), 200);
    EXPECT_FALSE(journal.refusesNextPart());
    EXPECT_LE(journal.usage().usedBytes, options.limitBytes / 2 + 64 * 1024);
    const std::optional<core::ResumePoint> resume = journal.resumePoint(run);
    ASSERT_TRUE(resume);
    EXPECT_EQ(resume->lastPartNumber, parts);
    Database db(plant.config());
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM parts")), parts);
}

INSTANTIATE_TEST_SUITE_P(Backends, PlantJournalTest, ::testing::ValuesIn(test::backends()),
                         [](const auto& info) { return info.param; });

TEST(PlantJournal, AJournalOfAnotherMachineOrPlantIsRefusedUntouched) {
    QTemporaryDir dir;
    const JournalOptions m1 = journalIn(dir.path());
    { HistoryJournal journal(m1); }
    JournalOptions other = m1;
    other.machine = QStringLiteral("m2");
    EXPECT_THROW(HistoryJournal{other}, StorageError);
    other = m1;
    other.plant = QStringLiteral("another plant");
    try {
        HistoryJournal journal(other);
        FAIL() << "expected a refusal";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("left untouched"), std::string::npos) << e.what();
    }
    HistoryJournal again(m1);
    EXPECT_THROW(again.beginRun(test::plantRun("m2")), StorageError);
}

// A wait computed as "what is left of the retry" comes out below zero when the computer was busy; QDeadlineTimer
// takes a negative time as "never": the forwarder then slept for ever after an outage (a terminal under a loaded
// ctest -j4 sent nothing more once the plant database was back).
TEST(PlantJournal, TheForwardersWaitsAllEndAndAWaitLeftBelowZeroEndsAtOnce) {
    for (const double seconds : {-0.004, -1.0, 0.0, std::nan("")}) {
        const QDeadlineTimer d = PlantForwarderThread::deadlineAfter(seconds);
        EXPECT_FALSE(d.isForever()) << seconds;
        EXPECT_TRUE(d.hasExpired()) << seconds;
    }
    const QDeadlineTimer retry = PlantForwarderThread::deadlineAfter(2.0);
    EXPECT_FALSE(retry.isForever());
    EXPECT_FALSE(retry.hasExpired());
    EXPECT_GT(retry.remainingTime(), 1000);
    EXPECT_LE(retry.remainingTime(), 2000);
    EXPECT_FALSE(PlantForwarderThread::deadlineAfter(1e300).isForever());
}

// The forwarder thread while the plant database cannot be opened: offline since the first failure, the parts
// kept counted, retries with a growing wait; once it can be opened, everything is sent and it says drained.
TEST(PlantJournal, TheForwarderThreadRetriesWhileThePlantIsAwayAndDrainsWhenItIsBack) {
    QTemporaryDir dir;
    const JournalOptions options = journalIn(dir.path());
    HistoryJournal journal(options);
    const std::int64_t run = journal.beginRun(test::plantRun("m1"));
    test::writeParts(journal, run, 1, 30);
    const QString plantFolder = dir.filePath(QStringLiteral("not-yet"));  // the plant's folder does not exist yet
    ForwarderOptions forward{options.path,
                             DatabaseConfig::sqlite(plantFolder + QStringLiteral("/plant.sqlite")),
                             options.machine,
                             options.limitBytes,
                             {}};
    forward.settings.firstRetryS = 0.05;
    forward.settings.maxRetryS = 0.2;
    PlantForwarderThread forwarder(forward);
    std::vector<double> waits;
    forwarder.setStatusCallback([&waits, last = -1.0](const ForwarderStatus& s) mutable {
        if (s.link == ForwarderStatus::Link::Offline && s.retryInS > last + 1e-9) waits.push_back(s.retryInS);
        last = s.link == ForwarderStatus::Link::Offline ? s.retryInS : -1.0;
    });
    forwarder.start();
    QElapsedTimer waited;
    waited.start();
    while (waited.elapsed() < 10000 && forwarder.status().link != ForwarderStatus::Link::Offline)
        QThread::msleep(10);
    QThread::msleep(600);
    ForwarderStatus s = forwarder.status();
    ASSERT_EQ(s.link, ForwarderStatus::Link::Offline);
    EXPECT_TRUE(s.offlineSince.isValid());
    EXPECT_EQ(s.backlogParts, 30);
    EXPECT_FALSE(s.reason.isEmpty());
    EXPECT_NE(s.describe().indexOf(QStringLiteral("offline since")), -1) << qPrintable(s.describe());
    ASSERT_TRUE(QDir().mkpath(plantFolder));
    journal.finishRun(run, "complete");
    EXPECT_TRUE(forwarder.drainAndStop(30.0));
    s = forwarder.status();
    EXPECT_EQ(s.backlogParts, 0);
    EXPECT_EQ(s.sentParts, 30);
    ASSERT_GE(waits.size(), 2u);
    EXPECT_GT(waits[1], waits[0]) << "the wait grows after each failure";
    Database db(forward.plant);
    EXPECT_EQ(scalar(db, QStringLiteral("SELECT COUNT(*) FROM measurements")), 150);
}

}  // namespace
}  // namespace tt::storage
