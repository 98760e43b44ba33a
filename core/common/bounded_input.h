#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace tt::core {

/// The size limits of one input file, checked before any of it is parsed (issue 17: an endless
/// file such as /dev/zero or a 200 MB line of commas must be refused, not read into memory).
/// A line of at most maxLineLength characters also bounds the columns of a table to that number.
struct InputLimits {
    std::size_t maxBytes = 16u * 1024u * 1024u;  ///< the whole file, bytes
    std::size_t maxLines = 1000000;              ///< lines (rows, header and comments included); 0: no check
    std::size_t maxLineLength = 4096;            ///< characters of one line, '\n' excluded; 0: no check
};

/// The limits of a table (CSV): all three checks.
inline constexpr InputLimits kTableLimits{};

/// The limits of a document (JSON, whose writers may put it on one line): bytes only.
inline constexpr InputLimits kDocumentLimits{16u * 1024u * 1024u, 0, 0};

/// Reads the file `path` (a regular file, a pipe or a device) but never more than
/// `limits.maxBytes` + 1 bytes, then checks the text with checkTextLimits. Throws
/// std::invalid_argument "cannot read: <reason>" or the broken limit ("is larger than the limit of
/// 16777216 bytes").
std::string readBoundedFile(const std::string& path, const InputLimits& limits);

/// Checks `text` against the line count and line length of `limits`; throws std::invalid_argument
/// naming the line and the limit ("line 2 is longer than 4096 characters").
void checkTextLimits(std::string_view text, const InputLimits& limits);

}  // namespace tt::core
