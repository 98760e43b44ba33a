#include "core/sim/statistics/normal_stream.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace tt::core {

NormalStream::NormalStream(std::uint64_t seed) : m_engine(seed) {}

double NormalStream::uniformOpen() {
    // 53 random bits mapped into (0, 1): the midpoints of 2^53 equal cells, never 0 (log) or 1.
    return (static_cast<double>(m_engine() >> 11) + 0.5) * 0x1.0p-53;
}

double NormalStream::next() {
    const double u1 = uniformOpen();
    const double u2 = uniformOpen();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

std::string NormalStream::saveState() const {
    std::ostringstream out;
    out << m_engine;
    return out.str();
}

void NormalStream::restoreState(const std::string& state) {
    std::istringstream in(state);
    std::mt19937_64 engine;
    in >> engine;
    if (in.fail()) throw std::invalid_argument("saved random-number state is malformed");
    std::string rest;
    if (in >> rest) throw std::invalid_argument("saved random-number state has trailing data");
    m_engine = engine;
}

}  // namespace tt::core
