#include "devices/parsers/line_framer.h"

#include <stdexcept>

namespace tt::devices {

LineFramer::LineFramer(std::size_t maxLength) : m_maxLength(maxLength) {
    if (maxLength == 0) throw std::invalid_argument("line framer: the maximum line length must be positive");
}

std::vector<std::string> LineFramer::feed(std::span<const std::uint8_t> bytes) {
    std::vector<std::string> lines;
    for (const std::uint8_t byte : bytes) {
        if (byte == '\n') continue;
        if (byte == '\r') {
            if (!m_discarding && !m_buffer.empty()) lines.push_back(m_buffer);
            m_buffer.clear();
            m_discarding = false;
            continue;
        }
        if (m_discarding) continue;
        if (m_buffer.size() == m_maxLength) {
            m_buffer.clear();
            m_discarding = true;
            ++m_overlong;
            continue;
        }
        m_buffer.push_back(static_cast<char>(byte));
    }
    return lines;
}

void LineFramer::reset() {
    m_buffer.clear();
    m_discarding = false;
}

}  // namespace tt::devices
