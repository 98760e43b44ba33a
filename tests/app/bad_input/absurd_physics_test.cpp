#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "cli_test.h"

// Absurd physics in a preset (issue 17, item 3): every value was "positive" and ran, giving k_eff 1 with
// a specific cutting force of 1e300 N/mm², a singular beam with Young's modulus 1e300, k_eff 0 with a
// systematic error of 1e300 mm. Each is now refused before the run, naming the value and the limit.

namespace {

using tt::test::expectRefused;

/// `value` put at `path` (keys, or array indexes as numbers) inside `object`.
QJsonValue withValue(const QJsonValue& object, QStringList path, const QJsonValue& value) {
    if (path.isEmpty()) return value;
    const QString key = path.takeFirst();
    bool isIndex = false;
    const int index = key.toInt(&isIndex);
    if (isIndex) {
        QJsonArray a = object.toArray();
        a[index] = withValue(a.at(index), path, value);
        return a;
    }
    QJsonObject o = object.toObject();
    o.insert(key, withValue(o.value(key), path, value));
    return o;
}

class AbsurdPhysics : public tt::test::CliTest {
protected:
    /// The built-in preset `name` with `value` at the slash-separated `path`, written as a file.
    QString presetWith(const QString& name, const QString& path, double value) {
        QFile file(QStringLiteral(TRUETURN_SOURCE_DIR "/resources/presets/") + name + QStringLiteral(".json"));
        EXPECT_TRUE(file.open(QIODevice::ReadOnly));
        const QJsonValue preset =
            withValue(QJsonDocument::fromJson(file.readAll()).object(), path.split(QLatin1Char('/')), value);
        return write(name + QStringLiteral("-changed.json"), QJsonDocument(preset.toObject()).toJson());
    }

    static QStringList simulate(const QString& preset) {
        return {QStringLiteral("simulate"), QStringLiteral("--preset"), preset,
                QStringLiteral("--parts"),  QStringLiteral("100"),      QStringLiteral("--warmup"),
                QStringLiteral("0"),        QStringLiteral("--json")};
    }
};

TEST_F(AbsurdPhysics, LatheValuesOutsideTheirPhysicalRangeAreRefusedWithTheRange) {
    const QString group = QStringLiteral("paper-2012-group1");
    struct Case {
        const char* path;
        double value;
        const char* phrase;
    };
    const Case cases[] = {
        {"lathe/workpiece/young_modulus_n_per_mm2", 1e300, "Young's modulus 1e+300 N/mm² is outside 500 .. 1.2e+06"},
        {"lathe/stiffness/headstock_n_per_mm", 1e-300, "the headstock stiffness 1e-300 N/mm is outside 100 .. 1e+07"},
        {"lathe/stiffness/tool_n_per_mm", 1e-9, "the cutter stiffness 1e-09 N/mm is outside 100 .. 1e+07"},
        {"lathe/stiffness/tailstock_n_per_mm", 0, "tailstock_n_per_mm: 0 must be > 0"},
        {"lathe/stiffness/tailstock_n_per_mm", -5, "tailstock_n_per_mm: -5 must be > 0"},
        {"lathe/force/specific_force_n_per_mm2", 1e300,
         "the specific cutting force 1e+300 N/mm² is outside 10 .. 10000 N/mm²"},
        {"lathe/cutting/speed_m_per_min", 1e9, "the cutting speed 1e+09 m/min is outside 0.1 .. 2000 m/min"},
        {"lathe/element_length_mm", 1e300, "the element length of the shaft model 1e+300 mm is longer than a tenth"},
        {"lathe/station/part_time_s", 1e300, "lathe.station.part_time_s: 1e+300 is outside 1 .. 86400"},
    };
    for (const Case& c : cases)
        expectRefused(simulate(presetWith(group, QString::fromLatin1(c.path), c.value)), QString::fromUtf8(c.phrase));
}

TEST_F(AbsurdPhysics, ASystematicErrorOfAbsurdSizeIsRefusedInsteadOfAKeffOfZero) {
    expectRefused(simulate(presetWith(QStringLiteral("paper-2012-group1"),
                                      QStringLiteral("systematic_model/coefficients/0"), 1e300)),
                  QStringLiteral("the model reaches 1e+300 mm at x = 0 mm; the limit is ±10 mm on diameter"));
    expectRefused(simulate(presetWith(QStringLiteral("paper-2012-group1"),
                                      QStringLiteral("systematic_model/coefficients/2"), 1e-3)),
                  QStringLiteral("the limit is ±10 mm on diameter"));
}

TEST_F(AbsurdPhysics, PlantVariancesAndCorrectionLimitsOutsideTheirRangeAreRefused) {
    for (const char* path : {"plant/gauge_noise_variance_mm2", "plant/disturbance/0/variance_mm2"})
        expectRefused(simulate(presetWith(QStringLiteral("paper-2012"), QString::fromLatin1(path), 1e300)),
                      QStringLiteral("1e+300 is outside 0 .. 100"));
    expectRefused(
        simulate(presetWith(QStringLiteral("paper-2012"), QStringLiteral("controller/max_correction_mm"), 1e300)),
        QStringLiteral("max_correction_mm: 1e+300 is outside 0 .. 100"));
}

TEST_F(AbsurdPhysics, ABoringProbeCharacteristicOfAbsurdSizeIsRefused) {
    // The probe's bridge ratio r(u) = sum c_i u^i with c_1 = 1e300 used to run and report a pass.
    expectRefused({QStringLiteral("boring"), QStringLiteral("--preset"),
                   presetWith(QStringLiteral("heavy-boring"), QStringLiteral("probe/bridge_coefficients/1"), 1e300),
                   QStringLiteral("--json")},
                  QStringLiteral("bridge_coefficients: 1e+300 is outside -10 .. 10"));
}

TEST_F(AbsurdPhysics, ALatheWithoutVariationPrintsNoKeffOfZero) {
    // No random variation, no wear, no warm-up, a perfect micrometer: the open loop's parts are all alike
    // (variance 0), and k_eff = 0 / closed used to be printed as 0 (and 0 / 0 as NaN).
    QString preset = presetWith(QStringLiteral("paper-2012-group1"), QStringLiteral("lathe/random_scale"), 0);
    QFile file(preset);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    QJsonValue json = QJsonDocument::fromJson(file.readAll()).object();
    file.close();
    for (const char* path : {"lathe/micrometer/resolution_mm", "lathe/micrometer/error95_mm",
                             "lathe/tool_wear/diameter_growth_mm", "lathe/warm_up/diameter_shift_mm"})
        json = withValue(json, QString::fromLatin1(path).split(QLatin1Char('/')), 0);
    preset = write(QStringLiteral("still.json"), QJsonDocument(json.toObject()).toJson());
    for (const char* controller : {"lqg", "open"}) {
        QStringList args = simulate(preset);
        args << QStringLiteral("--controller") << QString::fromLatin1(controller);
        const tt::test::CliResult r = tt::test::runTrueturn(args);
        ASSERT_EQ(r.exitCode, 0) << qPrintable(r.err);
        EXPECT_TRUE(r.json().value(QStringLiteral("k_eff")).isNull()) << qPrintable(r.out);
        for (const QJsonValue& point : r.json().value(QStringLiteral("points")).toArray())
            EXPECT_TRUE(point.toObject().value(QStringLiteral("k_eff")).isNull()) << qPrintable(r.out);
        args.removeAll(QStringLiteral("--json"));
        const tt::test::CliResult text = tt::test::runTrueturn(args);
        EXPECT_TRUE(text.out.contains(QStringLiteral("k_eff n/a: the open- or closed-loop variance is below")))
            << qPrintable(text.out);
        EXPECT_FALSE(text.out.contains(QStringLiteral("k_eff (all points): 0 "))) << qPrintable(text.out);
    }
}

TEST_F(AbsurdPhysics, APartLengthOfThePlantOutsideItsRangeIsRefusedBeforeTheRun) {
    // It used to start and stop at part 1 with exit 1 (the correction path could not be sampled).
    expectRefused(simulate(presetWith(QStringLiteral("paper-2012"), QStringLiteral("plant/part_length_mm"), 1e300)),
                  QStringLiteral("plant.part_length_mm: 1e+300 mm is outside 1 .. 100000 mm"));
}

}  // namespace
