// libFuzzer target: the input limits every file passes before it is parsed (core/common/bounded_input.h),
// on arbitrary text with small limits taken from the first three bytes. Text that is accepted must
// really be within the limits (checked independently here).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "core/common/bounded_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 3) return 0;
    tt::core::InputLimits limits;
    limits.maxLines = data[0] % 16;
    limits.maxLineLength = data[1] % 64;
    limits.maxBytes = data[2];
    const std::string_view text(reinterpret_cast<const char*>(data + 3), size - 3);
    try {
        tt::core::checkTextLimits(text, limits);
    } catch (const std::invalid_argument&) {
        return 0;
    }
    std::size_t lines = 0;
    std::size_t length = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (length == 0) ++lines;
        if (text[i] == '\n') {
            length = 0;
            continue;
        }
        ++length;
        if (limits.maxLineLength > 0 && length > limits.maxLineLength) __builtin_trap();
    }
    if (limits.maxLines > 0 && lines > limits.maxLines) __builtin_trap();
    return 0;
}
