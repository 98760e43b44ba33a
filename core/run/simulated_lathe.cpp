#include "core/run/simulated_lathe.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tt::core {

namespace {
/// Finished parts the station keeps for their true profiles (the page shows the newest).
constexpr std::size_t kKeptParts = 4;
}  // namespace

SimulatedLathe::SimulatedLathe(const LatheShopSpec& spec, Time time, double speed) {
    if (time == Time::Paced)
        m_paced = std::make_unique<ScaledClock>(speed);
    else
        m_jumping = std::make_unique<ManualClock>();
    m_shop = std::make_unique<LatheShop>(spec, clock());
    m_shop->station().setKeptParts(kKeptParts);
}

const Clock& SimulatedLathe::clock() const {
    if (m_paced) return *m_paced;
    return *m_jumping;
}

bool SimulatedLathe::jumpTo(double timeS) {
    if (!m_jumping) return false;
    m_jumping->advanceTo(timeS);
    return true;
}

void SimulatedLathe::setSpeed(double speed) {
    if (m_paced && std::isfinite(speed) && speed >= 0.0) m_paced->setSpeed(speed);
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
