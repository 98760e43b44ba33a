// The corrections TrueTurn writes into LinuxCNC land on the path LinuxCNC executes: the LinuxCNC lathe samples
// the tool's position while the cut runs (LinuxCNC's own actual position, abs_act_pos) and each control point's
// correction must be there within 1 um on diameter, in diameter (G7) and radius (G8) mode, in mm and inch
// programs; likewise the one correction of the wear mode (the tool's X wear applied by G43.2).
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <cctype>
#include <cmath>
#include <numeric>
#include <ostream>

#include "config/loop_scenario.h"
#include "core/control/correction_path_builder.h"
#include "core/loop/loop_engine.h"
#include "devices/linuxcnc/linuxcnc_lathe.h"
#include "devices/linuxcnc/linuxcnc_lathe_offer.h"
#include "devices/linuxcnc/linuxcnc_settings.h"
#include "tests/devices/support/linuxcnc_test_machine.h"

namespace {

using namespace tt;
using devices::linuxcnc::LinuxCncLathe;

struct Conventions {
    const char* xMode;
    const char* units;
};

/// "diameter, mm": how gtest (and the test names ctest lists) show a parameter, instead of its raw bytes.
void PrintTo(const Conventions& c, std::ostream* os) {
    *os << c.xMode << ", " << c.units;
}

/// The corrections of the test, radial mm: different at every point, both signs, not round numbers.
const std::vector<double> kCorrectionsMm{0.0123, -0.0211, 0.0157, 0.0309, -0.0087};

/// Cuts part 1 on the LinuxCNC lathe with `corrections` and returns the executed path and the write record.
struct Cut {
    core::CorrectionPath executed;
    devices::linuxcnc::WriteRecord write;
    core::LoopConfig loop;
};

std::optional<Cut> cutOnePart(const test::TestLinuxCnc& lc, const QString& mode, const Conventions& c,
                              const std::vector<double>& corrections) {
    const config::LoopScenario scenario = config::loadLoopScenario(QStringLiteral("paper-2012-group1"));
    QVariantMap settings = devices::linuxcnc::settingsFromUrl(lc.url(), mode);
    settings.insert(QStringLiteral("xMode"), QString::fromLatin1(c.xMode));
    settings.insert(QStringLiteral("units"), QString::fromLatin1(c.units));
    LinuxCncLathe lathe(scenario, 5, devices::linuxcnc::latheOptions(settings, lc.programFolder(), true));
    if (!test::operate(lathe.session(), [](devices::linuxcnc::LinuxCncController& c) { test::bringUp(c); }))
        return std::nullopt;
    Cut cut;
    cut.loop = scenario.loopConfig(true, std::nullopt);
    const core::PartCorrection correction = core::partCorrectionFor(cut.loop, 1, corrections);
    EXPECT_TRUE(lathe.output().sendPartCorrection(correction).ok);
    const core::OutputResult started = lathe.cycle().startPart(1);
    EXPECT_TRUE(started.ok) << started.message;
    std::optional<core::FinishedPart> finished;
    test::waitUntil([&] { return (finished = lathe.cycle().takeFinishedPart()).has_value(); }, 120.0);
    if (!finished) {
        ADD_FAILURE() << "part 1 was not cut: " << lathe.snapshot().health.message;
        return std::nullopt;
    }
    const auto path = lathe.executedPath(1);
    if (!path) return std::nullopt;
    cut.executed = *path;
    const auto writes = lathe.takeWrites();
    if (writes.empty()) return std::nullopt;
    cut.write = writes.back();
    return cut;
}

/// The executed correction at z less the feed-forward (what the point corrections moved the cutter by), radial mm.
double pointPart(const Cut& cut, double z) {
    core::CorrectionPathRequest request;
    request.pointZMm = cut.loop.pointZMm;
    request.pointCorrectionMm.assign(cut.loop.pointZMm.size(), 0.0);
    request.diameterErrorModel = cut.loop.systematicModel;
    request.partLengthMm = cut.loop.partLengthMm;
    const core::CorrectionProfile feedForward(request);
    const auto& zs = cut.executed.zMm;
    const auto it = std::lower_bound(zs.begin(), zs.end(), z - 1e-9);
    EXPECT_NE(it, zs.end());
    EXPECT_NEAR(*it, z, 1e-9) << "the control points lie on the path's grid";
    return cut.executed.xCorrectionMm[static_cast<std::size_t>(it - zs.begin())] - feedForward.feedForwardMm(z);
}

class ProfilePath : public ::testing::TestWithParam<Conventions> {};

TEST_P(ProfilePath, EachCorrectionLandsOnTheExecutedPathAtItsControlPointWithinOneMicrometreOnDiameter) {
    TT_REQUIRE_LINUXCNC(lc);
    const auto cut = cutOnePart(*lc, QStringLiteral("profile"), GetParam(), kCorrectionsMm);
    ASSERT_TRUE(cut.has_value());
    ASSERT_TRUE(cut->write.applied()) << cut->write.message;
    ASSERT_EQ(cut->write.readBackMm, cut->write.writtenMm) << "read back equal to what was written";
    double worstUm = 0.0;
    for (std::size_t i = 0; i < kCorrectionsMm.size(); ++i) {
        EXPECT_NEAR(cut->write.writtenMm[i], kCorrectionsMm[i], 2.6e-5) << "six decimals of the program's unit";
        // Diameter = 2 x radius; 1 um on diameter.
        const double onDiameter = 2.0 * pointPart(*cut, cut->loop.pointZMm[i]);
        EXPECT_NEAR(onDiameter, 2.0 * cut->write.writtenMm[i], 0.001)
            << "point " << i + 1 << " at z = " << cut->loop.pointZMm[i] << " mm";
        worstUm = std::max(worstUm, 1000.0 * std::fabs(onDiameter - 2.0 * cut->write.writtenMm[i]));
        std::string key(1, 'z');
        key += std::to_string(static_cast<int>(cut->loop.pointZMm[i]));
        RecordProperty(key, std::to_string(1000.0 * (onDiameter - 2.0 * cut->write.writtenMm[i])));
    }
    RecordProperty("largest_difference_on_diameter_um", std::to_string(worstUm));
}

class WearPath : public ::testing::TestWithParam<Conventions> {};

TEST_P(WearPath, TheWearCorrectionLandsOnTheExecutedPathWithinOneMicrometreOnDiameter) {
    TT_REQUIRE_LINUXCNC(lc);
    const auto cut = cutOnePart(*lc, QStringLiteral("wear"), GetParam(), kCorrectionsMm);
    ASSERT_TRUE(cut.has_value());
    ASSERT_TRUE(cut->write.applied()) << cut->write.message;
    const double mean =
        std::accumulate(kCorrectionsMm.begin(), kCorrectionsMm.end(), 0.0) / static_cast<double>(kCorrectionsMm.size());
    ASSERT_EQ(cut->write.writtenMm.size(), 1u);
    EXPECT_NEAR(cut->write.writtenMm[0], mean, 2.6e-5) << "wear mode writes the mean correction";
    EXPECT_EQ(cut->write.readBackMm, cut->write.writtenMm);
    double worstUm = 0.0;
    for (const double z : cut->loop.pointZMm) {
        const double onDiameter = 2.0 * pointPart(*cut, z);
        EXPECT_NEAR(onDiameter, 2.0 * cut->write.writtenMm[0], 0.001) << "at z = " << z << " mm";
        worstUm = std::max(worstUm, 1000.0 * std::fabs(onDiameter - 2.0 * cut->write.writtenMm[0]));
        std::string key(1, 'z');
        key += std::to_string(static_cast<int>(z));
        RecordProperty(key, std::to_string(1000.0 * (onDiameter - 2.0 * cut->write.writtenMm[0])));
    }
    RecordProperty("largest_difference_on_diameter_um", std::to_string(worstUm));
}

const Conventions kConventions[] = {{"diameter", "mm"}, {"radius", "mm"}, {"diameter", "inch"}, {"radius", "inch"}};

/// "DiameterMm", "RadiusInch": the X mode and the units, each word capitalised (gtest names allow no other bytes).
std::string conventionName(const ::testing::TestParamInfo<Conventions>& info) {
    std::string name;
    for (const char* word : {info.param.xMode, info.param.units}) {
        std::string w(word);
        if (!w.empty()) w[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(w[0])));
        name += w;
    }
    return name;
}

INSTANTIATE_TEST_SUITE_P(Modes, ProfilePath, ::testing::ValuesIn(kConventions), conventionName);
INSTANTIATE_TEST_SUITE_P(Modes, WearPath, ::testing::ValuesIn(kConventions), conventionName);

}  // namespace
