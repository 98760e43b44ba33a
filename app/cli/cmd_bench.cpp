#include <QJsonObject>
#include <QString>

#include "app/cli/command.h"
#include "app/cli/command_parser.h"
#include "config/plant_config.h"
#include "core/run/run_to_run_timing.h"

namespace tt::cli {

namespace {

int run(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("bench"),
                         QStringLiteral("Times the hot paths on this machine: LQG synthesis, controller update and "
                                        "statistical plant for the paper plant (preset paper-2012) at z = 4."));
    parser.addOption(QStringLiteral("seconds"), QStringLiteral("Time spent on each path, 0.05..10 s (default 0.25)."),
                     QStringLiteral("s"), QStringLiteral("0.25"));
    parser.parse(arguments);
    const double budget = parser.number(QStringLiteral("seconds"), 0.05, 10.0);
    const core::RunToRunSetup setup = config::loadRunToRunSetup(QStringLiteral("paper-2012"), 4);
    const core::RunToRunTimings t = core::measureRunToRunHotPaths(setup, budget);
    if (parser.json()) {
        printJson(QJsonObject{{QStringLiteral("lqg_synthesis_us"), t.lqgSynthesisUs},
                              {QStringLiteral("controller_update_us"), t.controllerUpdateUs},
                              {QStringLiteral("sim_part_steps_per_s"), t.simPartStepsPerS},
                              {QStringLiteral("monte_carlo_parts_per_s"), t.monteCarloPartsPerS},
                              {QStringLiteral("points"), t.points},
                              {QStringLiteral("delay"), t.delay},
                              {QStringLiteral("states"), t.states}});
        return kExitOk;
    }
    printLine(QStringLiteral("Paper plant (paper-2012): %1 points, z = %2, %3 states; one core")
                  .arg(t.points)
                  .arg(t.delay)
                  .arg(t.states));
    printLine(QStringLiteral("  LQG synthesis               %1 µs").arg(t.lqgSynthesisUs, 10, 'f', 1));
    printLine(QStringLiteral("  controller update per part  %1 µs").arg(t.controllerUpdateUs, 10, 'f', 3));
    printLine(QStringLiteral("  statistical plant           %1 parts/s").arg(t.simPartStepsPerS, 10, 'g', 4));
    printLine(QStringLiteral("  closed-loop Monte-Carlo     %1 parts/s").arg(t.monteCarloPartsPerS, 10, 'g', 4));
    return kExitOk;
}

}  // namespace

Command makeBenchCommand() {
    return {QStringLiteral("bench"),
            QStringLiteral("Time the hot paths (LQG synthesis, controller update, simulation)"), run};
}

}  // namespace tt::cli
