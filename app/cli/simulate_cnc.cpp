#include "app/cli/simulate_cnc.h"

#include <QJsonArray>
#include <stdexcept>

#include "app/cli/command.h"
#include "app/cli/command_parser.h"
#include "core/loop/loop_engine.h"
#include "devices/linuxcnc/linuxcnc_controller.h"
#include "devices/linuxcnc/linuxcnc_lathe.h"
#include "devices/linuxcnc/linuxcnc_lathe_offer.h"
#include "devices/linuxcnc/linuxcnc_settings.h"

namespace tt::cli {

namespace {

QString modeOf(const runtime::RunRequest& request) {
    return request.cncMode.isEmpty() ? QStringLiteral("profile") : request.cncMode;
}

QVariantMap settingsOf(const runtime::RunRequest& request) {
    return devices::linuxcnc::settingsFromUrl(request.cnc, modeOf(request));
}

/// The part program's folder: the request's, or a temporary folder of this computer kept in `report`.
QString programFolder(const runtime::RunRequest& request, CncRunReport& report) {
    if (!request.cncProgramFolder.isEmpty()) return request.cncProgramFolder;
    report.folder = std::make_unique<QTemporaryDir>();
    if (!report.folder->isValid())
        throw std::runtime_error("no temporary folder for the LinuxCNC part program: " +
                                 report.folder->errorString().toStdString());
    return report.folder->path();
}

/// Takes the machine's writes and incidents into the report (incidents also as alarms of a stored run).
void takeReports(devices::linuxcnc::LinuxCncLathe& lathe, const core::LoopEngine& engine, CncRunReport& report,
                 core::HistoryStore* history) {
    for (const devices::linuxcnc::WriteRecord& w : lathe.takeWrites()) {
        const bool written = !w.readBackMm.empty() || w.outcome == devices::linuxcnc::WriteOutcome::Differs;
        report.written += written ? 1 : 0;
        report.readBack += w.applied() && w.readBackMm == w.writtenMm ? 1 : 0;
        report.refused += written ? 0 : 1;
    }
    for (const std::string& incident : lathe.takeIncidents()) {
        report.incidents.push_back(incident);
        if (history && engine.runId())
            history->recordAlarm(*engine.runId(),
                                 {engine.partAwaitingMeasurement(), lathe.clock().nowS(), "machine", incident});
    }
}

}  // namespace

void addCncOptions(CommandParser& parser) {
    parser.addOption(QStringLiteral("cnc"),
                     QStringLiteral("Cut the closed run's parts on this LinuxCNC (linuxcnc://HOST[:PORT], port 5007 "
                                    "when absent; out of E-stop, on and homed): TrueTurn writes the corrections "
                                    "into it between parts and presses cycle start; the built-in physics turns the "
                                    "path it executed into the part. Needs a preset with a lathe section; runs in "
                                    "wall time; the open-loop reference runs on the built-in simulated lathe."),
                     QStringLiteral("url"));
    parser.addOption(QStringLiteral("cnc-mode"),
                     QStringLiteral("With --cnc: profile (numbered parameters read by the part program TrueTurn "
                                    "writes; the default) or wear (the tool's X wear)."),
                     QStringLiteral("profile|wear"));
    parser.addOption(QStringLiteral("cnc-program-folder"),
                     QStringLiteral("With --cnc: the folder the part program is written to, which LinuxCNC reads "
                                    "under the same path (default: a temporary folder of this computer)."),
                     QStringLiteral("dir"));
}

void readCncOptions(const CommandParser& parser, runtime::RunRequest& request) {
    const bool cnc = parser.isSet(QStringLiteral("cnc"));
    for (const char* option : {"cnc-mode", "cnc-program-folder"})
        if (!cnc && parser.isSet(QString::fromLatin1(option)))
            throw UsageError(std::string("--") + option + ": only with --cnc linuxcnc://HOST:PORT");
    if (!cnc) return;
    request.cnc = parser.value(QStringLiteral("cnc"));
    if (parser.isSet(QStringLiteral("cnc-mode")))
        request.cncMode =
            parser.choice(QStringLiteral("cnc-mode"), {QStringLiteral("profile"), QStringLiteral("wear")});
    request.cncProgramFolder = parser.value(QStringLiteral("cnc-program-folder"));
    if (const auto problem = runtime::cncUrlProblem(request.cnc)) throw UsageError("--cnc: " + *problem);
    const QVariantMap settings = settingsOf(request);
    request.machine = QStringLiteral("linuxcnc-lathe:%1:%2")
                          .arg(settings.value(QStringLiteral("host")).toString())
                          .arg(settings.value(QStringLiteral("port")).toInt());
}

void checkCncReachable(const runtime::RunRequest& request) {
    const QVariantMap settings = settingsOf(request);
    const std::string where = devices::linuxcnc::endpointText(settings).toStdString();
    devices::linuxcnc::LinuxCncController controller(devices::linuxcnc::sessionSettings(settings).controller);
    devices::linuxcnc::MachineStatus status;
    try {
        controller.connect();
        status = controller.status();
        controller.disconnect();
    } catch (const std::exception& e) {
        const std::string why = e.what();
        throw std::runtime_error((why.rfind(where, 0) == 0 ? why : where + ": " + why) +
                                 "; is LinuxCNC running there with its remote shell (linuxcncrsh)?");
    }
    if (status.estop) throw std::runtime_error(where + " is in E-stop; release it, switch the machine on and home it");
    if (!status.machineOn) throw std::runtime_error(where + " is off; switch the machine on and home it");
    if (!status.allHomed()) throw std::runtime_error(where + " is not homed; home every joint first");
}

core::ShaftMachineFactory cncMachineFactory(const runtime::RunRequest& request, CncRunReport& report,
                                            core::HistoryStore* history) {
    const devices::ShaftMachineOffer offer =
        devices::linuxcnc::linuxCncLatheOffer(settingsOf(request), programFolder(request, report), true);
    auto lathe = std::make_shared<devices::linuxcnc::LinuxCncLathe*>(nullptr);
    core::ShaftMachineFactory factory;
    factory.make = [make = offer.make, lathe](const core::ShaftScenario& scenario, std::uint64_t seed) {
        std::unique_ptr<core::ShaftMachine> machine = make(scenario, seed);
        *lathe = dynamic_cast<devices::linuxcnc::LinuxCncLathe*>(machine.get());
        return machine;
    };
    factory.poll = [lathe, &report, history](core::ShaftMachine&, const core::LoopEngine& engine) {
        if (*lathe) takeReports(**lathe, engine, report, history);
    };
    return factory;
}

void printCncText(const QString& url, const CncRunReport& report) {
    printLine(QStringLiteral("Through LinuxCNC at %1: %2 correction(s) written, %3 read back equal, %4 not written")
                  .arg(url)
                  .arg(report.written)
                  .arg(report.readBack)
                  .arg(report.refused));
    for (const std::string& incident : report.incidents)
        printLine(QStringLiteral("  incident: %1").arg(QString::fromStdString(incident)));
}

void addCncJson(QJsonObject& out, const CncRunReport& report) {
    out.insert(QStringLiteral("cnc"), QStringLiteral("linuxcnc"));
    QJsonArray incidents;
    for (const std::string& incident : report.incidents)
        incidents.append(QString::fromStdString(incident));
    out.insert(QStringLiteral("cnc_corrections"),
               QJsonObject{{QStringLiteral("written"), static_cast<qint64>(report.written)},
                           {QStringLiteral("read_back"), static_cast<qint64>(report.readBack)},
                           {QStringLiteral("not_written"), static_cast<qint64>(report.refused)},
                           {QStringLiteral("incidents"), incidents}});
}

}  // namespace tt::cli
