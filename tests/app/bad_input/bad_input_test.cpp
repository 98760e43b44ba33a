#include <gtest/gtest.h>

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>

#include "cli_test.h"
#include "tests/support/patient_wait.h"

// Bad input through the real binary (issue 17, "Bad input"): every case used to crash, hang or
// answer wrongly with exit 0; each must now be refused with exit 2 and one line naming the limit.

namespace {

using tt::test::CliResult;
using tt::test::expectRefused;
using tt::test::runTrueturn;

class BadInput : public tt::test::CliTest {
protected:
    /// A preset file `name` that takes its sections from `base` (a preset name or path).
    QString presetBasedOn(const QString& name, const QString& base) {
        return write(name, QStringLiteral("{\"name\": \"%1\", \"description\": \"test\", \"based_on\": \"%2\"}")
                               .arg(name, base)
                               .toUtf8());
    }

    static QStringList simulate(const QString& preset) {
        return {QStringLiteral("simulate"), QStringLiteral("--preset"), preset,
                QStringLiteral("--parts"),  QStringLiteral("100"),      QStringLiteral("--json")};
    }
};

TEST_F(BadInput, PresetBasedOnItselfIsRefusedWithTheChain) {
    const QString self = path(QStringLiteral("self.json"));
    presetBasedOn(QStringLiteral("self.json"), self);
    expectRefused(simulate(self), QStringLiteral("based_on: cycle"));
}

TEST_F(BadInput, TwoPresetsNamingEachOtherAreRefused) {
    const QString a = path(QStringLiteral("a.json"));
    const QString b = path(QStringLiteral("b.json"));
    presetBasedOn(QStringLiteral("a.json"), b);
    presetBasedOn(QStringLiteral("b.json"), a);
    expectRefused(simulate(a), QStringLiteral("a.json -> ") + b + QStringLiteral(" -> ") + a);
}

TEST_F(BadInput, APresetChainDeeperThanTheLimitIsRefused) {
    // p0 <- p1 <- ... <- p9: ten levels, above the limit of 8 (config/loop_scenario.h).
    presetBasedOn(QStringLiteral("p0.json"), QStringLiteral("paper-2012"));
    for (int i = 1; i < 10; ++i)
        presetBasedOn(QStringLiteral("p%1.json").arg(i), path(QStringLiteral("p%1.json").arg(i - 1)));
    expectRefused(simulate(path(QStringLiteral("p9.json"))), QStringLiteral("deeper than 8"));
}

TEST_F(BadInput, AResumedRunWhosePresetBecameACycleIsRefused) {
    // The run keeps its preset's path; the file is then changed to name itself, and the run resumed.
    const QString preset = path(QStringLiteral("resumed.json"));
    presetBasedOn(QStringLiteral("resumed.json"), QStringLiteral("paper-2012"));
    const QString db = path(QStringLiteral("history.db"));
    QStringList args = simulate(preset);
    args << QStringLiteral("--db") << db;
    const CliResult first = runTrueturn(args);
    ASSERT_EQ(first.exitCode, 0) << qPrintable(first.err);
    QProcess sqlite;  // an interrupted run: the history says it is still running
    sqlite.start(QStringLiteral("sqlite3"), {db, QStringLiteral("UPDATE runs SET status = 'running'")});
    ASSERT_TRUE(sqlite.waitForFinished(tt::test::kPatientWaitMs));
    ASSERT_EQ(sqlite.exitCode(), 0);
    presetBasedOn(QStringLiteral("resumed.json"), preset);
    expectRefused({QStringLiteral("simulate"), QStringLiteral("--resume"), QStringLiteral("--db"), db},
                  QStringLiteral("based_on: cycle"));
}

TEST_F(BadInput, AShortPresetChainStillWorks) {
    presetBasedOn(QStringLiteral("p0.json"), QStringLiteral("paper-2012"));
    presetBasedOn(QStringLiteral("p1.json"), path(QStringLiteral("p0.json")));
    const CliResult r = runTrueturn(simulate(path(QStringLiteral("p1.json"))));
    EXPECT_EQ(r.exitCode, 0) << qPrintable(r.err);
}

TEST_F(BadInput, ADisturbanceOfAThousandComponentsIsRefusedAtTheModelLimit) {
    // 1000 first-order components made a 1000-state model per point, and the run never finished.
    QByteArray components;
    for (int i = 0; i < 1000; ++i)
        components += QByteArray(i == 0 ? "" : ",") + R"({"type": "ar1", "pole": 0.5, "variance_mm2": 1e-5})";
    const QString preset = write(QStringLiteral("order.json"),
                                 R"({"name": "order", "description": "test", "based_on": "paper-2012", "plant": {)"
                                 R"("part_length_mm": 325, "gain": 2, "gauge_noise_variance_mm2": 2.5e-7, )"
                                 R"("disturbance": [)" +
                                     components + "]}}");
    expectRefused(simulate(preset), QStringLiteral("1000 components; the limit is 8"));
}

TEST_F(BadInput, ABoringPassOfTrillionsOfStepsIsRefusedBeforeItStarts) {
    // Every value in range, but 5000 mm at 0.01 mm/rev and 1 rpm in 0.01 ms steps is 3e12 steps.
    QFile file(QStringLiteral(TRUETURN_SOURCE_DIR "/resources/presets/heavy-boring.json"));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    QJsonObject preset = QJsonDocument::fromJson(file.readAll()).object();
    QJsonObject cut = preset.value(QStringLiteral("cut")).toObject();
    cut.insert(QStringLiteral("bore_length_mm"), 5000);
    cut.insert(QStringLiteral("feed_mm_per_rev"), 0.01);
    cut.insert(QStringLiteral("spindle_rpm"), 1);
    preset.insert(QStringLiteral("cut"), cut);
    preset.insert(QStringLiteral("simulation"), QJsonObject{{QStringLiteral("step_ms"), 0.01}});
    const QString path = write(QStringLiteral("slow.json"), QJsonDocument(preset).toJson());
    expectRefused({QStringLiteral("boring"), QStringLiteral("--preset"), path, QStringLiteral("--json")},
                  QStringLiteral("the limit is 7200 s"));
}

TEST_F(BadInput, AnEndlessInputFileIsRefusedAtTheByteLimit) {
    // /dev/zero never ends: the reader stops at the limit of 16 MiB (core/common/bounded_input.h).
    expectRefused({QStringLiteral("fit-profile"), QStringLiteral("/dev/zero")}, QStringLiteral("16777216 bytes"));
    expectRefused(
        {QStringLiteral("linearise"), QStringLiteral("/dev/zero"), QStringLiteral("--adc-bits"), QStringLiteral("12")},
        QStringLiteral("16777216 bytes"));
}

TEST_F(BadInput, ALineOfCommasIsRefusedAtTheLineLengthLimit) {
    const QString csv = write(QStringLiteral("commas.csv"), "x_mm,error_mm\n" + QByteArray(100000, ',') + '\n');
    expectRefused({QStringLiteral("fit-profile"), csv}, QStringLiteral("line 2 is longer than 4096 characters"));
}

TEST_F(BadInput, TooManyRowsAreRefusedAtTheRowLimit) {
    QByteArray text = "x_mm,error_mm\n";
    for (int i = 0; i < 1000000; ++i)
        text += "1,0\n";
    expectRefused({QStringLiteral("fit-profile"), write(QStringLiteral("rows.csv"), text)},
                  QStringLiteral("more than 1000000 lines"));
}

TEST_F(BadInput, CommaDecimalsAreRefusedNamingTheLocale) {
    // "12,5" with a comma separator used to be read as 12 (and the 5 dropped with the rest of the row).
    const QString csv =
        write(QStringLiteral("comma.csv"), "reference_um,adc_code\n-300,100\n-212,5,400\n-100,900\n0,2047\n100,3000\n");
    expectRefused({QStringLiteral("linearise"), csv, QStringLiteral("--adc-bits"), QStringLiteral("12")},
                  QStringLiteral("C locale"));
}

TEST_F(BadInput, CommaDecimalsInAProfileAreRefusedNamingTheLocale) {
    const QString csv = write(QStringLiteral("comma_profile.csv"), "x_mm,error_mm\n0,5,0,01\n1,5,0,02\n");
    expectRefused({QStringLiteral("fit-profile"), csv}, QStringLiteral("C locale"));
    const QString experiment =
        write(QStringLiteral("comma_experiment.csv"), "a_mm,f_mm_rev,z_mm,y_um\n0,5,0,1,10,12,5\n");
    expectRefused({QStringLiteral("fit-deformation"), experiment}, QStringLiteral("C locale"));
}

TEST_F(BadInput, AnExtraColumnIsRefusedByName) {
    const QString csv =
        write(QStringLiteral("extra.csv"), "reference_um,adc_code,temperature_c\n-300,100,20\n0,2047,20\n");
    expectRefused({QStringLiteral("linearise"), csv, QStringLiteral("--adc-bits"), QStringLiteral("12")},
                  QStringLiteral("temperature_c"));
}

TEST_F(BadInput, ProfileValuesOutsideTheirRangeAreRefused) {
    // Near 1e308 the degree-1 and degree-2 fits overflowed to inf/NaN standard errors and left with exit 0.
    const QString huge = write(QStringLiteral("huge.csv"), "x_mm,error_mm\n0,1e300\n1,-1e300\n2,1.7e300\n3,-1e300\n");
    for (const QString& degree : {QStringLiteral("1"), QStringLiteral("2")})
        expectRefused(
            {QStringLiteral("fit-profile"), huge, QStringLiteral("--degree"), degree, QStringLiteral("--json")},
            QStringLiteral("outside -100 .. 100 mm"));
    const QString far = write(QStringLiteral("far.csv"), "x_mm,error_mm\n0,0.01\n1e300,0.02\n2e300,0.01\n");
    expectRefused({QStringLiteral("fit-profile"), far, QStringLiteral("--degree"), QStringLiteral("1")},
                  QStringLiteral("outside -100000 .. 100000 mm"));
}

TEST_F(BadInput, JsonToAFullDiskIsAFailure) {
    QByteArray text = "x_mm,error_mm\n";
    for (int i = 0; i <= 13; ++i)
        text += QByteArray::number(25.0 * i) + ',' + QByteArray::number(0.001 * i * i) + '\n';
    const QString csv = write(QStringLiteral("ok.csv"), text);
    for (const QString& format : {QStringLiteral("--json"), QStringLiteral("--degree")}) {
        QStringList args{QStringLiteral("fit-profile"), csv};
        if (format == QStringLiteral("--degree"))
            args << QStringLiteral("--degree") << QStringLiteral("2");
        else
            args << format;
        QProcess process;
        process.setStandardOutputFile(QStringLiteral("/dev/full"));
        process.start(QStringLiteral(TRUETURN_EXE), args);
        ASSERT_TRUE(process.waitForFinished(tt::test::kPatientWaitMs));
        EXPECT_EQ(process.exitCode(), 1) << qPrintable(args.join(' '));
        EXPECT_TRUE(
            QString::fromUtf8(process.readAllStandardError()).contains(QStringLiteral("cannot write the output")));
    }
}

}  // namespace
