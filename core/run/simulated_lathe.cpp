#include "core/run/simulated_lathe.h"

#include <algorithm>
#include <stdexcept>

namespace tt::core {

namespace {
/// Finished parts the station keeps for their true profiles (the page shows the newest).
constexpr std::size_t kKeptParts = 4;
}  // namespace

SimulatedLathe::SimulatedLathe(const LatheShopSpec& spec)
    : m_clock(std::make_unique<ManualClock>()), m_shop(std::make_unique<LatheShop>(spec, *m_clock)) {
    m_shop->station().setKeptParts(kKeptParts);
}

TurnedPart SimulatedLathe::replay(const PartCorrection& applied, double finishedS) {
    TurnedPart part = m_shop->process().machine(applied);
    if (finishedS > m_clock->nowS()) m_clock->advanceTo(finishedS);
    return part;
}

bool SimulatedLathe::jumpTo(double timeS) {
    m_clock->advanceTo(timeS);
    return true;
}

std::size_t SimulatedLathe::setManualEntry(bool manual) {
    m_shop->station().setAutomaticGauge(!manual);
    return 0;
}

std::optional<TrueProfile> SimulatedLathe::trueProfile(std::int64_t partNumber) const {
    const auto& parts = m_shop->station().machinedParts();
    const auto part = std::find_if(parts.rbegin(), parts.rend(),
                                   [partNumber](const TurnedPart& p) { return p.partNumber == partNumber; });
    if (part == parts.rend()) return std::nullopt;
    TrueProfile profile{partNumber, part->zMm, {}};
    const double nominal = m_shop->process().nominalDiameterMm();
    for (double d : part->diameterMm)
        profile.errorMm.push_back(d - nominal);
    return profile;
}

bool SimulatedLathe::silenceGauge(double seconds) {
    const double now = clock().nowS();
    m_shop->station().silenceGauge(now, now + seconds);
    return true;
}

}  // namespace tt::core
