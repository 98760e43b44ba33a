// LinuxCNC's remote shell replies, as the Debian 12 package (linuxcnc-uspace 2.9.0~pre1) writes them: the byte
// strings below were recorded from linuxcncrsh on the simulated lathe (scripts/start-test-linuxcnc.sh), with
// their line ends as sent (values CR LF, acknowledgements LF CR).
#include <gtest/gtest.h>

#include "devices/parsers/linuxcnc_reply.h"

namespace {

using namespace tt::devices::linuxcnc;

std::vector<std::string> frame(std::string_view bytes) {
    ReplyFramer f;
    return f.feed(bytes);
}

TEST(LinuxCncFramer, SplitsTheShellsMixedLineEndsAndSkipsEmptyLines) {
    // Recorded: "set verbose on" then "set nonsense" then "get nonsense" then "get estop" (one chunk each).
    const auto lines = frame("SET VERBOSE ACK\n\rSET NONSENSE NAK\n\rGET NONSENSE NAK\r\n\r\nESTOP ON\r\n");
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[0], "SET VERBOSE ACK");
    EXPECT_EQ(lines[1], "SET NONSENSE NAK");
    EXPECT_EQ(lines[2], "GET NONSENSE NAK");
    EXPECT_EQ(lines[3], "ESTOP ON");
}

TEST(LinuxCncFramer, KeepsAReplySplitOverChunksAndReportsWhatIsPending) {
    ReplyFramer f;
    EXPECT_TRUE(f.feed("ABS_ACT_POS 0.531496 0.000000 -0.29").empty());
    EXPECT_EQ(f.pending(), 35u) << "a reply cut off here stays pending: the connection's end shows it";
    const auto lines = f.feed("3701 0.000000 0.000000 0.000000\r\n");
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0], "ABS_ACT_POS 0.531496 0.000000 -0.293701 0.000000 0.000000 0.000000");
    EXPECT_EQ(f.pending(), 0u);
}

TEST(LinuxCncFramer, RefusesBinaryBytesAndOverlongLinesForGood) {
    ReplyFramer binary;
    EXPECT_TRUE(binary.feed(std::string("ESTOP O\x01N\r\nMACHINE ON\r\n", 22)).empty());
    EXPECT_TRUE(binary.corrupt());
    EXPECT_NE(binary.problem().find("not printable"), std::string::npos) << binary.problem();
    EXPECT_TRUE(binary.feed("ESTOP ON\r\n").empty()) << "nothing after corruption: the replies are out of step";
    binary.reset();
    EXPECT_EQ(binary.feed("ESTOP ON\r\n").size(), 1u);

    ReplyFramer longLines(16);
    EXPECT_TRUE(longLines.feed("OPERATOR_DISPLAY 0123456789").empty());
    EXPECT_TRUE(longLines.corrupt());
    EXPECT_NE(longLines.problem().find("longer than 16"), std::string::npos);
}

TEST(LinuxCncReply, ParsesHelloAcknowledgementsAndValues) {
    const auto hello = parseReply("HELLO ACK EMCNETSVR 1.1");
    ASSERT_TRUE(hello) << hello.error();
    EXPECT_EQ(hello->kind, ReplyKind::HelloAck);
    EXPECT_EQ(hello->words, (std::vector<std::string>{"EMCNETSVR", "1.1"}));
    EXPECT_EQ(parseReply("HELLO NAK")->kind, ReplyKind::HelloNak);
    EXPECT_EQ(parseReply("SET MDI ACK")->kind, ReplyKind::Ack);
    EXPECT_EQ(parseReply("SET MDI ACK")->key, "MDI");
    EXPECT_EQ(parseReply("SET MDI NAK")->kind, ReplyKind::Nak);
    EXPECT_EQ(parseReply("GET NONSENSE NAK")->kind, ReplyKind::Nak);
    const auto error = parseReply("ERROR Can't issue MDI command when not homed");
    ASSERT_TRUE(error);
    EXPECT_EQ(error->kind, ReplyKind::Value);
    EXPECT_EQ(error->key, "ERROR");
    EXPECT_EQ(error->text, "Can't issue MDI command when not homed");
    EXPECT_EQ(message(error.value(), "ERROR").value(), "Can't issue MDI command when not homed");
    EXPECT_EQ(message(parseReply("OPERATOR_DISPLAY OK").value(), "OPERATOR_DISPLAY").value(), "") << "OK: no message";
}

TEST(LinuxCncReply, RefusesGarbageAndMalformedAcknowledgements) {
    EXPECT_FALSE(parseReply(""));
    EXPECT_FALSE(parseReply("   "));
    EXPECT_FALSE(parseReply("HELLO ACK EMCNETSVR"));  // the version is missing: cut off
    EXPECT_FALSE(parseReply("HELLO MAYBE"));
    EXPECT_FALSE(parseReply("GET ESTOP ACK")) << "a get is never acknowledged";
    EXPECT_FALSE(parseReply("estop on")) << "keys are upper case";
    EXPECT_FALSE(parseReply("?!ESTOP ON"));
    EXPECT_FALSE(parseReply(std::string("ESTOP \x7f", 7)));
}

TEST(LinuxCncReply, MatchesEachReplyToItsRequestAndRefusesOneOutOfStep) {
    EXPECT_TRUE(replyTo("get estop", "ESTOP OFF"));
    EXPECT_TRUE(replyTo("set mdi #500=0.012300 #505=3", "SET MDI ACK"));
    EXPECT_TRUE(replyTo("set mdi G1 Q", "SET MDI NAK"));
    EXPECT_TRUE(replyTo("hello EMC TrueTurn 1.0", "HELLO ACK EMCNETSVR 1.1"));
    // The shell's own names for two gets.
    EXPECT_TRUE(replyTo("get program_linear_units", "PROGRAM_UNITS MM"));
    EXPECT_TRUE(replyTo("get timeout", "SET_TIMEOUT 5.000000"));
    EXPECT_TRUE(replyTo("get nonsense", "GET NONSENSE NAK"));
    // Out of step: the answer to an earlier request, or another command's acknowledgement.
    EXPECT_FALSE(replyTo("get machine", "ESTOP OFF"));
    EXPECT_FALSE(replyTo("set mdi G21", "SET MODE ACK"));
    EXPECT_FALSE(replyTo("set mdi G21", "MDI ACK"));
    EXPECT_FALSE(replyTo("get estop", "SET ESTOP ACK"));
    // Recorded when two connections sent at once (the shell's tokenizer is shared): refused, never taken as ACK.
    EXPECT_FALSE(replyTo("set mdi (DEBUG,Q3 #5400)", "SET (DEBUG,Q3 NAK"));
    EXPECT_FALSE(replyTo("frobnicate", "ESTOP ON"));
}

TEST(LinuxCncReply, ReadsTheMachinesState) {
    EXPECT_EQ(onOff(parseReply("ESTOP ON").value(), "ESTOP").value(), true);
    EXPECT_EQ(onOff(parseReply("MACHINE OFF").value(), "MACHINE").value(), false);
    EXPECT_FALSE(onOff(parseReply("MACHINE MAYBE").value(), "MACHINE"));
    EXPECT_FALSE(onOff(parseReply("ESTOP ON").value(), "MACHINE")) << "another key";
    EXPECT_EQ(taskMode(parseReply("MODE MDI").value()).value(), TaskMode::Mdi);
    EXPECT_EQ(taskMode(parseReply("MODE AUTO").value()).value(), TaskMode::Auto);
    EXPECT_FALSE(taskMode(parseReply("MODE TELEOP").value()));
    EXPECT_EQ(programStatus(parseReply("PROGRAM_STATUS RUNNING").value()).value(), ProgramStatus::Running);
    EXPECT_FALSE(programStatus(parseReply("PROGRAM_STATUS RUNNING NOW").value()));
    const auto homed = jointsHomed(parseReply("JOINT_HOMED YES YES NO NO NO NO").value());
    ASSERT_TRUE(homed);
    EXPECT_EQ(homed.value(), (std::vector<bool>{true, true, false, false, false, false}));
    EXPECT_TRUE(jointsHomed(parseReply("JOINT_HOMED HOMED NOT").value()));  // the manual's words
    EXPECT_FALSE(jointsHomed(parseReply("JOINT_HOMED YES PERHAPS").value()));
    EXPECT_EQ(linearUnits(parseReply("USER_LINEAR_UNITS INCH").value(), "USER_LINEAR_UNITS").value(),
              LinearUnits::Inch);
    EXPECT_EQ(millimetresPer(LinearUnits::Inch), 25.4);
    EXPECT_FALSE(linearUnits(parseReply("PROGRAM_UNITS NONE").value(), "PROGRAM_UNITS"));
    EXPECT_EQ(integerValue(parseReply("PROGRAM_LINE 42").value(), "PROGRAM_LINE").value(), 42);
    EXPECT_FALSE(integerValue(parseReply("PROGRAM_LINE 4.2").value(), "PROGRAM_LINE"));
}

TEST(LinuxCncReply, ReadsPositionsAndRefusesOnesCutOffOrGarbled) {
    const auto p = position(parseReply("ABS_ACT_POS 0.531496 0.000000 -0.293701 0.000000 0.000000 0.000000").value(),
                            "ABS_ACT_POS");
    ASSERT_TRUE(p) << p.error();
    EXPECT_DOUBLE_EQ(p.value()[0], 0.531496);
    EXPECT_DOUBLE_EQ(p.value()[2], -0.293701);
    const auto cut = position(parseReply("ABS_ACT_POS 0.531496 0.000000 -0.29").value(), "ABS_ACT_POS");
    ASSERT_FALSE(cut);
    EXPECT_NE(cut.error().find("cut off"), std::string::npos) << cut.error();
    EXPECT_FALSE(position(parseReply("ABS_ACT_POS 0.5314x6 0 0 0 0 0").value(), "ABS_ACT_POS"));
    EXPECT_FALSE(position(parseReply("ABS_ACT_POS nan 0 0 0 0 0").value(), "ABS_ACT_POS"));
    EXPECT_FALSE(position(parseReply("ABS_ACT_POS 1e5 0 0 0 0 0").value(), "ABS_ACT_POS"))
        << "LinuxCNC prints fixed decimals";
    EXPECT_FALSE(position(parseReply("REL_ACT_POS 0 0 0 0 0 0").value(), "ABS_ACT_POS"));
}

TEST(LinuxCncReply, ReadsTheNumbersOfATaggedOperatorMessage) {
    const auto v = taggedNumbers("TRUETURN7 0.012300 -0.004000", "TRUETURN7", 2);
    ASSERT_TRUE(v) << v.error();
    EXPECT_EQ(v.value(), (std::vector<double>{0.0123, -0.004}));
    EXPECT_FALSE(taggedNumbers("TRUETURN6 0.012300 -0.004000", "TRUETURN7", 2)) << "an older message";
    EXPECT_FALSE(taggedNumbers("TRUETURN7 0.012300", "TRUETURN7", 2));
    EXPECT_FALSE(taggedNumbers("TRUETURN7 0.012300 -0.0040O0", "TRUETURN7", 2));
}

}  // namespace
