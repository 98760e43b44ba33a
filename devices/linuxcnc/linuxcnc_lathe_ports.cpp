// The LinuxCNC lathe's ports (CNC output, part cycle) and what happens when LinuxCNC has cut a part: the path it
// executed, turned into a part by the scenario's physics and put on the simulated measuring station.
#include <algorithm>

#include "devices/linuxcnc/linuxcnc_lathe.h"

namespace tt::devices::linuxcnc {

namespace {

constexpr std::size_t kKeptPaths = 8;

core::DeviceHealth machineHealth(const SessionSnapshot& s) {
    if (s.health.state != core::DeviceState::Ready) return s.health;
    return {core::DeviceState::Ready, s.health.message};
}

}  // namespace

core::DeviceHealth LinuxCncLathe::Output::health() const {
    return machineHealth(m_lathe.m_session.snapshot());
}

core::OutputResult LinuxCncLathe::Output::sendPartCorrection(const core::PartCorrection& correction) {
    LinuxCncLathe& l = m_lathe;
    const CorrectionSettings& c = l.m_options.session.corrections;
    if (correction.pointCorrectionMm.size() != l.m_scenario.control.plant.points.size() ||
        correction.path.zMm.size() < 2 || correction.path.zMm.size() != correction.path.xCorrectionMm.size())
        return {false, "the corrections do not fit the run's control points and path"};
    const std::vector<double> values = valuesToWrite(correction, c.mode);
    if (const std::string problem = limitProblem(values, l.m_lastAccepted, c); !problem.empty())
        return {false, "LinuxCNC at " + l.m_options.session.controller.endpoint.text() + ": part " +
                           std::to_string(correction.partNumber) + ": " + problem + "; nothing written"};
    l.m_pending = correction;
    l.m_lastAccepted = values;
    return {true, {}};
}

core::OutputResult LinuxCncLathe::Output::sendDynamicOffset(double) {
    return {false, "the LinuxCNC lathe takes corrections between parts, not a dynamic X offset"};
}

core::DeviceHealth LinuxCncLathe::Cycle::health() const {
    return machineHealth(m_lathe.m_session.snapshot());
}

core::OutputResult LinuxCncLathe::Cycle::startPart(std::int64_t partNumber) {
    LinuxCncLathe& l = m_lathe;
    l.pump();
    if (!l.m_cutting.empty())
        return {false, "LinuxCNC is still cutting part " + std::to_string(l.m_cutting.begin()->first)};
    if (!l.m_pending) return {false, "no corrections were sent for part " + std::to_string(partNumber)};
    core::PartCorrection correction = *l.m_pending;
    correction.partNumber = partNumber;
    try {
        l.writeProgram(correction);
    } catch (const std::exception& e) {
        return {false, e.what()};
    }
    l.m_cutting[partNumber] = correction;
    l.m_session.submit(l.partJob(correction));
    return {true, {}};
}

std::optional<core::FinishedPart> LinuxCncLathe::Cycle::takeFinishedPart() {
    LinuxCncLathe& l = m_lathe;
    l.pump();
    if (l.m_finished.empty()) return std::nullopt;
    const core::FinishedPart part = l.m_finished.front();
    l.m_finished.pop_front();
    return part;
}

std::vector<std::string> LinuxCncLathe::takeIncidents() {
    std::vector<std::string> incidents = m_session.takeIncidents();
    incidents.insert(incidents.end(), m_incidents.begin(), m_incidents.end());
    m_incidents.clear();
    return incidents;
}

void LinuxCncLathe::pump() {
    for (const PartResult& result : m_session.takeResults())
        finish(result);
}

void LinuxCncLathe::finish(const PartResult& result) {
    const auto cutting = m_cutting.find(result.partNumber);
    if (cutting == m_cutting.end()) return;
    const core::PartCorrection& commanded = cutting->second;
    DrawnPath drawn = drawExecutedPath(result.samplesMm, commanded.path, cutGeometry());
    m_feedOverridePct = nextFeedOverridePct(m_feedOverridePct, drawn);
    core::PartCorrection executedCorrection{result.partNumber, commanded.pointZMm, commanded.pointCorrectionMm,
                                            std::move(drawn.path)};
    if (executedCorrection.path.zMm.empty()) {
        // The samples do not cover the part (the sampling stopped for long where the path bends, or a program that
        // was not ours ran).
        m_incidents.push_back("LinuxCNC at " + m_options.session.controller.endpoint.text() + ": part " +
                              std::to_string(result.partNumber) + ": its path was not seen over the whole part: " +
                              drawn.unseen + "; it is not counted and is cut again");
        ++m_partsCutAgain;
        m_session.submit(partJob(commanded));
        return;
    }
    core::TurnedPart part = m_shop->process().machine(executedCorrection);
    m_shop->station().acceptMachinedPart(std::move(part));
    m_executed.emplace_back(result.partNumber, executedCorrection.path);
    while (m_executed.size() > kKeptPaths)
        m_executed.pop_front();
    m_finished.push_back({result.partNumber, m_clock.nowS()});
    m_cutting.erase(cutting);
}

CutGeometry LinuxCncLathe::cutGeometry() const {
    return {m_scenario.partLengthMm, m_scenario.nominalDiameterMm, m_options.zOriginMm,
            m_options.zDirection,    m_options.clearanceMm,        m_options.session.corrections.largestTotalMm};
}

}  // namespace tt::devices::linuxcnc
