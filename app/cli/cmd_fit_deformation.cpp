#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <cmath>
#include <stdexcept>

#include "app/cli/command.h"
#include "app/cli/command_files.h"
#include "app/cli/command_parser.h"
#include "config/deformation_csv.h"
#include "config/deformation_model_config.h"
#include "config/feed_schedule_config.h"
#include "config/preset_library.h"

namespace tt::cli {

namespace {

const QStringList kTermSets = {QStringLiteral("cubic-z"), QStringLiteral("quadratic"), QStringLiteral("interactions"),
                               QStringLiteral("linear"), QStringLiteral("cubic-fz")};

QString number(double v, int precision = 4) {
    return std::isfinite(v) ? QString::number(v, 'g', precision) : QStringLiteral("infinite");
}

/// The machine job of the set-up the experiments were cut on, when the preset has one.
std::optional<devices::FeedPassJob> jobOf(const QString& preset, const QString& origin) {
    try {
        return config::feedPassJobFromPreset(config::PresetLibrary::load(preset));
    } catch (const std::invalid_argument& e) {
        throw UsageError(
            QStringLiteral("%1 %2: %3").arg(origin, preset, QString::fromStdString(e.what())).toStdString());
    }
}

void printText(const config::DeformationModelFile& file) {
    const config::DeformationModelStatistics& s = file.statistics;
    printLine(QStringLiteral("Force-deformation model Y(a, f, z) of %1: %2 measurements, term set %3%4")
                  .arg(file.sourceFile)
                  .arg(s.pointCount)
                  .arg(QString::fromStdString(s.termSet))
                  .arg(s.stepwise ? QStringLiteral(", stepwise") : QString()));
    printLine(QStringLiteral("Coded factors x = (value - centre) / half range:"));
    const char* names[3] = {"a (depth of cut, mm)", "f (feed, mm/rev)", "z (axial position, mm)"};
    for (int f = 0; f < 3; ++f) {
        const core::FactorCoding& c = file.model.codings()[static_cast<std::size_t>(f)];
        printLine(QStringLiteral("  %1: %2 .. %3, centre %4, half range %5")
                      .arg(QLatin1String(names[f]))
                      .arg(number(c.min, 6), number(c.max, 6), number(c.centre, 6), number(c.halfRange, 6)));
    }
    printLine(QStringLiteral("  term            coefficient um   std error um        t"));
    for (const config::DeformationTermReport& t : s.terms)
        printLine(QStringLiteral("  %1 %2 %3 %4")
                      .arg(QString::fromStdString(t.name), -12)
                      .arg(t.coefficient, 16, 'f', 4)
                      .arg(t.stdError, 14, 'f', 4)
                      .arg(number(t.tValue, 4), 8));
    for (const auto& [name, t] : s.removed)
        printLine(QStringLiteral("  removed %1 (|t| %2 < %3)")
                      .arg(QString::fromStdString(name), number(t, 3), number(s.tCritical95, 4)));
    printLine(QStringLiteral("R² %1, adjusted R² %2, F %3 %4 F(0.95; %5, %6) = %7: %8")
                  .arg(number(s.r2, 6), number(s.r2Adjusted, 6), number(s.fStatistic))
                  .arg(s.significant() ? QStringLiteral(">") : QStringLiteral("<="))
                  .arg(s.termCount - 1)
                  .arg(s.residualDof)
                  .arg(number(s.fCritical95))
                  .arg(s.significant() ? QStringLiteral("the model is significant")
                                       : QStringLiteral("the model is NOT significant at 95 %")));
    printLine(QStringLiteral("Residual sigma %1 um, 2 sigma %2 um (the band the model states for a new measurement)")
                  .arg(number(s.residualSigmaUm), number(s.twoSigmaUm())));
}

int runFitDeformation(const QStringList& arguments) {
    CommandParser parser(
        QStringLiteral("fit-deformation"),
        QStringLiteral("Fits the force-deformation model Y(a, f, z) of paper 004 (Y in um, depth of cut "
                       "a mm, feed f mm/rev, axial position z mm) to an experiment, with R², adjusted "
                       "R², F against its table value, every term's standard error and t-value and "
                       "the residual 2 sigma. --json writes the model file schedule-feed reads."));
    parser.addPositional(QStringLiteral("FILE.csv"),
                         QStringLiteral("The experiment: header 'a_mm,f_mm_rev,z_mm,y_um', one row per measurement "
                                        "(deformation-experiment writes it)."));
    parser.addOption(QStringLiteral("terms"),
                     QStringLiteral("Terms to start from: cubic-z (the full quadratic in a and f times 1, z, z², z³), "
                                    "quadratic (full quadratic), interactions (linear plus af, az, fz, afz), linear, "
                                    "cubic-fz (one depth of cut: 1, f, f², f³ times 1, z, z², z³). Default: cubic-z."),
                     QStringLiteral("SET"), QStringLiteral("cubic-z"));
    parser.addOption(QStringLiteral("stepwise"),
                     QStringLiteral("Remove insignificant terms one by one (smallest |t| below t(0.975)), refitting."));
    parser.addOption(QStringLiteral("preset"),
                     QStringLiteral("The set-up the experiments were cut on, for its machine job (spindle, coolant, "
                                    "Z origin); default: the '# preset:' line of the CSV."),
                     QStringLiteral("NAME|FILE.json"));
    parser.addOption(QStringLiteral("out"), QStringLiteral("Also write the model file here."),
                     QStringLiteral("FILE.json"));
    parser.parse(arguments);
    const QString path = parser.positionals(1).first();
    const core::DeformationTermSet set =
        core::deformationTermSetFromName(parser.choice(QStringLiteral("terms"), kTermSets).toStdString());

    const config::DeformationCsv csv = [&] {
        try {
            return config::parseDeformationCsv(readInputFile(path));
        } catch (const std::invalid_argument& e) {
            throw inputError(path, e.what());
        }
    }();
    config::DeformationModelFile file = [&] {
        try {
            return config::deformationModelFile(
                core::fitDeformationModel(csv.samples, set, parser.isSet(QStringLiteral("stepwise"))));
        } catch (const std::invalid_argument& e) {
            throw inputError(path, e.what());
        }
    }();
    file.sourceFile = QFileInfo(path).fileName();
    file.seed = csv.seed;
    if (parser.isSet(QStringLiteral("preset"))) {
        file.preset = parser.required(QStringLiteral("preset"));
        file.job = jobOf(file.preset, QStringLiteral("--preset"));
    } else if (!csv.preset.isEmpty()) {
        file.preset = csv.preset;
        file.job = jobOf(file.preset, path + QStringLiteral(": '# preset:'"));
    }
    const QJsonObject json = config::deformationModelToJson(file);
    if (parser.isSet(QStringLiteral("out")))
        writeOutputFile(parser.required(QStringLiteral("out")), QJsonDocument(json).toJson(QJsonDocument::Indented));
    if (parser.json())
        printJson(json);
    else
        printText(file);
    return kExitOk;
}

}  // namespace

Command makeFitDeformationCommand() {
    return {QStringLiteral("fit-deformation"),
            QStringLiteral("force-deformation model Y(a, f, z) from an experiment CSV (paper 004)"), runFitDeformation};
}

}  // namespace tt::cli
