#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/ports/clock.h"
#include "core/ports/correction_output.h"
#include "core/ports/diameter_gauge.h"
#include "core/ports/machine_cycle.h"
#include "core/ports/simulation_timeline.h"
#include "core/sim/shaft/lathe_micrometer.h"
#include "core/sim/shaft/lathe_part_process.h"

namespace tt::core {

/// Times of the simulated shop floor, simulated seconds.
struct LatheStationTiming {
    double partTimeS = 360.0;     ///< one part on the lathe (paper 000: 6 min)
    double measureStartS = 20.0;  ///< from the end of a part to its first reading
    double perPointS = 5.0;       ///< between readings at successive points
};

/// The built-in simulator as the closed loop sees it, behind the same ports as a real shop: the CNC
/// (CorrectionOutput), the part cycle (MachineCycle) and the measuring station with its micrometer
/// (DiameterGauge, one reading per control point, in point order, oldest finished part first). Faults
/// can be switched on for tests and demonstrations: a silent gauge (from a time, for a while), a
/// refused CNC write, a wrong reading. Passive: everything follows from the shared Clock.
class LatheStation final : public SimulationTimeline {
public:
    /// `measurePointZMm`: where the operator measures each part (the control points).
    LatheStation(LathePartProcess& process, const LatheMicrometer& micrometer, std::uint64_t seed, const Clock& clock,
                 std::vector<double> measurePointZMm, LatheStationTiming timing = {});
    /// With a gauge model of its own (per-point noise of the statistical plant).
    LatheStation(LathePartProcess& process, LatheMicrometerModel gauge, const Clock& clock,
                 std::vector<double> measurePointZMm, LatheStationTiming timing = {});
    LatheStation(const LatheStation&) = delete;
    LatheStation& operator=(const LatheStation&) = delete;

    /// The CNC's correction output port.
    CorrectionOutput& output() { return m_output; }
    /// The part-cycle port (start a part, learn it finished).
    MachineCycle& machine() { return m_cycle; }
    /// The gauge port (readings of the measured parts).
    DiameterGauge& gauge() { return m_gauge; }

    double nextEventTimeS() const override;

    /// The gauge answers nothing during [fromS, untilS) (simulated seconds); readings due meanwhile
    /// come when it is back, in order.
    void silenceGauge(double fromS, double untilS);
    /// Automatic measuring on (the simulated operator measures every part) or off (manual entry).
    void setAutomaticGauge(bool on) { m_automatic = on; }
    /// Whether the simulated operator measures every part.
    bool automaticGauge() const { return m_automatic; }
    /// The reading of part `partNumber` at point `pointIndex` will be `valueMm` (a typing error, a dirty anvil).
    void injectReading(std::int64_t partNumber, int pointIndex, double valueMm);
    /// Part `partNumber` was measured elsewhere (by hand): the station does not measure it again.
    void forgetPart(std::int64_t partNumber);
    /// The CNC refuses corrections with `message` (empty: accepts again).
    void setOutputFault(const std::string& message) { m_outputFault = message; }
    /// A part machined before an interruption (with the corrections it really got) is back on the rack,
    /// waiting to be measured: it is re-created from the deterministic process.
    void restoreMachinedPart(const PartCorrection& applied);
    /// A part machined elsewhere (on a real CNC, its true profile from the path the CNC executed) arrives at the
    /// station now: it is kept with the machined parts and measured like the station's own.
    void acceptMachinedPart(TurnedPart part);

    /// The most recent corrections the CNC received, oldest first (at most `keep`, see setKeptParts).
    const std::deque<PartCorrection>& sentCorrections() const { return m_sent; }
    /// How many corrections the CNC has received in all.
    std::int64_t sentCount() const { return m_sentCount; }
    /// The parts machined so far with their true profiles (most recent last; at most `keep` kept).
    const std::deque<TurnedPart>& machinedParts() const { return m_machined; }
    /// How many machined parts and corrections are kept (default 64).
    void setKeptParts(std::size_t keep) { m_keep = keep; }
    /// Where the gauge measures, mm along the part.
    const std::vector<double>& measurePointZMm() const { return m_points; }
    /// The process that machines the parts.
    LathePartProcess& process() { return m_process; }

private:
    class Output final : public CorrectionOutput {
    public:
        explicit Output(LatheStation& s) : m_s(s) {}
        DeviceHealth health() const override;
        OutputResult sendPartCorrection(const PartCorrection& correction) override;
        OutputResult sendDynamicOffset(double xOffsetMm) override;

    private:
        LatheStation& m_s;
    };
    class Cycle final : public MachineCycle {
    public:
        explicit Cycle(LatheStation& s) : m_s(s) {}
        DeviceHealth health() const override;
        OutputResult startPart(std::int64_t partNumber) override;
        std::optional<FinishedPart> takeFinishedPart() override;

    private:
        LatheStation& m_s;
    };
    class Gauge final : public DiameterGauge {
    public:
        explicit Gauge(LatheStation& s) : m_s(s) {}
        DeviceHealth health() const override;
        void requestReading() override {}
        std::optional<GaugeReading> takeReading() override;

    private:
        LatheStation& m_s;
    };

    struct Machining {
        PartCorrection correction;
        double finishS = 0.0;
    };
    struct ToMeasure {
        TurnedPart part;
        double readyS = 0.0;  ///< when the part reached the measuring station
        int nextPoint = 0;
    };

    bool gaugeSilentAt(double timeS) const;
    double afterSilence(double timeS) const;
    std::optional<double> nextReadingTimeS() const;
    void finishMachining();

    LathePartProcess& m_process;
    LatheMicrometerModel m_micrometer;
    const Clock& m_clock;
    std::vector<double> m_points;
    LatheStationTiming m_timing;
    Output m_output{*this};
    Cycle m_cycle{*this};
    Gauge m_gauge{*this};

    std::optional<PartCorrection> m_active;
    std::optional<Machining> m_machining;
    std::deque<FinishedPart> m_finished;
    std::deque<ToMeasure> m_queue;
    double m_lastReadingS = -1e300;
    std::vector<std::pair<double, double>> m_silences;
    std::map<std::pair<std::int64_t, int>, double> m_injected;
    bool m_automatic = true;
    std::string m_outputFault;
    std::deque<PartCorrection> m_sent;
    std::int64_t m_sentCount = 0;
    std::deque<TurnedPart> m_machined;
    std::size_t m_keep = 64;
};

}  // namespace tt::core
