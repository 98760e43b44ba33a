#pragma once

#include <QByteArray>
#include <QString>
#include <optional>

namespace tt::devices {

/// The bytes of a request string typed with escapes: \r \n \t \\ and \xNN (two hex digits).
/// nullopt for a malformed escape. Used for the polled gauge's request ("\r", "1\r").
std::optional<QByteArray> unescapeRequest(const QString& text);

}  // namespace tt::devices
