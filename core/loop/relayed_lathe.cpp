#include "core/loop/relayed_lathe.h"

namespace tt::core {

RelayedLathe::RelayedLathe(std::optional<double> outputNominalDiameterMm)
    : m_outputNominalMm(outputNominalDiameterMm) {}

std::size_t RelayedLathe::setManualEntry(bool manual) {
    // Readings the gauge sent while the diameters were typed by hand belong to no point.
    const std::size_t dropped = m_manual && !manual ? m_gauge.discardPending() : 0;
    m_manual = manual;
    return dropped;
}

}  // namespace tt::core
