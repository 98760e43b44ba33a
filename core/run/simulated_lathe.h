#pragma once

#include <memory>

#include "core/loop/loop_clock.h"
#include "core/ports/shaft_machine.h"
#include "core/sim/shaft/lathe_shop.h"

namespace tt::core {

/// The built-in simulated lathe as a ShaftMachine: the simulated shop of a scenario (physical lathe or
/// statistical plant, CNC, part cycle, measuring station) on a clock of its own.
class SimulatedLathe final : public ShaftMachine {
public:
    /// How the lathe's time passes.
    enum class Time {
        Jumping,  ///< moves only by jumpTo (headless runs, as fast as the computer goes)
        Paced     ///< runs at a settable multiple of the wall clock (the operator watches it)
    };

    /// Throws std::invalid_argument on a bad spec or speed (Paced: `speed` >= 0, finite).
    explicit SimulatedLathe(const LatheShopSpec& spec, Time time = Time::Jumping, double speed = 1.0);

    MachineCycle& cycle() override { return m_shop->station().machine(); }
    CorrectionOutput& output() override { return m_shop->station().output(); }
    DiameterGauge& gauge() override { return m_shop->station().gauge(); }
    const Clock& clock() const override;

    double nextEventTimeS() const override { return m_shop->station().nextEventTimeS(); }
    bool jumpTo(double timeS) override;
    bool speedAdjustable() const override { return m_paced != nullptr; }
    void setSpeed(double speed) override;
    std::size_t setManualEntry(bool manual) override;
    std::optional<TrueProfile> trueProfile(std::int64_t partNumber) const override;
    void partMeasured(std::int64_t partNumber) override { m_shop->station().forgetPart(partNumber); }
    bool silenceGauge(double seconds) override;
    void restorePart(const PartCorrection& applied) override { m_shop->station().restoreMachinedPart(applied); }

    /// The simulated shop itself (its process machines parts for a resumed run's record).
    LatheShop& shop() { return *m_shop; }

private:
    std::unique_ptr<ManualClock> m_jumping;
    std::unique_ptr<ScaledClock> m_paced;
    std::unique_ptr<LatheShop> m_shop;
};

}  // namespace tt::core
