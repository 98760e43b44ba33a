// libFuzzer target: LinuxCNC's remote shell replies (devices/parsers/linuxcnc_reply.h) on arbitrary bytes: the
// framer over the stream in two chunks, each line as the reply to the requests TrueTurn sends, and the typed
// readers. Must never crash, hang, leak or hit undefined behaviour; what it accepts must be well-formed.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "devices/parsers/linuxcnc_reply.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tt::devices::linuxcnc;
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const std::size_t cut = size == 0 ? 0 : data[0] % (size + 1);
    ReplyFramer framer(64);
    std::vector<std::string> lines = framer.feed(bytes.substr(0, cut));
    for (std::string& line : framer.feed(bytes.substr(cut)))
        lines.push_back(std::move(line));
    if (framer.corrupt() && framer.problem().empty()) __builtin_trap();
    static const char* const requests[] = {"get estop",
                                           "get machine",
                                           "get mode",
                                           "get program_status",
                                           "get joint_homed",
                                           "get abs_act_pos",
                                           "get user_linear_units",
                                           "get error",
                                           "get operator_display",
                                           "set mdi G21",
                                           "hello EMC TrueTurn 1.0",
                                           "get program_linear_units"};
    for (const std::string& line : lines) {
        if (line.empty() || line.size() > 64) __builtin_trap();  // the framer never returns these
        for (const char* request : requests) {
            const auto reply = replyTo(request, line);
            if (!reply) continue;
            (void)onOff(reply.value(), "ESTOP");
            (void)taskMode(reply.value());
            (void)programStatus(reply.value());
            (void)jointsHomed(reply.value());
            (void)linearUnits(reply.value(), "USER_LINEAR_UNITS");
            (void)message(reply.value(), "ERROR");
            if (const auto p = position(reply.value(), "ABS_ACT_POS"))
                for (const double v : p.value())
                    if (!std::isfinite(v)) __builtin_trap();  // only finite positions pass
        }
        if (const auto numbers = taggedNumbers(line, "TRUETURN1", 2))
            for (const double v : numbers.value())
                if (!std::isfinite(v)) __builtin_trap();
    }
    // The whole input as one line.
    if (const auto reply = parseReply(bytes); reply && reply.value().key.empty()) __builtin_trap();
    return 0;
}
