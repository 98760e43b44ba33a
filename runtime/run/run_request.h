#pragma once

#include <QJsonObject>
#include <QString>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "config/loop_scenario.h"
#include "core/control/run_to_run_setup.h"
#include "core/run/shaft_run_builder.h"

namespace tt::runtime {

/// The key of the built-in simulator's lathe (devices/simulator), the default machine of a run.
inline const QString kBuiltInLatheKey = QStringLiteral("simulated-lathe");

/// A field of a run request that is missing, mistyped or out of range: `field` is its JSON path
/// ("plant_mismatch.gain_factor"), what() says what is wrong in the user's terms.
class RunRequestError : public std::invalid_argument {
public:
    RunRequestError(std::string field, const std::string& message)
        : std::invalid_argument(field + ": " + message), field(std::move(field)) {}
    std::string field;
};

/// A step in the simulated plant asked for by the request (core::PlantStep with a 1-based point).
struct RequestedStep {
    std::int64_t atPart = 1;
    double sizeMm = 0.0;
    std::optional<int> point;  ///< 1-based control point; none: the whole part
};

/// How the simulated plant is to differ from the model (the built-in lathe only); absent values keep the
/// preset's.
struct RequestedPlant {
    std::optional<double> gainFactor;
    std::optional<int> delayParts;
    std::optional<RequestedStep> step;
    bool any() const { return gainFactor || delayParts || step; }
};

/// Everything one shaft run is, as one value: the machine and its devices, the set-up, the controller and
/// its tuning, the delay, the seed, the pace, how the simulated plant differs, the history and the end.
/// The Run page, `trueturn simulate` (options or --request FILE.json), `simulate --db --resume` and the
/// interrupted-run offer all build and read it; it is validated in one place (validate) and written to and
/// read from JSON in one place (toJson, runRequestFromJson), and stored once with the run.
/// Absent optional values take the preset's.
struct RunRequest {
    // ---- the machine ----
    QString machine = kBuiltInLatheKey;  ///< the machine offer's key (runtime/run/machine_catalog.h)
    QString lathe;                       ///< the lathe's name in the history (a plant holds several); may be empty
    QString cncOutput;                   ///< machines assembled from devices: the CNC output's device id
    QString gauge;                       ///< and the gauge's; empty: diameters typed in by hand
    /// The CNC that cuts the parts: "linuxcnc://HOST[:PORT]" (the LinuxCNC lathe, docs/protocols/cnc.md); empty:
    /// none. Needs a preset with a lathe section; the run goes at the machine's own pace (speed 0).
    QString cnc;
    QString cncMode;           ///< how the corrections reach LinuxCNC's cut: "profile" or "wear"; empty: profile
    QString cncProgramFolder;  ///< where the part program is written (LinuxCNC reads it there); empty: a temporary one
    // ---- the set-up and its control ----
    QString preset = QStringLiteral("paper-2012");  ///< preset name or JSON file
    std::optional<int> delay;                       ///< transport delay z, parts (1..8)
    core::ControllerKind controller = core::ControllerKind::Lqg;
    std::optional<double> ewmaWeight;   ///< EWMA lambda in (0, 1]
    bool ewmaAuto = false;              ///< the best EWMA lambda on a grid
    std::optional<double> driftWeight;  ///< double EWMA's lambda2 in (0, 1)
    std::optional<bool> integral;       ///< the LQG's integral action
    std::optional<double> integralWeight;
    std::optional<std::string> mismatchAction;  ///< the mismatch monitor's action (core::mismatchActionFromName)
    /// The dither on the correction while the adaptive loop identifies the plant, as a share of the tolerance zone
    /// (0 .. core::kMaxDitherShare); none: the preset's.
    std::optional<double> ditherShare;
    RequestedPlant plant;
    /// The controller tuning applied on the Controller page (config::controllerTuningToJson); none: the preset's.
    std::optional<QJsonObject> tuning;
    bool pauseOnScrap = false;  ///< pause on a scrap part (besides the preset's loop.pause_on_scrap)
    // ---- the run ----
    std::uint64_t seed = 1;               ///< every random source of a simulated machine (0 .. 2^53)
    double speed = 0.0;                   ///< machine s per wall s: 0 as fast as possible, else 1 .. 1e9
    std::optional<std::int64_t> endPart;  ///< the run ends after this part; none: until stopped
    std::int64_t warmupParts = 0;         ///< the first parts, machined and stored but not in the statistics
    bool manualEntry = false;             ///< diameters typed in by hand instead of the gauge
    QString database;                     ///< the history: SQLite file or postgresql://...; empty: none
};

/// Whether `url` is linuxcnc://HOST[:PORT] with a port 1..65535; else the reason in the user's terms.
std::optional<std::string> cncUrlProblem(const QString& url);

/// Largest seed a request takes (JSON numbers are exact to 2^53).
inline constexpr std::uint64_t kMaxRequestSeed = 1ULL << 53;

/// Checks every field against its range and the others (a step's point within the preset's points, the
/// plant's delay not below the model's, an EWMA weight only with an EWMA controller, ...); throws
/// RunRequestError naming the field. Loads the preset to check what depends on it.
void validate(const RunRequest& request);

/// The request as JSON (the format `simulate --dump-request` prints and `--request` reads; absent values are
/// left out).
QJsonObject toJson(const RunRequest& request);
/// Reads toJson's output; unknown keys and wrong types are refused (RunRequestError naming the field).
RunRequest runRequestFromJson(const QJsonObject& json);
/// Reads a request file (bounded, as every input file); throws RunRequestError("request", ...) when it cannot
/// be read or is not a JSON object.
RunRequest readRunRequestFile(const QString& path);

/// The scenario the request runs: its preset (with based_on) and delay, the applied tuning, the plant's
/// difference, integral action, drift weight, mismatch action and pause on scrap. Throws RunRequestError.
config::LoopScenario scenarioOf(const RunRequest& request);
/// The run's choices for planShaftRun (controller, EWMA weight, end).
core::ShaftRunChoice choiceOf(const RunRequest& request);

}  // namespace tt::runtime
