// The run request: one value for everything a run is, written to and read from JSON in one place, validated in
// one place with refusals that name the field, and read back from what a run stored (the request format and
// the two older ones).
#include "runtime/run/run_request.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>

#include "config/controller_tuning_json.h"
#include "config/plant_config.h"
#include "runtime/run/stored_runs.h"

namespace tt::runtime {
namespace {

/// The field a refusal names ("" when nothing is refused).
std::string refusedField(const RunRequest& request) {
    try {
        validate(request);
    } catch (const RunRequestError& e) {
        return e.field;
    }
    return {};
}

/// The field runRequestFromJson refuses in `json` ("" when nothing is refused).
std::string refusedFieldOfJson(const QJsonObject& json) {
    try {
        runRequestFromJson(json);
    } catch (const RunRequestError& e) {
        return e.field;
    }
    return {};
}

RunRequest everything() {
    RunRequest q;
    q.machine = QStringLiteral("simulated-lathe");
    q.lathe = QStringLiteral("m7");
    q.preset = QStringLiteral("paper-2012");
    q.delay = 3;
    q.controller = core::ControllerKind::Lqg;
    q.integral = true;
    q.integralWeight = 0.2;
    q.mismatchAction = "alarm";
    q.plant.gainFactor = 0.7;
    q.plant.delayParts = 4;
    q.plant.step = RequestedStep{200, 0.02, 3};
    q.pauseOnScrap = true;
    q.seed = 123456789;
    q.speed = 360.0;
    q.endPart = 1100;
    q.warmupParts = 100;
    q.database = QStringLiteral("h.sqlite");
    return q;
}

TEST(RunRequest, EveryFieldSurvivesJson) {
    const RunRequest q = everything();
    const RunRequest back = runRequestFromJson(toJson(q));
    EXPECT_EQ(toJson(back), toJson(q));
    EXPECT_EQ(back.plant.step->point, std::optional<int>(3));
    EXPECT_EQ(back.seed, 123456789u);
    EXPECT_NO_THROW(validate(back));
}

TEST(RunRequest, AbsentValuesAreLeftOutAndTakeThePresets) {
    const QJsonObject json = toJson(RunRequest{});
    for (const char* absent : {"delay", "ewma_weight", "integral", "plant_mismatch", "tuning", "end_part"})
        EXPECT_FALSE(json.contains(QLatin1String(absent))) << absent;
    const config::LoopScenario scenario = scenarioOf(RunRequest{});
    EXPECT_EQ(scenario.delay(), config::loadLoopScenario(QStringLiteral("paper-2012")).delay());
    EXPECT_FALSE(scenario.plantMismatch.any());
}

TEST(RunRequest, RefusalsNameTheField) {
    RunRequest q;
    q.plant.gainFactor = 12.0;
    EXPECT_EQ(refusedField(q), "plant_mismatch.gain_factor");
    q = {};
    q.delay = 9;
    EXPECT_EQ(refusedField(q), "delay");
    q = {};
    q.ewmaWeight = 0.5;  // with the LQG
    EXPECT_EQ(refusedField(q), "ewma_weight");
    q = {};
    q.plant.delayParts = 1;  // below the preset's z = 4
    EXPECT_EQ(refusedField(q), "plant_mismatch.delay");
    q = {};
    q.plant.step = RequestedStep{10, 0.02, 6};  // the preset has five points
    EXPECT_EQ(refusedField(q), "plant_mismatch.step.point");
    q = {};
    q.preset = QStringLiteral("paper-2012-group1");
    q.plant.gainFactor = 0.7;  // a physical lathe: the statistical plant only
    EXPECT_EQ(refusedField(q), "plant_mismatch.gain_factor");
    q = {};
    q.endPart = 50;
    q.warmupParts = 50;
    EXPECT_EQ(refusedField(q), "warmup_parts");
    q = {};
    q.speed = 0.5;
    EXPECT_EQ(refusedField(q), "speed");
    q = {};
    q.mismatchAction = "explode";
    EXPECT_EQ(refusedField(q), "mismatch_action");
    q = {};
    q.preset = QStringLiteral("no-such-preset");
    EXPECT_EQ(refusedField(q), "preset");
}

RunRequest throughLinuxCnc() {
    RunRequest q;
    q.machine = QStringLiteral("linuxcnc-lathe:127.0.0.1:5007");
    q.preset = QStringLiteral("paper-2012-group1");
    q.cnc = QStringLiteral("linuxcnc://127.0.0.1:5007");
    q.cncMode = QStringLiteral("wear");
    q.endPart = 60;
    return q;
}

TEST(RunRequest, TheCncSurvivesJsonAndIsLeftOutWithoutOne) {
    QTemporaryDir folder;
    RunRequest q = throughLinuxCnc();
    q.cncProgramFolder = folder.path();
    const QJsonObject json = toJson(q);
    EXPECT_EQ(json.value(QStringLiteral("cnc")).toObject(),
              (QJsonObject{{QStringLiteral("url"), q.cnc},
                           {QStringLiteral("mode"), QStringLiteral("wear")},
                           {QStringLiteral("program_folder"), folder.path()}}));
    const RunRequest back = runRequestFromJson(json);
    EXPECT_EQ(back.cnc, q.cnc);
    EXPECT_EQ(back.cncMode, q.cncMode);
    EXPECT_EQ(back.cncProgramFolder, q.cncProgramFolder);
    EXPECT_NO_THROW(validate(back));
    EXPECT_FALSE(toJson(RunRequest{}).contains(QStringLiteral("cnc")));
    EXPECT_EQ(refusedFieldOfJson(QJsonObject{{QStringLiteral("cnc"), QJsonObject{{QStringLiteral("port"), 5007}}}}),
              "cnc.port");
}

TEST(RunRequest, CncRefusalsNameTheField) {
    RunRequest q = throughLinuxCnc();
    q.cnc.clear();
    EXPECT_EQ(refusedField(q), "cnc.mode") << "a mode without a CNC";
    for (const char* url : {"fanuc://127.0.0.1:8193", "linuxcnc://", "linuxcnc://127.0.0.1:0", "linuxcnc://h:70000",
                            "linuxcnc://h:port", "linuxcnc://h/path", "127.0.0.1:5007"}) {
        q = throughLinuxCnc();
        q.cnc = QString::fromLatin1(url);
        EXPECT_EQ(refusedField(q), "cnc.url") << url;
    }
    for (const char* url : {"linuxcnc://127.0.0.1", "linuxcnc://lathe-7.plant:5007", "linuxcnc://[::1]:5007"}) {
        q = throughLinuxCnc();
        q.cnc = QString::fromLatin1(url);
        EXPECT_EQ(refusedField(q), "") << url;
    }
    q = throughLinuxCnc();
    q.cncMode = QStringLiteral("offset");
    EXPECT_EQ(refusedField(q), "cnc.mode");
    q = throughLinuxCnc();
    q.cncProgramFolder = QStringLiteral("/no/such/folder");
    EXPECT_EQ(refusedField(q), "cnc.program_folder");
    q = throughLinuxCnc();
    q.speed = 10.0;
    EXPECT_EQ(refusedField(q), "speed") << "a CNC goes at its own pace";
    q = throughLinuxCnc();
    q.preset = QStringLiteral("paper-2012");
    EXPECT_EQ(refusedField(q), "preset") << "the statistical plant has no lathe to cut on";
}

TEST(RunRequest, UnknownAndMistypedFieldsAreRefusedByName) {
    auto fieldOf = [](const QJsonObject& json) {
        try {
            runRequestFromJson(json);
        } catch (const RunRequestError& e) {
            return e.field;
        }
        return std::string();
    };
    EXPECT_EQ(fieldOf({{QStringLiteral("sead"), 3}}), "sead");
    EXPECT_EQ(fieldOf({{QStringLiteral("seed"), QStringLiteral("three")}}), "seed");
    EXPECT_EQ(fieldOf({{QStringLiteral("delay"), 2.5}}), "delay");
    EXPECT_EQ(fieldOf({{QStringLiteral("plant_mismatch"), QJsonObject{{QStringLiteral("gain"), 2}}}}),
              "plant_mismatch.gain");
    EXPECT_EQ(fieldOf({{QStringLiteral("controller"), QStringLiteral("pid")}}), "controller");
    EXPECT_EQ(fieldOf({{QStringLiteral("ewma_weight"), QStringLiteral("best")}}), "ewma_weight");
}

TEST(RunRequest, AFileThatIsNotARequestIsRefusedInWords) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("r.json"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("[1, 2]");
    f.close();
    try {
        readRunRequestFile(path);
        FAIL() << "an array was taken as a request";
    } catch (const RunRequestError& e) {
        EXPECT_EQ(e.field, "request");
        EXPECT_NE(std::string(e.what()).find("must hold one JSON object"), std::string::npos) << e.what();
    }
    EXPECT_THROW(readRunRequestFile(dir.filePath(QStringLiteral("none.json"))), RunRequestError);
}

TEST(RunRequest, TheAppliedTuningReachesTheScenario) {
    core::RunToRunSetup tuned = config::loadRunToRunSetup(QStringLiteral("paper-2012"));
    tuned.weights.R2 *= 4.0;
    tuned.limits.maxStepMm = 0.05;
    tuned.integral.enabled = true;
    RunRequest q;
    q.tuning = config::controllerTuningToJson(tuned);
    const config::LoopScenario scenario = scenarioOf(runRequestFromJson(toJson(q)));
    EXPECT_DOUBLE_EQ(scenario.control.weights.R2(0, 0), tuned.weights.R2(0, 0));
    EXPECT_DOUBLE_EQ(scenario.control.limits.maxStepMm, 0.05);
    EXPECT_TRUE(scenario.control.integral.enabled);
    EXPECT_EQ(scenario.control.plant.points.front().disturbance.describe(),
              tuned.plant.points.front().disturbance.describe());
}

TEST(StoredRuns, TheRequestIsStoredOnceAndReadBack) {
    const RunRequest q = everything();
    const config::LoopScenario scenario = scenarioOf(q);
    const core::RunDescription d = storedRunDescription(q, core::planShaftRun(scenario, choiceOf(q)));
    EXPECT_EQ(d.machine, "m7");
    EXPECT_EQ(d.delayParts, 3);
    core::RunSummary run;
    run.runId = 4;
    run.description = d;
    RunRequest back = requestOfStoredRun(run);
    EXPECT_TRUE(back.database.isEmpty()) << "the history is where it was read from";
    back.database = q.database;
    EXPECT_EQ(toJson(back), toJson(q));
}

TEST(StoredRuns, TheOlderFormatsAreReadToo) {
    core::RunSummary simulate;
    simulate.runId = 1;
    simulate.description.settingsJson =
        R"({"source":"simulate","preset":"paper-2012","delay":2,"parts":500,"warmup":100,"seed":9,)"
        R"("controller":"ewma","ewma_weight":0.4})";
    const RunRequest s = requestOfStoredRun(simulate);
    EXPECT_EQ(s.endPart, std::optional<std::int64_t>(600));
    EXPECT_EQ(s.warmupParts, 100);
    EXPECT_EQ(s.ewmaWeight, std::optional<double>(0.4));
    core::RunSummary gui;
    gui.runId = 2;
    gui.description.settingsJson =
        R"({"source":"gui","preset":"paper-2012-group1","controller":"lqg","delay":2,"seed":"77",)"
        R"("ewma_weight":0.3,"machine":"real-lathe","last_part":40})";
    const RunRequest g = requestOfStoredRun(gui);
    EXPECT_EQ(g.machine, QStringLiteral("devices-lathe"));
    EXPECT_EQ(g.seed, 77u);
    EXPECT_EQ(g.endPart, std::optional<std::int64_t>(40));
    EXPECT_FALSE(g.ewmaWeight.has_value()) << "an LQG run keeps no EWMA weight";
    core::RunSummary foreign;
    foreign.runId = 3;
    foreign.description.settingsJson = R"({"source":"spreadsheet"})";
    EXPECT_THROW(requestOfStoredRun(foreign), RunRequestError);
}

}  // namespace
}  // namespace tt::runtime
