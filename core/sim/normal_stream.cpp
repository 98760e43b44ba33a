#include "core/sim/normal_stream.h"

#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace tt::core {

NormalStream::NormalStream(std::uint64_t seed) : m_engine(seed) {}

double NormalStream::uniformSigned() {
    // 53 random bits -> [0, 1) -> [-1, 1).
    return static_cast<double>(m_engine() >> 11) * 0x1.0p-52 - 1.0;
}

double NormalStream::next() {
    if (m_hasSpare) {
        m_hasSpare = false;
        return m_spare;
    }
    double u = 0.0;
    double v = 0.0;
    double s = 0.0;
    do {
        u = uniformSigned();
        v = uniformSigned();
        s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double factor = std::sqrt(-2.0 * std::log(s) / s);
    m_spare = v * factor;
    m_hasSpare = true;
    return u * factor;
}

std::string NormalStream::saveState() const {
    std::ostringstream out;
    std::uint64_t spareBits = 0;
    std::memcpy(&spareBits, &m_spare, sizeof spareBits);
    out << m_engine << ' ' << (m_hasSpare ? 1 : 0) << ' ' << spareBits;
    return out.str();
}

void NormalStream::restoreState(const std::string& state) {
    std::istringstream in(state);
    std::mt19937_64 engine;
    int hasSpare = 0;
    std::uint64_t spareBits = 0;
    in >> engine >> hasSpare >> spareBits;
    if (in.fail() || (hasSpare != 0 && hasSpare != 1))
        throw std::invalid_argument("saved random-number state is malformed");
    std::string rest;
    if (in >> rest) throw std::invalid_argument("saved random-number state has trailing data");
    double spare = 0.0;
    std::memcpy(&spare, &spareBits, sizeof spare);
    m_engine = engine;
    m_hasSpare = hasSpare == 1;
    m_spare = spare;
}

}  // namespace tt::core
