// What goes wrong between TrueTurn and LinuxCNC, against the real controller: an E-stop or a machine that is off
// (nothing is written, it is reported), a write LinuxCNC refuses and a value it holds that differs from the one
// written (not applied, reported, written again before the part is cut), and a reply that is garbage or cut off
// (refused by the parser, the connection reset). The faults on the wire come from a proxy between the two that
// changes one line: LinuxCNC itself then refuses the corrupted write or holds the changed value.
#include <gtest/gtest.h>

#include <atomic>

#include "config/loop_scenario.h"
#include "core/loop/loop_engine.h"
#include "devices/linuxcnc/linuxcnc_lathe.h"
#include "devices/linuxcnc/linuxcnc_lathe_offer.h"
#include "devices/linuxcnc/linuxcnc_settings.h"
#include "tests/devices/support/linuxcnc_test_machine.h"
#include "tests/devices/support/tcp_fault_proxy.h"

namespace {

using namespace tt;
using devices::linuxcnc::LinuxCncController;
using devices::linuxcnc::LinuxCncLathe;
using devices::linuxcnc::WriteOutcome;
using devices::linuxcnc::WriteRecord;

const std::vector<double> kCorrectionsMm{0.0123, -0.0211, 0.0157, 0.0309, -0.0087};

std::unique_ptr<LinuxCncLathe> makeLathe(const test::TestLinuxCnc& lc, const QString& url) {
    const config::LoopScenario scenario = config::loadLoopScenario(QStringLiteral("paper-2012-group1"));
    QVariantMap settings = devices::linuxcnc::settingsFromUrl(url, QStringLiteral("profile"));
    settings.insert(QStringLiteral("xMode"), QStringLiteral("radius"));
    return std::make_unique<LinuxCncLathe>(scenario, 5,
                                           devices::linuxcnc::latheOptions(settings, lc.programFolder(), true));
}

core::PartCorrection correctionFor(std::int64_t part, const std::vector<double>& corrections) {
    const config::LoopScenario scenario = config::loadLoopScenario(QStringLiteral("paper-2012-group1"));
    return core::partCorrectionFor(scenario.loopConfig(true, std::nullopt), part, corrections);
}

/// Sends the corrections and starts the part; true when it is cut within `seconds`.
bool cut(LinuxCncLathe& lathe, std::int64_t part, const std::vector<double>& corrections, double seconds = 120.0) {
    const core::OutputResult sent = lathe.output().sendPartCorrection(correctionFor(part, corrections));
    EXPECT_TRUE(sent.ok) << sent.message;
    const core::OutputResult started = lathe.cycle().startPart(part);
    EXPECT_TRUE(started.ok) << started.message;
    return test::waitUntil([&] { return lathe.cycle().takeFinishedPart().has_value(); }, seconds);
}

bool anyContains(const std::vector<std::string>& texts, const std::string& part) {
    return std::any_of(texts.begin(), texts.end(),
                       [&](const std::string& t) { return t.find(part) != std::string::npos; });
}

std::string joined(const std::vector<std::string>& texts) {
    std::string all;
    for (const std::string& t : texts)
        all += t + "\n";
    return all;
}

TEST(LinuxCncFaults, AnEStopOrAMachineThatIsOffGetsNoWriteAndIsReported) {
    TT_REQUIRE_LINUXCNC(lc);
    auto lathe = makeLathe(*lc, lc->url());
    // A value TrueTurn did not write, to see that nothing is written during the E-stop.
    ASSERT_TRUE(test::operate(lathe->session(), [](LinuxCncController& c) {
        test::bringUp(c);
        c.setMode(devices::linuxcnc::TaskMode::Mdi);
        c.mdi("#500=0.432100 #505=0", 5000);
        c.request("set estop on");
    }));
    ASSERT_TRUE(lathe->output().sendPartCorrection(correctionFor(1, kCorrectionsMm)).ok);
    ASSERT_TRUE(lathe->cycle().startPart(1).ok) << "the part waits; the write is not tried while in E-stop";
    ASSERT_TRUE(test::waitUntil([&] { return lathe->snapshot().counters.writesHeld >= 1; }, 30.0));
    const std::string where = "LinuxCNC " + lc->endpoint().text();
    const std::vector<std::string> incidents = lathe->takeIncidents();
    EXPECT_TRUE(anyContains(incidents, "the E-stop is on at " + where + "; nothing written")) << joined(incidents);
    EXPECT_EQ(lathe->cycle().health().state, core::DeviceState::Error);
    EXPECT_FALSE(lathe->cycle().takeFinishedPart().has_value());
    const std::vector<WriteRecord> held = lathe->takeWrites();
    ASSERT_FALSE(held.empty());
    EXPECT_EQ(held.front().outcome, WriteOutcome::NotReady);
    EXPECT_FALSE(held.front().applied());
    EXPECT_TRUE(held.front().writtenMm.empty());

    // The operator clears the E-stop; before TrueTurn writes again, LinuxCNC still holds the old values.
    std::vector<double> before;
    ASSERT_TRUE(test::operate(lathe->session(), [&](LinuxCncController& c) {
        test::bringUp(c);
        c.setMode(devices::linuxcnc::TaskMode::Mdi);
        before = c.readParameters({"#500", "#505"});
    }));
    EXPECT_EQ(before, (std::vector<double>{0.4321, 0.0})) << "nothing was written during the E-stop";
    ASSERT_TRUE(test::waitUntil([&] { return lathe->cycle().takeFinishedPart().has_value(); }, 120.0))
        << "part 1 is cut once the machine is ready";
    // A part whose path the sampling did not see whole (a busy computer) is cut again, with a write of its own.
    EXPECT_EQ(lathe->snapshot().counters.writesVerified, 1u + lathe->partsCutAgain());

    // The machine off (no E-stop): the same.
    ASSERT_TRUE(test::operate(lathe->session(), [](LinuxCncController& c) { c.request("set machine off"); }));
    ASSERT_TRUE(lathe->output().sendPartCorrection(correctionFor(2, kCorrectionsMm)).ok);
    ASSERT_TRUE(lathe->cycle().startPart(2).ok);
    ASSERT_TRUE(
        test::waitUntil([&] { return anyContains(lathe->takeIncidents(), "the machine is off at " + where); }, 30.0));
    ASSERT_TRUE(test::operate(lathe->session(), [&](LinuxCncController& c) {
        test::bringUp(c);
        c.setMode(devices::linuxcnc::TaskMode::Mdi);
        before = c.readParameters({"#505"});
    }));
    EXPECT_EQ(before, std::vector<double>{0.0}) << "part 1's program cleared its part number; part 2's is not written";
    EXPECT_TRUE(test::waitUntil([&] { return lathe->cycle().takeFinishedPart().has_value(); }, 120.0));
}

TEST(LinuxCncFaults, AWriteLinuxCncRefusesIsNotAppliedIsReportedAndIsWrittenAgainBeforeThePart) {
    TT_REQUIRE_LINUXCNC(lc);
    test::bringUpNow(*lc);
    test::TcpFaultProxy proxy(lc->host, lc->port);
    std::atomic<int> corrupted{0};
    // The first write of the corrections arrives with a word LinuxCNC cannot read: LinuxCNC refuses it.
    proxy.onRequest([&](const std::string& line) -> std::optional<test::TcpFaultProxy::Action> {
        if (line.rfind("set mdi #500=", 0) != 0 || corrupted.fetch_add(1) > 0) return std::nullopt;
        return test::TcpFaultProxy::Action{"set mdi #500=Q" + line.substr(13), false};
    });
    auto lathe = makeLathe(*lc, QStringLiteral("linuxcnc://127.0.0.1:%1").arg(proxy.port()));
    ASSERT_TRUE(cut(*lathe, 1, kCorrectionsMm));
    const std::vector<WriteRecord> writes = lathe->takeWrites();
    const std::uint64_t again = lathe->partsCutAgain();  // each with a write of its own
    ASSERT_EQ(writes.size(), 2u + again);
    EXPECT_EQ(writes[0].outcome, WriteOutcome::Refused);
    EXPECT_FALSE(writes[0].applied());
    EXPECT_NE(writes[0].message.find("LinuxCNC refused the corrections"), std::string::npos) << writes[0].message;
    EXPECT_EQ(writes[1].outcome, WriteOutcome::Verified);
    EXPECT_EQ(writes[1].partNumber, 1);
    const auto counters = lathe->snapshot().counters;
    EXPECT_EQ(counters.writesRefused, 1u);
    EXPECT_EQ(counters.writesVerified, 1u + again);
    EXPECT_EQ(counters.partsCut, 1u + again) << "the part is cut once, with the verified corrections";
    EXPECT_TRUE(anyContains(lathe->takeIncidents(), "refused the corrections"));
}

TEST(LinuxCncFaults, AValueLinuxCncHoldsThatDiffersFromTheOneWrittenIsNotApplied) {
    TT_REQUIRE_LINUXCNC(lc);
    test::bringUpNow(*lc);
    test::TcpFaultProxy proxy(lc->host, lc->port);
    std::atomic<int> changed{0};
    // On its way, the first write's #502 becomes 1 um larger: LinuxCNC holds another value than TrueTurn wrote.
    proxy.onRequest([&](const std::string& line) -> std::optional<test::TcpFaultProxy::Action> {
        const std::size_t at = line.find("#502=");
        if (line.rfind("set mdi #500=", 0) != 0 || at == std::string::npos || changed.fetch_add(1) > 0)
            return std::nullopt;
        const std::size_t end = line.find(' ', at);
        const double value = std::stod(line.substr(at + 5, end - at - 5)) + 0.001;
        char text[32];
        std::snprintf(text, sizeof text, "%.6f", value);
        return test::TcpFaultProxy::Action{line.substr(0, at + 5) + text + line.substr(end), false};
    });
    auto lathe = makeLathe(*lc, QStringLiteral("linuxcnc://127.0.0.1:%1").arg(proxy.port()));
    ASSERT_TRUE(cut(*lathe, 1, kCorrectionsMm));
    const std::vector<WriteRecord> writes = lathe->takeWrites();
    const std::uint64_t again = lathe->partsCutAgain();  // each with a write of its own
    ASSERT_EQ(writes.size(), 2u + again);
    EXPECT_EQ(writes[0].outcome, WriteOutcome::Differs);
    EXPECT_FALSE(writes[0].applied());
    ASSERT_EQ(writes[0].readBackMm.size(), 5u) << "what LinuxCNC holds, read back for the report";
    EXPECT_NEAR(writes[0].readBackMm[2], writes[0].writtenMm[2] + 0.001, 1e-9);
    EXPECT_NEAR(writes[0].readBackMm[1], writes[0].writtenMm[1], 1e-9);
    EXPECT_NE(writes[0].message.find("but LinuxCNC holds"), std::string::npos) << writes[0].message;
    EXPECT_EQ(writes[1].outcome, WriteOutcome::Verified);
    EXPECT_EQ(writes[1].readBackMm, writes[1].writtenMm);
    EXPECT_EQ(lathe->snapshot().counters.readBacksDiffered, 1u);
    EXPECT_EQ(lathe->snapshot().counters.partsCut, 1u + again);
}

TEST(LinuxCncFaults, AGarbledReplyIsRefusedAndTheConnectionResetAndThePartIsCutAgain) {
    TT_REQUIRE_LINUXCNC(lc);
    test::bringUpNow(*lc);
    test::TcpFaultProxy proxy(lc->host, lc->port);
    std::atomic<int> garbled{0};
    // While the cut runs, one status reply arrives with a control character in it.
    proxy.onReply([&](const std::string& line) -> std::optional<test::TcpFaultProxy::Action> {
        if (line != "PROGRAM_STATUS RUNNING" || garbled.fetch_add(1) != 3) return std::nullopt;
        return test::TcpFaultProxy::Action{std::string("PROGRAM_STATUS RUN\x01NING"), false};
    });
    auto lathe = makeLathe(*lc, QStringLiteral("linuxcnc://127.0.0.1:%1").arg(proxy.port()));
    ASSERT_TRUE(cut(*lathe, 1, kCorrectionsMm));
    const auto s = lathe->snapshot();
    EXPECT_GE(s.counters.connectionResets, 1u);
    EXPECT_EQ(s.counters.partsAborted, 1u) << "the interrupted cut is not counted";
    EXPECT_EQ(s.counters.partsCut, 1u + lathe->partsCutAgain());
    EXPECT_GE(proxy.connections(), 2);
    EXPECT_TRUE(anyContains(lathe->takeIncidents(), "not printable")) << s.lastProblem;
}

TEST(LinuxCncFaults, AReplyCutOffIsRefusedAndTheConnectionResetAndThePartIsCutAgain) {
    TT_REQUIRE_LINUXCNC(lc);
    test::bringUpNow(*lc);
    test::TcpFaultProxy proxy(lc->host, lc->port);
    std::atomic<int> positions{0};
    // The 200th position reply (during the cut) stops in the middle and the connection ends.
    proxy.onReply([&](const std::string& line) -> std::optional<test::TcpFaultProxy::Action> {
        if (line.rfind("ABS_ACT_POS ", 0) != 0 || positions.fetch_add(1) != 200) return std::nullopt;
        return test::TcpFaultProxy::Action{line.substr(0, 20), true};
    });
    auto lathe = makeLathe(*lc, QStringLiteral("linuxcnc://127.0.0.1:%1").arg(proxy.port()));
    ASSERT_TRUE(cut(*lathe, 1, kCorrectionsMm));
    const auto s = lathe->snapshot();
    EXPECT_GE(s.counters.connectionResets, 1u);
    EXPECT_EQ(s.counters.partsAborted, 1u);
    EXPECT_EQ(s.counters.partsCut, 1u + lathe->partsCutAgain());
    EXPECT_TRUE(anyContains(lathe->takeIncidents(), "in the middle of a reply")) << s.lastProblem;
}

}  // namespace
