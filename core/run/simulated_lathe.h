#pragma once

#include <memory>

#include "core/loop/loop_clock.h"
#include "core/ports/shaft_machine.h"
#include "core/sim/shaft/lathe_shop.h"

namespace tt::core {

/// The built-in simulated lathe as a ShaftMachine: the simulated shop of a scenario (physical lathe or
/// statistical plant, CNC, part cycle, measuring station) on a clock of its own that moves only by jumpTo
/// (core/loop/shaft_run_stepper.h moves it from event to event, as fast as possible or paced by the wall
/// clock).
class SimulatedLathe final : public ShaftMachine {
public:
    /// Throws std::invalid_argument on a bad spec.
    explicit SimulatedLathe(const LatheShopSpec& spec);

    MachineCycle& cycle() override { return m_shop->station().machine(); }
    CorrectionOutput& output() override { return m_shop->station().output(); }
    DiameterGauge& gauge() override { return m_shop->station().gauge(); }
    const Clock& clock() const override { return *m_clock; }

    double nextEventTimeS() const override { return m_shop->station().nextEventTimeS(); }
    bool jumpTo(double timeS) override;
    std::size_t setManualEntry(bool manual) override;
    std::optional<TrueProfile> trueProfile(std::int64_t partNumber) const override;
    void partMeasured(std::int64_t partNumber) override { m_shop->station().forgetPart(partNumber); }
    bool silenceGauge(double seconds) override;
    void restorePart(const PartCorrection& applied) override { m_shop->station().restoreMachinedPart(applied); }
    void replayPart(const PartCorrection& applied, double finishedS) override { replay(applied, finishedS); }

    /// replayPart, returning the part as it came off the simulated machine again.
    TurnedPart replay(const PartCorrection& applied, double finishedS);

    /// The simulated shop itself (its process machines parts for a resumed run's record).
    LatheShop& shop() { return *m_shop; }

private:
    std::unique_ptr<ManualClock> m_clock;
    std::unique_ptr<LatheShop> m_shop;
};

}  // namespace tt::core
