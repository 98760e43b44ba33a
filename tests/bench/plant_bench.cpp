// The plant-wide history at shop scale (docs/BENCHMARKS.md, "The plant-wide history"). Needs a PostgreSQL server
// with the test roles (scripts/start-test-postgres.sh; TRUETURN_PG_URL) and skips without one; never run in CI.
//   BM_PlantTerminals/B    20 terminals (`trueturn simulate --parts 1000` each, full simulator speed, their own
//                          journal and login) against one server, forwarding in batches of B parts: parts stored
//                          per second until every terminal has drained.
//   BM_PlantForward/B      the forwarding alone: 20 journals of 1000 parts each, filled while the server was away,
//                          sent at once by 20 `trueturn forward` processes in batches of B parts.
//   BM_PlantOverview       `trueturn plant --db DB --json` over TRUETURN_PLANT_HISTORY_PG (20 machines x 100,000
//                          parts; scripts/make-big-history.sh --plant), the whole process.
#include <benchmark/benchmark.h>

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QUuid>
#include <memory>
#include <vector>

#include "core/storage/database.h"
#include "core/storage/history_store.h"

namespace {

using namespace tt;

constexpr int kTerminals = 20;
constexpr int kPartsPerTerminal = 1000;

void ensureApplication() {
    static int argc = 1;
    static char name[] = "trueturn_bench";
    static char* argv[] = {name, nullptr};
    static const std::unique_ptr<QCoreApplication> app =
        QCoreApplication::instance() ? nullptr : std::make_unique<QCoreApplication>(argc, argv);
}

/// A fresh plant database on the TRUETURN_PG_URL server, migrated by its owner, each terminal_mN writing mN.
/// Returns its name; empty when there is no server.
QString freshPlant(QString name = {}) {
    const QString url = qEnvironmentVariable("TRUETURN_PG_URL");
    if (url.isEmpty()) return {};
    if (name.isEmpty()) name = QStringLiteral("plant_bench_") + QUuid::createUuid().toString(QUuid::Id128).left(10);
    {
        storage::Database admin(storage::DatabaseConfig::postgresUrl(url));
        admin.exec(QStringLiteral("CREATE DATABASE ") + name);
    }
    storage::DatabaseConfig c = storage::DatabaseConfig::postgresUrl(url);
    c.databaseName = name;
    storage::Database owner(c);
    owner.migrate(storage::historySchema());
    for (int i = 1; i <= kTerminals; ++i)
        owner.exec(
            QStringLiteral("INSERT INTO plant_terminals (login, machine) VALUES ('terminal_m%1', 'm%1')").arg(i));
    return name;
}

void dropPlant(const QString& name) {
    storage::Database admin(storage::DatabaseConfig::postgresUrl(qEnvironmentVariable("TRUETURN_PG_URL")));
    admin.exec(QStringLiteral("DROP DATABASE IF EXISTS %1 WITH (FORCE)").arg(name));
}

/// postgresql://terminal_mN@host:port/plant
QString terminalUrl(int i, const QString& plant) {
    storage::DatabaseConfig c = storage::DatabaseConfig::postgresUrl(qEnvironmentVariable("TRUETURN_PG_URL"));
    return QStringLiteral("postgresql://terminal_m%1@%2:%3/%4").arg(i).arg(c.host).arg(c.port).arg(plant);
}

/// Starts every process, waits for all; false (and the first one's stderr in `why`) when one failed.
bool runAll(std::vector<std::unique_ptr<QProcess>>& processes, std::string& why) {
    for (auto& p : processes)
        p->waitForFinished(3600000);
    for (auto& p : processes)
        if (p->exitStatus() != QProcess::NormalExit || p->exitCode() != 0) {
            why = p->readAllStandardError().toStdString();
            return false;
        }
    return true;
}

std::unique_ptr<QProcess> start(const QStringList& args) {
    auto p = std::make_unique<QProcess>();
    p->setStandardOutputFile(QProcess::nullDevice());
    p->start(QStringLiteral(TRUETURN_BINARY), args);
    return p;
}

void BM_PlantTerminals(benchmark::State& state) {
    ensureApplication();
    if (qEnvironmentVariable("TRUETURN_PG_URL").isEmpty()) {
        state.SkipWithError("needs TRUETURN_PG_URL (scripts/start-test-postgres.sh)");
        return;
    }
    for (auto _ : state) {
        state.PauseTiming();
        const QString plant = freshPlant();
        QTemporaryDir dir;
        state.ResumeTiming();
        std::vector<std::unique_ptr<QProcess>> terminals;
        for (int i = 1; i <= kTerminals; ++i)
            terminals.push_back(start(
                {"simulate", "--db", terminalUrl(i, plant), "--machine", QStringLiteral("m%1").arg(i), "--journal",
                 dir.filePath(QStringLiteral("m%1.sqlite").arg(i)), "--parts", QString::number(kPartsPerTerminal),
                 "--warmup", "0", "--seed", QString::number(i), "--forward-batch", QString::number(state.range(0))}));
        std::string why;
        const bool ok = runAll(terminals, why);
        state.PauseTiming();
        dropPlant(plant);
        state.ResumeTiming();
        if (!ok) {
            state.SkipWithError(("a terminal failed: " + why).c_str());
            return;
        }
    }
    state.counters["parts_per_s"] = benchmark::Counter(static_cast<double>(kTerminals * kPartsPerTerminal),
                                                       benchmark::Counter::kIsIterationInvariantRate);
}

void BM_PlantForward(benchmark::State& state) {
    ensureApplication();
    if (qEnvironmentVariable("TRUETURN_PG_URL").isEmpty()) {
        state.SkipWithError("needs TRUETURN_PG_URL (scripts/start-test-postgres.sh)");
        return;
    }
    // The journals, filled once while their plant database did not exist yet (every attempt refused, nothing
    // sent), then copied per round; each round creates that database afresh and forwards into it. A journal
    // belongs to one plant database (its server and name), so every round uses the same name.
    const QString plantName = QStringLiteral("plant_bench_forward");
    static QTemporaryDir filled;
    static bool made = false;
    if (!made) {
        dropPlant(plantName);
        std::vector<std::unique_ptr<QProcess>> terminals;
        for (int i = 1; i <= kTerminals; ++i)
            terminals.push_back(start(
                {"simulate", "--db", terminalUrl(i, plantName), "--machine", QStringLiteral("m%1").arg(i), "--journal",
                 filled.filePath(QStringLiteral("m%1.sqlite").arg(i)), "--parts", QString::number(kPartsPerTerminal),
                 "--warmup", "0", "--seed", QString::number(i), "--drain-wait", "0"}));
        std::string why;
        if (!runAll(terminals, why)) {
            state.SkipWithError(("filling the journals failed: " + why).c_str());
            return;
        }
        made = true;
    }
    for (auto _ : state) {
        state.PauseTiming();
        const QString plant = freshPlant(plantName);
        QTemporaryDir dir;
        for (int i = 1; i <= kTerminals; ++i)
            QFile::copy(filled.filePath(QStringLiteral("m%1.sqlite").arg(i)),
                        dir.filePath(QStringLiteral("m%1.sqlite").arg(i)));
        state.ResumeTiming();
        std::vector<std::unique_ptr<QProcess>> forwarders;
        for (int i = 1; i <= kTerminals; ++i)
            forwarders.push_back(
                start({"forward", "--db", terminalUrl(i, plant), "--machine", QStringLiteral("m%1").arg(i), "--journal",
                       dir.filePath(QStringLiteral("m%1.sqlite").arg(i)), "--forward-batch",
                       QString::number(state.range(0))}));
        std::string why;
        const bool ok = runAll(forwarders, why);
        state.PauseTiming();
        dropPlant(plant);
        state.ResumeTiming();
        if (!ok) {
            state.SkipWithError(("a forwarder failed: " + why).c_str());
            return;
        }
    }
    state.counters["parts_per_s"] = benchmark::Counter(static_cast<double>(kTerminals * kPartsPerTerminal),
                                                       benchmark::Counter::kIsIterationInvariantRate);
}

void BM_PlantOverview(benchmark::State& state) {
    ensureApplication();
    const QString db = qEnvironmentVariable("TRUETURN_PLANT_HISTORY_PG");
    if (db.isEmpty()) {
        state.SkipWithError("needs TRUETURN_PLANT_HISTORY_PG (scripts/make-big-history.sh --plant)");
        return;
    }
    const QString at = qEnvironmentVariable("TRUETURN_PLANT_AT", QStringLiteral("2026-03-11T10:40:00Z"));
    std::int64_t machines = 0;
    for (auto _ : state) {
        QProcess plant;
        plant.start(QStringLiteral(TRUETURN_BINARY), {"plant", "--db", db, "--at", at, "--json"});
        if (!plant.waitForFinished(600000) || plant.exitCode() != 0) {
            state.SkipWithError(("trueturn plant failed: " + plant.readAllStandardError().toStdString()).c_str());
            return;
        }
        machines = plant.readAllStandardOutput().count("\"machine\":");
    }
    state.counters["machines"] = static_cast<double>(machines);
}

BENCHMARK(BM_PlantTerminals)->Arg(20)->Arg(200)->Arg(1000)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_PlantForward)
    ->Arg(10)
    ->Arg(50)
    ->Arg(200)
    ->Arg(1000)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(BM_PlantOverview)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
