#pragma once

// `trueturn simulate --cnc linuxcnc://HOST:PORT`: the closed run goes on the LinuxCNC lathe (LinuxCNC cuts every part,
// the built-in physics turns the executed path into the part, the simulated micrometer measures it) instead of the
// built-in simulated lathe. The engine only gets a machine factory (core::ShaftMachineFactory); what the machine
// reports (its writes, its incidents) is collected here.
#include <QJsonObject>
#include <QTemporaryDir>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/ports/history_store.h"
#include "core/run/shaft_run.h"
#include "runtime/run/run_request.h"

namespace tt::cli {

class CommandParser;

/// --cnc, --cnc-mode and --cnc-program-folder.
void addCncOptions(CommandParser& parser);
/// Puts the CNC options into `request` (its machine becomes the LinuxCNC lathe's key). Throws UsageError for
/// --cnc-mode or --cnc-program-folder without --cnc.
void readCncOptions(const CommandParser& parser, runtime::RunRequest& request);

/// What a run through LinuxCNC reported.
struct CncRunReport {
    std::int64_t written = 0;               ///< corrections written into LinuxCNC (read back equal or not)
    std::int64_t readBack = 0;              ///< of them, read back equal (applied)
    std::int64_t refused = 0;               ///< not written: refused, beyond the limits or the machine not ready
    std::vector<std::string> incidents;     ///< the machine's incidents (each also an alarm of a stored run)
    std::unique_ptr<QTemporaryDir> folder;  ///< the part program's folder when the request names none
};

/// Connects to the LinuxCNC of `request.cnc` once and checks it is out of E-stop, on and homed, so that a run does
/// not wait for a machine that cannot cut. Throws std::runtime_error naming LinuxCNC and what is wrong.
void checkCncReachable(const runtime::RunRequest& request);

/// The machine factory of a request with a CNC: the LinuxCNC lathe (linuxCncLatheOffer of the URL and mode),
/// TrueTurn pressing cycle start; its writes and incidents go into `report`, the incidents also as alarms
/// ("machine") of the stored run in `history` (may be null).
core::ShaftMachineFactory cncMachineFactory(const runtime::RunRequest& request, CncRunReport& report,
                                            core::HistoryStore* history);

/// Two lines for the text output: the CNC and its corrections written and read back, and its incidents.
void printCncText(const QString& url, const CncRunReport& report);

/// "cnc": "linuxcnc" and "cnc_corrections": {written, read_back, refused, incidents} of the report.
void addCncJson(QJsonObject& out, const CncRunReport& report);

}  // namespace tt::cli
