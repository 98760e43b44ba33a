#include "core/sim/shaft/lathe_part_process.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace tt::core {

double TurnedPart::diameterAtMm(double z) const {
    if (zMm.empty() || zMm.size() != diameterMm.size()) throw std::logic_error("the machined part has no profile");
    if (z <= zMm.front()) return diameterMm.front();
    if (z >= zMm.back()) return diameterMm.back();
    const auto upper = std::upper_bound(zMm.begin(), zMm.end(), z);
    const auto i = static_cast<std::size_t>(std::distance(zMm.begin(), upper));
    const double t = (z - zMm[i - 1]) / (zMm[i] - zMm[i - 1]);
    return diameterMm[i - 1] + t * (diameterMm[i] - diameterMm[i - 1]);
}

}  // namespace tt::core
