#include "devices/gauge_serial/request_string.h"

namespace tt::devices {

std::optional<QByteArray> unescapeRequest(const QString& text) {
    const QByteArray in = text.toLatin1();
    QByteArray out;
    for (qsizetype i = 0; i < in.size(); ++i) {
        const char c = in[i];
        if (c != '\\') {
            out.append(c);
            continue;
        }
        if (++i >= in.size()) return std::nullopt;
        switch (in[i]) {
            case 'r':
                out.append('\r');
                break;
            case 'n':
                out.append('\n');
                break;
            case 't':
                out.append('\t');
                break;
            case '\\':
                out.append('\\');
                break;
            case 'x': {
                const QByteArray hex = in.mid(i + 1, 2);
                bool ok = false;
                const int v = hex.toInt(&ok, 16);
                if (hex.size() != 2 || !ok) return std::nullopt;
                out.append(static_cast<char>(v));
                i += 2;
                break;
            }
            default:
                return std::nullopt;
        }
    }
    return out;
}

}  // namespace tt::devices
