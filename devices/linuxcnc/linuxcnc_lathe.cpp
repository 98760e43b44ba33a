#include "devices/linuxcnc/linuxcnc_lathe.h"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "core/control/profile_interpolation.h"
#include "devices/linuxcnc/linuxcnc_program.h"

namespace tt::devices::linuxcnc {

namespace {

constexpr std::size_t kKeptParts = 8;

/// `program` written to `path` at once for a reader (a temporary file renamed over it).
void writeFileAtomically(const std::string& path, const std::string& program) {
    const std::string temporary = path + ".part";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << program;
        out.flush();
        if (!out) throw std::runtime_error("cannot write the part program " + temporary);
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
        throw std::runtime_error("cannot write the part program " + path);
}

}  // namespace

LinuxCncLathe::LinuxCncLathe(const core::ShaftScenario& scenario, std::uint64_t seed, LinuxCncLatheOptions options)
    : m_options(std::move(options)), m_scenario(scenario), m_session(m_options.session) {
    if (!scenario.lathe)
        throw std::invalid_argument(
            "the LinuxCNC lathe needs a scenario with a physical lathe (a preset with a "
            "\"lathe\" section, such as paper-2012-group1)");
    if (m_options.programFolder.empty() || !std::filesystem::is_directory(m_options.programFolder))
        throw std::invalid_argument("the LinuxCNC lathe's program folder '" + m_options.programFolder +
                                    "' is not a folder");
    if (!(m_options.feedMmPerMin > 0.0 && m_options.feedMmPerMin <= 100000.0))
        throw std::invalid_argument("the LinuxCNC lathe's feed must be in (0, 100000] mm/min");
    if (m_options.zDirection != 1 && m_options.zDirection != -1)
        throw std::invalid_argument("the LinuxCNC lathe's Z direction must be +1 or -1");
    core::LatheShopSpec spec = scenario.shopSpec(seed);
    spec.timing.measureStartS = m_options.measureStartS;
    spec.timing.perPointS = m_options.perPointS;
    m_shop = std::make_unique<core::LatheShop>(spec, m_clock);
    m_shop->station().setKeptParts(kKeptParts);
    m_programPath =
        (std::filesystem::path(m_options.programFolder) /
         ("trueturn-" + correctionModeName(m_options.session.corrections.mode) + "-" + std::to_string(::getpid()) +
          "-" + std::to_string(reinterpret_cast<std::uintptr_t>(this)) + ".ngc"))
            .string();
    m_session.start();
}

LinuxCncLathe::~LinuxCncLathe() {
    m_session.stop();
    std::error_code ignored;
    std::filesystem::remove(m_programPath, ignored);
}

std::size_t LinuxCncLathe::setManualEntry(bool manual) {
    m_shop->station().setAutomaticGauge(!manual);
    return 0;
}

std::optional<core::TrueProfile> LinuxCncLathe::trueProfile(std::int64_t partNumber) const {
    const auto& parts = m_shop->station().machinedParts();
    const auto part = std::find_if(parts.rbegin(), parts.rend(),
                                   [partNumber](const core::TurnedPart& p) { return p.partNumber == partNumber; });
    if (part == parts.rend()) return std::nullopt;
    core::TrueProfile profile{partNumber, part->zMm, {}};
    for (const double d : part->diameterMm)
        profile.errorMm.push_back(d - m_scenario.nominalDiameterMm);
    return profile;
}

std::optional<core::CorrectionPath> LinuxCncLathe::executedPath(std::int64_t partNumber) const {
    for (const auto& [part, path] : m_executed)
        if (part == partNumber) return path;
    return std::nullopt;
}

void LinuxCncLathe::writeProgram(const core::PartCorrection& correction) {
    // The feed-forward of the loop's path: the path less the interpolated point corrections (the program computes
    // the interpolation itself from the parameters, so both cut the same path).
    const core::PiecewiseCubic points =
        core::PiecewiseCubic::make(m_scenario.interpolation, correction.pointZMm, correction.pointCorrectionMm);
    std::vector<double> feedForward;
    for (std::size_t i = 0; i < correction.path.zMm.size(); ++i)
        feedForward.push_back(correction.path.xCorrectionMm[i] - points.value(correction.path.zMm[i]));
    if (std::filesystem::exists(m_programPath) && feedForward.size() == m_programFeedForward.size() &&
        std::equal(feedForward.begin(), feedForward.end(), m_programFeedForward.begin(),
                   [](double a, double b) { return std::fabs(a - b) < 1e-9; }))
        return;
    const CorrectionSettings& c = m_options.session.corrections;
    ProgramOptions o;
    o.firstParameter = c.mode == CorrectionMode::Profile ? c.firstParameter : 0;
    o.conventions = c.conventions;
    o.feed = m_options.feedMmPerMin;
    o.feedPerMinute = true;
    o.spindleRpm = m_options.spindleRpm;
    o.toolNumber = c.toolNumber;
    o.wearTool = c.wearTool;
    o.zOriginMm = m_options.zOriginMm;
    o.zDirection = m_options.zDirection;
    o.clearanceMm = m_options.clearanceMm;
    o.largestTotalMm = c.largestTotalMm;
    o.notes = {"LinuxCNC lathe of TrueTurn, " + correctionModeName(c.mode) + " mode"};
    ParametricProgramJob job = programJob(m_scenario.loopConfig(false, std::nullopt), o);
    job.pathZMm = correction.path.zMm;
    const bool any = std::any_of(feedForward.begin(), feedForward.end(), [](double v) { return std::fabs(v) > 1e-12; });
    job.feedForwardMm = any ? feedForward : std::vector<double>{};
    writeFileAtomically(m_programPath, writeParametricProgram(job));
    m_programFeedForward = feedForward;
}

PartJob LinuxCncLathe::partJob(const core::PartCorrection& correction) const {
    const CorrectionSettings& c = m_options.session.corrections;
    const double safeR = 0.5 * m_scenario.nominalDiameterMm + c.largestTotalMm + m_options.clearanceMm;
    const double startZ = correction.path.zMm.empty() ? 0.0 : correction.path.zMm.front();
    const double approachZ = m_options.zOriginMm + m_options.zDirection * (startZ - m_options.clearanceMm);
    char move[96];
    std::snprintf(move, sizeof move, "G0 X%.6f Z%.6f", safeR, approachZ);
    char tool[48];
    std::snprintf(tool, sizeof tool, "T%d M6 G43", c.toolNumber);
    PartJob job;
    job.correction = correction;
    job.programPath = m_programPath;
    job.pressCycleStart = m_options.pressCycleStart;
    job.feedOverridePct = m_feedOverridePct;
    job.referenceLines = {"G18 G21 G8 G90 G94 G40", tool, move};
    job.referenceProgramMm = {safeR, approachZ};
    job.endProgramMm = std::array<double, 2>{safeR, approachZ};
    job.endXToleranceMm = c.mode == CorrectionMode::Wear ? c.largestTotalMm + 0.001 : 0.001;
    return job;
}

}  // namespace tt::devices::linuxcnc
