#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <stdexcept>

#include "app/cli/command.h"
#include "app/cli/command_files.h"
#include "app/cli/command_parser.h"
#include "config/deformation_csv.h"
#include "config/feed_schedule_config.h"
#include "config/preset_library.h"
#include "core/sim/shaft/deformation_experiment.h"

namespace tt::cli {

namespace {

config::FeedSchedulingSetup loadSetup(const QString& preset) {
    try {
        return config::feedSchedulingSetupFromPreset(config::PresetLibrary::load(preset));
    } catch (const std::invalid_argument& e) {
        throw UsageError(QStringLiteral("--preset %1: %2").arg(preset, QString::fromStdString(e.what())).toStdString());
    }
}

QJsonArray toArray(const std::vector<double>& v) {
    QJsonArray a;
    for (double x : v)
        a.append(x);
    return a;
}

int runDeformationExperiment(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("deformation-experiment"),
                         QStringLiteral("Runs the force-deformation experiments of paper 004 on the shaft-turning "
                                        "simulator: one bar per depth of cut and feed of the preset's grid, turned "
                                        "along its whole length and gauged with the micrometer; writes the measured "
                                        "deformation Y (um) as the CSV that fit-deformation reads."));
    parser.addOption(QStringLiteral("preset"),
                     QStringLiteral("The set-up: a preset with lathe, experiment and job sections (feed-scheduling) "
                                    "or such a preset file."),
                     QStringLiteral("NAME|FILE.json"));
    parser.addOption(QStringLiteral("csv"), QStringLiteral("The experiment to write: a_mm,f_mm_rev,z_mm,y_um."),
                     QStringLiteral("FILE.csv"));
    parser.addOption(QStringLiteral("seed"), QStringLiteral("Seed of the micrometer's noise (default: the preset's)."),
                     QStringLiteral("S"));
    parser.parse(arguments);
    const QString presetName = parser.required(QStringLiteral("preset"));
    const QString csvPath = parser.required(QStringLiteral("csv"));
    config::FeedSchedulingSetup setup = loadSetup(presetName);
    if (parser.isSet(QStringLiteral("seed")))
        setup.experiment.seed = static_cast<std::uint64_t>(parser.integer(QStringLiteral("seed"), 0, 4294967295LL));

    config::DeformationCsv csv;
    csv.samples = core::runDeformationExperiment(setup.lathe, setup.experiment);
    csv.preset = presetName;
    csv.seed = setup.experiment.seed;
    writeOutputFile(csvPath, config::deformationCsvText(csv));

    const core::DeformationSamples& s = csv.samples;
    const std::size_t bars = setup.experiment.depthsMm.size() * setup.experiment.feedsMmPerRev.size();
    if (parser.json()) {
        printJson(
            QJsonObject{{QStringLiteral("preset"), presetName},
                        {QStringLiteral("seed"), static_cast<double>(setup.experiment.seed)},
                        {QStringLiteral("csv"), csvPath},
                        {QStringLiteral("rows"), static_cast<double>(s.size())},
                        {QStringLiteral("bars"), static_cast<double>(bars)},
                        {QStringLiteral("depths_mm"), toArray(setup.experiment.depthsMm)},
                        {QStringLiteral("feeds_mm_per_rev"), toArray(setup.experiment.feedsMmPerRev)},
                        {QStringLiteral("z_mm"), toArray(setup.experiment.zMm)},
                        {QStringLiteral("y_um"), QJsonObject{{QStringLiteral("min"), s.deformationUm.minCoeff()},
                                                             {QStringLiteral("max"), s.deformationUm.maxCoeff()}}}});
        return kExitOk;
    }
    printLine(QStringLiteral("Force-deformation experiment on preset %1 (seed %2): %3 bars (%4 depths x %5 feeds), "
                             "each gauged at %6 positions")
                  .arg(presetName)
                  .arg(setup.experiment.seed)
                  .arg(bars)
                  .arg(setup.experiment.depthsMm.size())
                  .arg(setup.experiment.feedsMmPerRev.size())
                  .arg(setup.experiment.zMm.size()));
    printLine(QStringLiteral("%1 measurements, Y from %2 to %3 um, written to %4")
                  .arg(s.size())
                  .arg(s.deformationUm.minCoeff(), 0, 'f', 1)
                  .arg(s.deformationUm.maxCoeff(), 0, 'f', 1)
                  .arg(csvPath));
    printLine(QStringLiteral("Next: trueturn fit-deformation %1 --stepwise --json > model.json").arg(csvPath));
    return kExitOk;
}

}  // namespace

Command makeDeformationExperimentCommand() {
    return {QStringLiteral("deformation-experiment"),
            QStringLiteral("force-deformation experiments on the simulator (paper 004), as CSV"),
            runDeformationExperiment};
}

}  // namespace tt::cli
