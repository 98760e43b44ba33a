// Valid set-ups that failed or lost keys: based_on merges objects key by key (arrays and values replace,
// null removes: JSON Merge Patch, RFC 7396), `simulate --dump-preset` prints the merged set-up, an absent
// correction limit (unlimited) is written as null instead of refused after the run, and the warm-up's parts
// are named in the JSON and in the verdicts.
#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "cli_test.h"

namespace {

using tt::test::CliResult;
using tt::test::expectRefused;
using tt::test::runTrueturn;

class SetUpMerge : public tt::test::CliTest {
protected:
    /// `simulate --preset P --dump-preset`, parsed; a failure fails the test.
    static QJsonObject dump(const QString& preset) {
        const CliResult r = runTrueturn({"simulate", "--preset", preset, "--dump-preset"});
        EXPECT_EQ(r.exitCode, 0) << qPrintable(r.err);
        return r.json();
    }
    QString preset(const QString& name, const QJsonObject& object) {
        return write(name, QJsonDocument(object).toJson());
    }
    static QJsonObject object(const char* json) { return QJsonDocument::fromJson(QByteArray(json)).object(); }
};

/// Every leaf of `base` (an object path "a/b/c") that is not in `changed` holds the same value in `merged`;
/// returns the number of leaves compared.
int expectLeavesKept(const QJsonValue& base, const QJsonValue& merged, const QStringList& changed,
                     const QString& path = QString()) {
    if (changed.contains(path)) return 0;
    if (!base.isObject()) {
        EXPECT_EQ(merged, base) << "lost or changed: " << qPrintable(path);
        return 1;
    }
    int leaves = 0;
    const QJsonObject b = base.toObject();
    for (auto it = b.begin(); it != b.end(); ++it)
        leaves += expectLeavesKept(it.value(), merged.toObject().value(it.key()), changed,
                                   path.isEmpty() ? it.key() : path + QLatin1Char('/') + it.key());
    return leaves;
}

TEST_F(SetUpMerge, OneKeyOverriddenInEachSectionKeepsEveryOtherKeyOfTheBase) {
    const QJsonObject base = dump(QStringLiteral("paper-2012-group1"));
    ASSERT_FALSE(base.isEmpty());
    EXPECT_FALSE(base.contains(QStringLiteral("based_on"))) << "the dump is the whole set-up";
    const QString file = preset(QStringLiteral("one-key-each.json"), object(R"({
        "based_on": "paper-2012-group1",
        "plant": {"gauge_noise_variance_mm2": 2e-6},
        "controller": {"ewma": {"dead_band_mm": 0.001}},
        "lathe": {"stiffness": {"tool_n_per_mm": 25000}},
        "systematic_model": {"source": "changed"},
        "loop": {"tolerance": {"fit": "h7"}}
    })"));
    const QJsonObject merged = dump(file);
    const QStringList changed{"name",
                              "description",
                              "plant/gauge_noise_variance_mm2",
                              "controller/ewma/dead_band_mm",
                              "lathe/stiffness/tool_n_per_mm",
                              "systematic_model/source",
                              "loop/tolerance"};
    // paper-2012-group1 has 56 leaves besides the changed ones (an array counts as one): all compared.
    EXPECT_GE(expectLeavesKept(base, merged, changed), 50);
    EXPECT_EQ(merged.value("plant").toObject().value("gauge_noise_variance_mm2").toDouble(), 2e-6);
    EXPECT_EQ(merged.value("controller").toObject().value("ewma").toObject().value("dead_band_mm").toDouble(), 0.001);
    EXPECT_EQ(merged.value("lathe").toObject().value("stiffness").toObject().value("tool_n_per_mm").toDouble(), 25000);
    EXPECT_EQ(merged.value("loop").toObject().value("tolerance").toObject().value("fit").toString(), "h7");
    // The README's example keeps the base's loop settings (the mismatch monitor only alarms on this lathe).
    const QJsonObject loop = merged.value("loop").toObject();
    EXPECT_EQ(loop.value("mismatch_monitor").toObject().value("action").toString(), "alarm");
    EXPECT_EQ(loop.value("nominal_diameter_mm").toDouble(), 27.0);
    EXPECT_EQ(loop.value("gauge_timeout_s").toDouble(), 600);
    EXPECT_EQ(loop.value("interpolation").toString(), "pchip");
}

TEST_F(SetUpMerge, ArraysReplaceAndNullRemoves) {
    const QString file = preset(QStringLiteral("arrays.json"), object(R"({
        "based_on": "paper-2012",
        "plant": {"points_mm": [0, 100, 200, 300, 325]},
        "controller": {"max_step_mm": null}
    })"));
    const QJsonObject merged = dump(file);
    EXPECT_EQ(merged.value("plant").toObject().value("points_mm").toArray(), (QJsonArray{0, 100, 200, 300, 325}));
    EXPECT_FALSE(merged.value("controller").toObject().contains("max_step_mm"));
    EXPECT_EQ(merged.value("controller").toObject().value("max_correction_mm").toDouble(), 0.3);
}

TEST_F(SetUpMerge, TheDumpLoadedAgainIsTheSameSetUp) {
    const QString file = preset(QStringLiteral("h7.json"), object(R"({"based_on": "paper-2012-group1",
                                                                        "loop": {"tolerance": {"fit": "h7"}}})"));
    const QJsonObject first = dump(file);
    const QString again = preset(QStringLiteral("dumped.json"), first);
    EXPECT_EQ(dump(again), first);
}

TEST_F(SetUpMerge, DumpPresetRunsNothingAndRefusesAHistory) {
    expectRefused({"simulate", "--dump-preset", "--db", path(QStringLiteral("h.sqlite"))},
                  QStringLiteral("--dump-preset: prints the set-up and runs nothing; leave --db out"));
    EXPECT_FALSE(QFile::exists(path(QStringLiteral("h.sqlite"))));
    expectRefused(
        {"simulate", "--preset", preset(QStringLiteral("bad.json"), object(R"({"based_on": 7})")), "--dump-preset"},
        QStringLiteral("based_on: must be the name of a preset"));
}

TEST_F(SetUpMerge, TheReadmeExampleKeepsTheMismatchMonitorAndRuns) {
    // Before the merge the base's whole loop section was lost: with seed 4 and z = 4 the monitor's default
    // (then hold) froze the correction at part 13. The base's monitor section now stays whole: its "alarm" and the
    // points' expected correlation (with it that run no longer alarms at all). A plant one part slower than the
    // model (--plant-delay 5) makes the monitor fire: the alarm only alarms.
    const QString file = preset(QStringLiteral("h7.json"), object(R"({"based_on": "paper-2012-group1",
                                                                        "loop": {"tolerance": {"fit": "h7"}}})"));
    const QJsonObject monitor = dump(file).value("loop").toObject().value("mismatch_monitor").toObject();
    EXPECT_EQ(monitor.value("action").toString(), QStringLiteral("alarm"));
    EXPECT_EQ(monitor.value("point_correlation").toDouble(), 0.8);
    const QStringList quiet{"simulate", "--preset", file, "--delay", "4", "--parts", "100", "--seed", "4", "--json"};
    const CliResult calm = runTrueturn(quiet);
    ASSERT_EQ(calm.exitCode, 0) << qPrintable(calm.err);
    EXPECT_TRUE(calm.json().value("alarms").toArray().isEmpty());
    const QStringList run = quiet + QStringList{"--plant-delay", "5"};
    const CliResult r = runTrueturn(run);
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonArray alarms = r.json().value("alarms").toArray();
    ASSERT_FALSE(alarms.isEmpty());
    for (const QJsonValue a : alarms)
        EXPECT_FALSE(a.toObject().value("held").toBool()) << "alarm only: the correction is never frozen";
    // What the lost key did: the same run told to hold freezes the correction at the same alarm.
    const CliResult held = runTrueturn(run + QStringList{"--mismatch-action", "hold"});
    ASSERT_EQ(held.exitCode, 0) << qPrintable(held.err);
    const QJsonObject first = held.json().value("alarms").toArray().first().toObject();
    EXPECT_TRUE(first.value("held").toBool());
    EXPECT_EQ(first.value("part").toInt(), alarms.first().toObject().value("part").toInt());
}

TEST_F(SetUpMerge, AnAbsentCorrectionLimitIsWrittenAsNullNotRefused) {
    QFile source(QStringLiteral(TRUETURN_SOURCE_DIR "/resources/presets/paper-2012.json"));
    ASSERT_TRUE(source.open(QIODevice::ReadOnly));
    QJsonObject preset = QJsonDocument::fromJson(source.readAll()).object();
    QJsonObject controller = preset.value("controller").toObject();
    controller.remove("max_correction_mm");
    controller.remove("max_step_mm");
    preset.insert("controller", controller);
    const QString withoutLimits = this->preset(QStringLiteral("unlimited.json"), preset);
    const QString nulled = this->preset(
        QStringLiteral("nulled.json"),
        object(R"({"based_on": "paper-2012", "controller": {"max_correction_mm": null, "max_step_mm": null}})"));
    for (const QString& file : {withoutLimits, nulled}) {
        const CliResult r = runTrueturn({"simulate", "--preset", file, "--parts", "100", "--warmup", "0", "--json"});
        ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
        const QJsonObject corrections = r.json().value("corrections").toObject();
        EXPECT_TRUE(corrections.value("limit_abs_mm").isNull());
        EXPECT_TRUE(corrections.value("limit_step_mm").isNull());
        EXPECT_GT(corrections.value("max_abs_mm").toDouble(), 0.0);
    }
    const CliResult limited = runTrueturn({"simulate", "--parts", "100", "--warmup", "0", "--json"});
    ASSERT_EQ(limited.exitCode, 0) << qPrintable(limited.err);
    EXPECT_EQ(limited.json().value("corrections").toObject().value("limit_abs_mm").toDouble(), 0.3);
}

TEST_F(SetUpMerge, TheWarmUpPartsAreNamedAndTheirVerdictsCountedApart) {
    const CliResult r = runTrueturn({"simulate", "--preset", "paper-2012-group1", "--parts", "150", "--seed", "3",
                                     "--db", path(QStringLiteral("h.sqlite")), "--json"});
    ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
    const QJsonObject j = r.json();
    EXPECT_EQ(j.value("parts").toInt(), 150);
    EXPECT_EQ(j.value("warmup_parts").toInt(), 100);
    const QJsonObject v = j.value("verdicts").toObject();
    const QJsonObject w = v.value("warmup").toObject();
    EXPECT_EQ(v.value("machined_parts").toInt(), 250);
    EXPECT_EQ(v.value("good").toInt() + v.value("rework").toInt() + v.value("scrap").toInt(), 250);
    EXPECT_EQ(w.value("good").toInt() + w.value("rework").toInt() + w.value("scrap").toInt(), 100);
    for (const char* k : {"good", "rework", "scrap"})
        EXPECT_LE(w.value(k).toInt(), v.value(k).toInt()) << k;
    const CliResult help = runTrueturn({"simulate", "--help"});
    EXPECT_TRUE(help.out.simplified().contains(QStringLiteral("--parts 150 machines 250 parts")))
        << qPrintable(help.out);
    const CliResult text = runTrueturn({"simulate", "--parts", "100", "--warmup", "20"});
    ASSERT_EQ(text.exitCode, 0) << qPrintable(text.err);
    EXPECT_TRUE(text.out.contains(QStringLiteral("verdicts of all 120 machined parts (warm-up included)")))
        << qPrintable(text.out);
    EXPECT_TRUE(text.out.contains(QStringLiteral("of the 20 warm-up parts"))) << qPrintable(text.out);
}

}  // namespace
