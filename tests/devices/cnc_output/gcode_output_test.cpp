// The G-code correction output writes the corrected path of the next part into a folder.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include "devices/api/steady_clock.h"
#include "devices/cnc_output/gcode_file_output.h"
#include "devices/cnc_output/gcode_output_factory.h"

namespace tt::devices {
namespace {

core::PartCorrection correction(std::int64_t part) {
    core::PartCorrection c;
    c.partNumber = part;
    c.pointZMm = {5.0, 30.0, 162.5, 262.5, 320.0};
    c.pointCorrectionMm = {-0.010, -0.040, -0.075, -0.030, -0.005};
    for (int i = 0; i <= 13; ++i) {
        c.path.zMm.push_back(25.0 * i);
        c.path.xCorrectionMm.push_back(-0.075 * std::sin(3.14159265 * i / 13.0));
    }
    return c;
}

TEST(GCodeOutput, WritesOneFilePerPartIntoTheFolder) {
    QTemporaryDir folder;
    SteadyClock clock;
    GCodeOutputFactory factory;
    const QVariantMap settings{{QStringLiteral("folder"), folder.path()},
                               {QStringLiteral("nominalDiameterMm"), 26.5},
                               {QStringLiteral("xMode"), QStringLiteral("radius")}};
    ASSERT_TRUE(factory.validate(DeviceKind::CorrectionOutput, settings, Validation::Full).isEmpty());
    auto device = factory.create(DeviceKind::CorrectionOutput, settings, DeviceContext{&clock});
    device->open();
    ASSERT_EQ(device->health().state, core::DeviceState::Ready);
    const core::OutputResult r = device->correctionOutput()->sendPartCorrection(correction(41));
    ASSERT_TRUE(r.ok) << r.message;
    QFile file(QDir(folder.path()).filePath(QStringLiteral("part-41.nc")));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QString text = QString::fromLatin1(file.readAll());
    EXPECT_TRUE(text.contains(QStringLiteral("(PART 41)")));
    EXPECT_TRUE(text.contains(QStringLiteral("RADIUS MODE")));
    EXPECT_EQ(text.count(QStringLiteral("(SEG ")), 13);  // one per path segment
    EXPECT_TRUE(text.contains(QStringLiteral("G1 X13.250 Z-325.000 (SEG 13 X325.000 DX0.000)")));
    EXPECT_EQ(device->liveValue(), QStringLiteral("part 41: part-41.nc"));
}

TEST(GCodeOutput, RefusesTheDynamicOffsetAndBadPathsAndAMissingFolder) {
    QTemporaryDir folder;
    SteadyClock clock;
    GCodeOutputFactory factory;
    auto device = factory.create(DeviceKind::CorrectionOutput, {{QStringLiteral("folder"), folder.path()}},
                                 DeviceContext{&clock});
    device->open();
    const core::OutputResult offset = device->correctionOutput()->sendDynamicOffset(0.01);
    EXPECT_FALSE(offset.ok);
    EXPECT_NE(offset.message.find("use a Modbus correction output"), std::string::npos);
    core::PartCorrection bad = correction(1);
    bad.path.xCorrectionMm[4] = 0.9;
    const core::OutputResult refused = device->correctionOutput()->sendPartCorrection(bad);
    EXPECT_FALSE(refused.ok);
    EXPECT_NE(refused.message.find("exceeds the limit"), std::string::npos);
    EXPECT_TRUE(QDir(folder.path()).entryList(QDir::Files).isEmpty());  // nothing written
    const auto issues =
        factory.validate(DeviceKind::CorrectionOutput,
                         {{QStringLiteral("folder"), folder.filePath(QStringLiteral("nope"))}}, Validation::Full);
    ASSERT_EQ(issues.size(), 1);
    EXPECT_TRUE(issues[0].message.contains(QStringLiteral("does not exist")));
    auto missing =
        factory.create(DeviceKind::CorrectionOutput,
                       {{QStringLiteral("folder"), folder.filePath(QStringLiteral("nope"))}}, DeviceContext{&clock});
    missing->open();
    EXPECT_EQ(missing->health().state, core::DeviceState::Error);
    EXPECT_FALSE(missing->correctionOutput()->sendPartCorrection(correction(2)).ok);
}

}  // namespace
}  // namespace tt::devices
