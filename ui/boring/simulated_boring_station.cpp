#include "ui/boring/simulated_boring_station.h"

namespace tt::ui {

namespace {

core::BoringScenario withCycle(core::BoringScenario scenario, double plcCycleS) {
    scenario.plcCycleS = plcCycleS;
    core::validateScenario(scenario);
    return scenario;
}

}  // namespace

SimulatedBoringStation::SimulatedBoringStation(core::BoringScenario scenario, const BoringRunSettings& settings)
    : m_scenario(withCycle(std::move(scenario), settings.plcCycleS)),
      m_source(settings.source),
      m_machine(std::make_unique<core::BoringMachine>(m_scenario, settings.source == BoringSource::Current)),
      m_twin(std::make_unique<core::BoringMachine>(m_scenario, false)) {
    if (m_source == BoringSource::Probe) m_calibration = core::calibrateMandrel(*m_machine, m_scenario);
    BoringRunSettings run = settings;
    run.plane = 0;  // the station's mandrel has plane 0 along X (its table is calibrated there)
    m_loop =
        std::make_unique<CompensationLoop>(run, &m_machine->driveReadout(), &m_machine->probe(), m_machine->output());
}

bool SimulatedBoringStation::finished() const {
    return m_machine->finished();
}

BoringCycleView SimulatedBoringStation::cycle() {
    m_machine->advanceCycle();
    if (!m_twin->finished()) m_twin->advanceCycle();
    BoringCycleView view;
    const core::BoringState& s = m_machine->state();
    view.cycle = m_loop->cycle(s.timeS);
    StationTruth truth;
    truth.zMm = s.toolZMm;
    truth.cutting = s.cutting;
    truth.deflectionMm = s.tipDeflectionXmm;
    truth.forceN = s.radialForceN;
    truth.diameterErrorMm = 2.0 * s.radiusErrorMm;
    truth.uncompensatedErrorMm = 2.0 * m_twin->state().radiusErrorMm;
    view.truth = truth;
    return view;
}

core::OutputResult SimulatedBoringStation::zeroOffset() {
    return m_machine->output().sendDynamicOffset(0.0);
}

void SimulatedBoringStation::setSourceSilent(bool silent) {
    m_silent = silent;
    const core::DeviceHealth health =
        silent ? core::DeviceHealth{core::DeviceState::Error,
                                    m_source == BoringSource::Current
                                        ? "no answer from the simulated drive read-out (fault switch)"
                                        : "no data from the simulated probe mandrel (fault switch)"}
               : core::DeviceHealth{core::DeviceState::Ready, {}};
    if (m_source == BoringSource::Current)
        m_machine->setDriveHealth(health);
    else
        m_machine->setProbeHealth(health);
}

}  // namespace tt::ui
