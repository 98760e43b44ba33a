#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace tt::devices {

/// The bytes of a request string typed with escapes: \r \n \t \\ and \xNN (two hex digits).
/// nullopt for a malformed escape. Used for the polled gauge's request ("\r", "1\r").
std::optional<std::string> unescapeRequest(std::string_view text);

}  // namespace tt::devices
