#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/loop/loop_clock.h"
#include "core/ports/shaft_machine.h"
#include "core/run/shaft_scenario.h"
#include "core/sim/shaft/lathe_shop.h"
#include "devices/linuxcnc/executed_path.h"
#include "devices/linuxcnc/linuxcnc_session.h"

namespace tt::devices::linuxcnc {

/// The LinuxCNC lathe's own choices besides the connection and the correction mode.
struct LinuxCncLatheOptions {
    SessionSettings session;
    /// A folder LinuxCNC reads: the machine writes its part program there (a local folder when LinuxCNC runs on
    /// this computer, or a share the LinuxCNC computer sees under the same path).
    std::string programFolder;
    double feedMmPerMin = 15000.0;  ///< the cut's feed (G94): a simulated LinuxCNC cuts a 325 mm part in 1.3 s
    int spindleRpm = 0;             ///< G97 S M3 when > 0
    bool pressCycleStart = true;    ///< false: the operator presses cycle start for every part
    double zOriginMm = 0.0;         ///< machine Z of the part's left end
    int zDirection = -1;            ///< machine Z = zOrigin + zDirection * z
    double clearanceMm = 2.0;
    double measureStartS = 0.2;  ///< the simulated gauge: from a part's end to its first reading, wall s
    double perPointS = 0.05;     ///< between readings, wall s
};

/// "LinuxCNC lathe": a real CNC controller machines every part. TrueTurn writes the corrections into LinuxCNC
/// between parts (profile: numbered parameters read by the parametric program TrueTurn writes for the run;
/// wear: the tool's X wear, the program applying it with G43.2), presses cycle start (when set to) and samples
/// the tool's position while the cut runs. The built-in physics of the scenario's lathe (deflection of the shaft
/// between its centres, the barrel, warm-up, wear, part-to-part variation: core/sim/shaft, the same seeded
/// LatheShop as the built-in simulated lathe) is applied to the path LinuxCNC actually executed, not to the
/// commanded one; the simulated micrometer measures the part. Its time is the wall clock (no jumpTo): poll it.
/// Used from one thread (the loop's); LinuxCNC is talked to in the session's own thread. A part is held, never
/// cut, while LinuxCNC is unreachable, in E-stop, off or not homed, or its write is refused or differs; it is cut
/// once all is well again (see LinuxCncSession), and what went wrong is in takeIncidents().
class LinuxCncLathe final : public core::ShaftMachine {
public:
    /// Starts the session (connects). Throws std::invalid_argument when the scenario has no physical lathe
    /// ("lathe" section of the preset) or the options are bad.
    LinuxCncLathe(const core::ShaftScenario& scenario, std::uint64_t seed, LinuxCncLatheOptions options);
    ~LinuxCncLathe() override;

    core::MachineCycle& cycle() override { return m_cycle; }
    core::CorrectionOutput& output() override { return m_output; }
    core::DiameterGauge& gauge() override { return m_shop->station().gauge(); }
    const core::Clock& clock() const override { return m_clock; }
    std::size_t setManualEntry(bool manual) override;
    std::optional<core::TrueProfile> trueProfile(std::int64_t partNumber) const override;
    void partMeasured(std::int64_t partNumber) override { m_shop->station().forgetPart(partNumber); }
    void restorePart(const core::PartCorrection& applied) override { m_shop->station().restoreMachinedPart(applied); }

    /// Problems worth an alarm since the last call, each naming LinuxCNC's host and what failed: the runtime
    /// records them as alarms of the run (kind "machine").
    std::vector<std::string> takeIncidents() override;
    /// Every write tried since the last call (applied or not): the runtime stores them with the run.
    std::vector<WriteRecord> takeWrites() { return m_session.takeWrites(); }
    /// What the session knows (health, machine state, counters).
    SessionSnapshot snapshot() const { return m_session.snapshot(); }
    /// The session, for an operator's commands (and tests).
    LinuxCncSession& session() { return m_session; }
    /// The correction path LinuxCNC executed for a part it cut (radial mm along the part, on the loop's path grid);
    /// the most recent parts only.
    std::optional<core::CorrectionPath> executedPath(std::int64_t partNumber) const;
    /// Parts cut again because their path was not seen over the whole part (each also an incident).
    std::uint64_t partsCutAgain() const { return m_partsCutAgain; }
    /// The pace of the next cut, % of the programmed feed: lowered while the sampling cannot keep up
    /// (nextFeedOverridePct).
    int feedOverridePct() const { return m_feedOverridePct; }
    /// The program file the machine runs.
    const std::string& programPath() const { return m_programPath; }

private:
    class Output final : public core::CorrectionOutput {
    public:
        explicit Output(LinuxCncLathe& lathe) : m_lathe(lathe) {}
        core::DeviceHealth health() const override;
        core::OutputResult sendPartCorrection(const core::PartCorrection& correction) override;
        core::OutputResult sendDynamicOffset(double xOffsetMm) override;

    private:
        LinuxCncLathe& m_lathe;
    };
    class Cycle final : public core::MachineCycle {
    public:
        explicit Cycle(LinuxCncLathe& lathe) : m_lathe(lathe) {}
        core::DeviceHealth health() const override;
        core::OutputResult startPart(std::int64_t partNumber) override;
        std::optional<core::FinishedPart> takeFinishedPart() override;

    private:
        LinuxCncLathe& m_lathe;
    };

    void writeProgram(const core::PartCorrection& correction);
    void pump();
    void finish(const PartResult& result);
    /// Where the part sits in the program and the band that is the cut, for drawing the executed path.
    CutGeometry cutGeometry() const;
    PartJob partJob(const core::PartCorrection& correction) const;

    LinuxCncLatheOptions m_options;
    core::ShaftScenario m_scenario;
    core::ScaledClock m_clock{1.0};
    std::unique_ptr<core::LatheShop> m_shop;
    LinuxCncSession m_session;
    Output m_output{*this};
    Cycle m_cycle{*this};
    std::string m_programPath;
    std::vector<double> m_programFeedForward;  ///< the feed-forward the program was written with
    std::optional<core::PartCorrection> m_pending;
    std::optional<std::vector<double>> m_lastAccepted;
    std::map<std::int64_t, core::PartCorrection> m_cutting;  ///< parts given to LinuxCNC, not yet cut
    std::deque<core::FinishedPart> m_finished;
    std::deque<std::pair<std::int64_t, core::CorrectionPath>> m_executed;
    std::vector<std::string> m_incidents;  ///< the machine's own (a cut not sampled over the whole part)
    std::uint64_t m_partsCutAgain = 0;
    int m_feedOverridePct = 100;
};

}  // namespace tt::devices::linuxcnc
