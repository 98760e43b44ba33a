#include "devices/simulator/simulated_lathe_offer.h"

#include <QCoreApplication>

#include "core/run/simulated_lathe.h"

namespace tt::devices {

namespace {

// The simulated lathe's own states, in the operator's language (the engine keeps them in English).
[[maybe_unused]] const char* const kStationTexts[] = {
    QT_TRANSLATE_NOOP("Simulator", "simulated CNC ready"),
    QT_TRANSLATE_NOOP("Simulator", "machining"),
    QT_TRANSLATE_NOOP("Simulator", "waiting for the next part"),
    QT_TRANSLATE_NOOP("Simulator", "the simulated gauge does not answer"),
    QT_TRANSLATE_NOOP("Simulator", "automatic measuring is off: diameters are entered by hand"),
    QT_TRANSLATE_NOOP("Simulator", "simulated micrometer ready"),
};

core::DeviceHealth translated(core::DeviceHealth health) {
    health.message = QCoreApplication::translate("Simulator", health.message.c_str()).toStdString();
    return health;
}

class TranslatedGauge final : public core::DiameterGauge {
public:
    explicit TranslatedGauge(core::DiameterGauge& gauge) : m_gauge(gauge) {}
    core::DeviceHealth health() const override { return translated(m_gauge.health()); }
    void requestReading() override { m_gauge.requestReading(); }
    std::optional<core::GaugeReading> takeReading() override { return m_gauge.takeReading(); }

private:
    core::DiameterGauge& m_gauge;
};

class TranslatedOutput final : public core::CorrectionOutput {
public:
    explicit TranslatedOutput(core::CorrectionOutput& output) : m_output(output) {}
    core::DeviceHealth health() const override { return translated(m_output.health()); }
    core::OutputResult sendPartCorrection(const core::PartCorrection& c) override {
        return m_output.sendPartCorrection(c);
    }
    core::OutputResult sendDynamicOffset(double xOffsetMm) override { return m_output.sendDynamicOffset(xOffsetMm); }

private:
    core::CorrectionOutput& m_output;
};

class TranslatedCycle final : public core::MachineCycle {
public:
    explicit TranslatedCycle(core::MachineCycle& cycle) : m_cycle(cycle) {}
    core::DeviceHealth health() const override { return translated(m_cycle.health()); }
    core::OutputResult startPart(std::int64_t partNumber) override { return m_cycle.startPart(partNumber); }
    std::optional<core::FinishedPart> takeFinishedPart() override { return m_cycle.takeFinishedPart(); }

private:
    core::MachineCycle& m_cycle;
};

/// The simulated lathe as the terminal shows it: the same machine in simulated time (the run's stepper paces
/// it by the wall clock, so it machines the same parts as a headless run of the same request), its states
/// worded in the operator's language like every device's.
class TerminalLathe final : public core::ShaftMachine {
public:
    TerminalLathe(const core::ShaftScenario& scenario, std::uint64_t seed) : m_lathe(scenario.shopSpec(seed)) {}

    core::MachineCycle& cycle() override { return m_cycle; }
    core::CorrectionOutput& output() override { return m_output; }
    core::DiameterGauge& gauge() override { return m_gauge; }
    const core::Clock& clock() const override { return m_lathe.clock(); }
    double nextEventTimeS() const override { return m_lathe.nextEventTimeS(); }
    bool jumpTo(double timeS) override { return m_lathe.jumpTo(timeS); }
    std::size_t setManualEntry(bool manual) override { return m_lathe.setManualEntry(manual); }
    std::optional<core::TrueProfile> trueProfile(std::int64_t partNumber) const override {
        return m_lathe.trueProfile(partNumber);
    }
    void partMeasured(std::int64_t partNumber) override { m_lathe.partMeasured(partNumber); }
    bool silenceGauge(double seconds) override { return m_lathe.silenceGauge(seconds); }
    void restorePart(const core::PartCorrection& applied) override { m_lathe.restorePart(applied); }
    void replayPart(const core::PartCorrection& applied, double finishedS) override {
        m_lathe.replayPart(applied, finishedS);
    }

private:
    core::SimulatedLathe m_lathe;
    TranslatedGauge m_gauge{m_lathe.gauge()};
    TranslatedOutput m_output{m_lathe.output()};
    TranslatedCycle m_cycle{m_lathe.cycle()};
};

}  // namespace

ShaftMachineOffer simulatedLatheOffer() {
    ShaftMachineOffer offer;
    offer.key = QStringLiteral("simulated-lathe");
    offer.name = QCoreApplication::translate("Simulator", "Simulated lathe (built in)");
    offer.description = QCoreApplication::translate(
        "Simulator",
        "Parts of the set-up are turned on the simulated lathe, measured at the control points and the next part "
        "is corrected.");
    offer.adjustableSpeed = true;
    offer.make = [](const core::ShaftScenario& scenario, std::uint64_t seed) {
        return std::make_unique<TerminalLathe>(scenario, seed);
    };
    return offer;
}

}  // namespace tt::devices
