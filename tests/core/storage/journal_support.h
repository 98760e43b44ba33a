#pragma once

// A terminal's run written into its journal as the loop writes it (delay z = 1: the measurement of part n is used
// for part n + 1), and the comparison of what a history holds, for the tests of the plant-wide history.
#include <gtest/gtest.h>

#include <QSqlQuery>
#include <QString>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/storage/history_journal.h"
#include "core/storage/history_store.h"

namespace tt::storage::test {

inline core::RunDescription plantRun(const std::string& machine) {
    return {"paper-2012", "lqg", 1, 27.0, 325.0, {0.0, 27.5, 162.5, 262.5, 325.0}, R"({"seed": 7})", machine};
}

/// The diameters of `part`, with h7 verdicts (a few rework and scrap parts).
inline core::PartMeasurementRecord plantMeasurement(std::int64_t part) {
    core::PartMeasurementRecord m{part, 400.0 * static_cast<double>(part) + 380.0, {}};
    const double z[] = {0.0, 27.5, 162.5, 262.5, 325.0};
    const core::ToleranceZone zone{27.0, 0.0, -0.021};
    for (int i = 0; i < 5; ++i) {
        const double d = 27.0 - 0.0105 + 0.004 * std::sin(0.7 * static_cast<double>(part) + i) +
                         (part % 17 == 0 ? 0.02 : 0.0) - (part % 23 == 0 ? 0.02 : 0.0);
        core::PointMeasurementRecord p{i, z[i], d, 27.0, true, ""};
        p.tolerance = zone;
        p.verdict = core::outerDiameterVerdict(zone, d);
        m.points.push_back(p);
    }
    return m;
}

inline core::PartCompletionRecord plantPart(std::int64_t part, std::optional<core::PartMeasurementRecord> used) {
    core::PartCompletionRecord r;
    r.partNumber = part;
    r.startedS = 400.0 * static_cast<double>(part - 1);
    r.finishedS = r.startedS + 360.0;
    const double z[] = {0.0, 27.5, 162.5, 262.5, 325.0};
    for (int i = 0; i < 5; ++i)
        r.corrections.push_back({i, z[i], -0.001 * static_cast<double>(part) - 0.1 / 3.0,
                                 -0.001 * static_cast<double>(part)});
    r.usedMeasurement = std::move(used);
    r.controllerState = {"lqg", {static_cast<double>(part), 1.0 / 3.0}};
    return r;
}

/// Parts `from` .. `to` of run `run` as the loop stores them with delay 1: part n (using the measurement of
/// n - 1, the controller rejecting point 3 of every 10th), then the diameters of part n. An alarm every 50 parts.
inline void writeParts(core::HistoryStore& store, std::int64_t run, std::int64_t from, std::int64_t to) {
    for (std::int64_t n = from; n <= to; ++n) {
        std::optional<core::PartMeasurementRecord> used;
        if (n > 1) {
            used = plantMeasurement(n - 1);
            if ((n - 1) % 10 == 0) {
                used->points[2].accepted = false;
                used->points[2].reason = "rejected by the controller: outside the gate";
            }
        }
        store.recordPart(run, plantPart(n, used));
        store.recordMeasurement(run, plantMeasurement(n));
        if (n % 50 == 0) store.recordAlarm(run, {n, 400.0 * static_cast<double>(n), "out-of-tolerance", "part " + std::to_string(n)});
    }
}

/// The run of `history` with the unique id `uid`.
inline std::optional<std::int64_t> runByUid(Database& db, const QString& uid) {
    QSqlQuery q = db.exec(QStringLiteral("SELECT id FROM runs WHERE run_uid = ?"), {uid});
    return q.next() ? std::optional<std::int64_t>(q.value(0).toLongLong()) : std::nullopt;
}

inline QString uidOf(Database& db, std::int64_t run) {
    QSqlQuery q = db.exec(QStringLiteral("SELECT run_uid FROM runs WHERE id = ?"), {QVariant::fromValue<qint64>(run)});
    return q.next() ? q.value(0).toString() : QString();
}

/// Every part, correction, reading (value, acceptance, reason, verdict, limits) and alarm of run `a` in history
/// `x` is in run `b` of history `y`, and nothing more.
inline void expectSameRun(core::HistoryStore& x, std::int64_t a, core::HistoryStore& y, std::int64_t b) {
    const std::vector<core::StoredPart> pa = x.parts(a), pb = y.parts(b);
    ASSERT_EQ(pa.size(), pb.size());
    for (std::size_t i = 0; i < pa.size(); ++i) {
        SCOPED_TRACE("part " + std::to_string(pa[i].partNumber));
        EXPECT_EQ(pa[i].partNumber, pb[i].partNumber);
        EXPECT_EQ(pa[i].startedS, pb[i].startedS);
        EXPECT_EQ(pa[i].finishedS, pb[i].finishedS);
        ASSERT_EQ(pa[i].corrections.size(), pb[i].corrections.size());
        for (std::size_t k = 0; k < pa[i].corrections.size(); ++k) {
            EXPECT_EQ(pa[i].corrections[k].computedMm, pb[i].corrections[k].computedMm);
            EXPECT_EQ(pa[i].corrections[k].appliedMm, pb[i].corrections[k].appliedMm);
        }
        ASSERT_EQ(pa[i].measurement.has_value(), pb[i].measurement.has_value());
        if (!pa[i].measurement) continue;
        const auto& ma = pa[i].measurement->points;
        const auto& mb = pb[i].measurement->points;
        ASSERT_EQ(ma.size(), mb.size());
        for (std::size_t k = 0; k < ma.size(); ++k) {
            EXPECT_EQ(ma[k].measuredMm, mb[k].measuredMm);
            EXPECT_EQ(ma[k].accepted, mb[k].accepted);
            EXPECT_EQ(ma[k].reason, mb[k].reason);
            EXPECT_EQ(ma[k].verdict, mb[k].verdict);
            EXPECT_EQ(ma[k].tolerance.has_value(), mb[k].tolerance.has_value());
        }
    }
    const std::vector<core::AlarmRecord> aa = x.alarms(a), ab = y.alarms(b);
    ASSERT_EQ(aa.size(), ab.size());
    for (std::size_t i = 0; i < aa.size(); ++i) {
        EXPECT_EQ(aa[i].partNumber, ab[i].partNumber);
        EXPECT_EQ(aa[i].kind, ab[i].kind);
        EXPECT_EQ(aa[i].message, ab[i].message);
    }
}

}  // namespace tt::storage::test
