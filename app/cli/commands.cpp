#include "app/cli/command.h"

namespace tt::cli {

// One factory per command, each in its own cmd_<name>.cpp.
Command makeFitProfileCommand();
Command makeLineariseCommand();
Command makeBoringCommand();
Command makeLqgCommand();
Command makeSimulateCommand();
Command makeBenchCommand();
Command makeFeedStabiliseCommand();
Command makeDeformationExperimentCommand();
Command makeFitDeformationCommand();
Command makeScheduleFeedCommand();
Command makeCornerCommand();
Command makeReportCommand();
Command makeGenerateHistoryCommand();
Command makeIdentifyCommand();
Command makeAuditCommand();
Command makeCncProgramCommand();
Command makePlantCommand();
Command makeForwardCommand();
Command makeTuneCommand();

const std::vector<Command>& commands() {
    static const std::vector<Command> all = {
        makeFitProfileCommand(),
        makeLineariseCommand(),
        makeBoringCommand(),
        makeLqgCommand(),
        makeSimulateCommand(),
        makeBenchCommand(),
        makeDeformationExperimentCommand(),
        makeFitDeformationCommand(),
        makeScheduleFeedCommand(),
        makeCornerCommand(),
        makeFeedStabiliseCommand(),
        makeReportCommand(),
        makeGenerateHistoryCommand(),
        makeIdentifyCommand(),
        makeAuditCommand(),
        makeCncProgramCommand(),
        makePlantCommand(),
        makeForwardCommand(),
        makeTuneCommand(),
    };
    return all;
}

}  // namespace tt::cli
