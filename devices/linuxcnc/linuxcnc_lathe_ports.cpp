// The LinuxCNC lathe's ports (CNC output, part cycle) and what happens when LinuxCNC has cut a part: the path it
// executed, turned into a part by the scenario's physics and put on the simulated measuring station.
#include <algorithm>
#include <cmath>

#include "core/control/profile_interpolation.h"
#include "devices/linuxcnc/linuxcnc_lathe.h"

namespace tt::devices::linuxcnc {

namespace {

constexpr std::size_t kKeptPaths = 8;
/// The executed path must reach this close to both ends of the part, and never skip more, mm.
constexpr double kCoverageMm = 5.0;

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
    core::PartCorrection executedCorrection{result.partNumber, commanded.pointZMm, commanded.pointCorrectionMm,
                                            executed(result, commanded.path)};
    if (executedCorrection.path.zMm.empty()) {
        // The samples do not cover the part (the sampling stopped for long, or a program that was not ours ran).
        m_incidents.push_back("LinuxCNC at " + m_options.session.controller.endpoint.text() + ": part " +
                              std::to_string(result.partNumber) +
                              ": its path was not seen over the whole part; it is not counted and is cut again");
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

core::CorrectionPath LinuxCncLathe::executed(const PartResult& result, const core::CorrectionPath& grid) const {
    const double length = m_scenario.partLengthMm;
    const double nominalR = 0.5 * m_scenario.nominalDiameterMm;
    double band = m_options.session.corrections.largestTotalMm + 0.5 * m_options.clearanceMm;
    for (const double x : grid.xCorrectionMm)
        band = std::max(band, std::fabs(x) + 0.5 * m_options.clearanceMm);
    // In time order: the feed onto the part (at the path's first X, from the clearance before z = 0) and the cut to
    // the part's end; what comes after it (the retract) is not the cut.
    const double feedStart = -m_options.clearanceMm + 1e-3;
    std::vector<std::pair<double, double>> cut;
    for (const auto& [x, zProgram] : result.samplesMm) {
        const double z = (zProgram - m_options.zOriginMm) / m_options.zDirection;
        if (z < feedStart || std::fabs(x - nominalR) > band) continue;
        // The program dwells at the end of the cut: the first sample there is the cut's end, the rest the retract.
        cut.emplace_back(std::min(z, length), x - nominalR);
        if (z >= length - 1e-6) break;
    }
    std::sort(cut.begin(), cut.end());
    cut.erase(std::unique(cut.begin(), cut.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
              cut.end());
    if (cut.size() < 2 || cut.front().first > 0.0 || cut.back().first < length - 1e-6) return {};
    for (std::size_t i = 1; i < cut.size(); ++i)
        if (cut[i].first - cut[i - 1].first > 2.0 * kCoverageMm) return {};
    // Between the samples the path is drawn by PCHIP: where the sampling paused (a busy computer) the cubic follows
    // the smooth path better than a chord; where the samples are dense (0.25 mm at 15 m/min) both are the same.
    std::vector<double> zs, xs;
    for (const auto& [z, x] : cut) {
        zs.push_back(z);
        xs.push_back(x);
    }
    const core::PiecewiseCubic executed = core::PiecewiseCubic::pchip(zs, xs);
    core::CorrectionPath path;
    path.zMm = grid.zMm;
    for (const double z : grid.zMm)
        path.xCorrectionMm.push_back(executed.value(z));
    return path;
}

}  // namespace tt::devices::linuxcnc
