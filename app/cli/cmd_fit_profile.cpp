#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <cmath>
#include <stdexcept>

#include "app/cli/command.h"
#include "app/cli/command_files.h"
#include "app/cli/command_parser.h"
#include "config/json_eigen.h"
#include "config/preset_library.h"
#include "config/profile_csv.h"
#include "config/profile_model_config.h"
#include "core/model/polynomial_regression.h"
#include "core/model/scaled_polynomial.h"
#include "core/model/systematic_error_model.h"

namespace tt::cli {

namespace {

struct FitOutcome {
    core::PolynomialRegression fit;
    std::vector<core::DegreeCandidate> candidates;  ///< empty when the degree was given
};

config::ProfileSamples readSamples(const QString& path) {
    const QByteArray text = readInputFile(path);
    try {
        return config::parseProfileCsv(text);
    } catch (const std::invalid_argument& e) {
        throw inputError(path, e.what());
    }
}

FitOutcome fit(const QString& path, const config::ProfileSamples& s, int degree) {
    try {
        if (degree > 0) return {core::fitPolynomialRegression(s.xMm, s.errorMm, degree), {}};
        core::DegreeSelection selection = core::fitPolynomialRegressionAutoDegree(s.xMm, s.errorMm);
        return {std::move(selection.fit), std::move(selection.candidates)};
    } catch (const std::invalid_argument& e) {
        throw inputError(path, e.what());
    }
}

QString number(double v, int precision = 4) {
    return std::isfinite(v) ? QString::number(v, 'g', precision) : QStringLiteral("infinite");
}

void printText(const QString& path, const FitOutcome& o, const core::PolynomialPeak& peak, double xMin, double xMax) {
    const core::PolynomialRegression& f = o.fit;
    printLine(QStringLiteral("Systematic diameter error fit of %1: %2 points, x %3 .. %4 mm")
                  .arg(path)
                  .arg(f.pointCount)
                  .arg(number(xMin, 6), number(xMax, 6)));
    if (o.candidates.empty()) {
        printLine(QStringLiteral("Degree %1 (given)").arg(f.degree));
    } else {
        printLine(QStringLiteral("Degree %1 (auto: smallest leave-one-out prediction error, PRESS)").arg(f.degree));
        for (const core::DegreeCandidate& c : o.candidates)
            printLine(QStringLiteral("  degree %1: PRESS %2 mm²%3")
                          .arg(c.degree)
                          .arg(std::isfinite(c.press) ? number(c.press) : QStringLiteral("not estimable"))
                          .arg(c.degree == f.degree ? QStringLiteral("  <- chosen") : QString()));
    }
    printLine(QStringLiteral("d(x) = b0 + b1 x + ... + b%1 x^%1, x in mm, d in mm:").arg(f.degree));
    for (int k = 0; k <= f.degree; ++k)
        printLine(QStringLiteral("  b%1 = %2   (standard error %3)")
                      .arg(k)
                      .arg(f.coefficients(k), 14, 'e', 6)
                      .arg(f.coefficientStdErrors(k), 0, 'e', 2));
    const bool significant = f.fStatistic > f.fCritical95;
    printLine(QStringLiteral("R² %1, adjusted R² %2, F %3 %4 F(0.95; %5, %6) = %7: %8")
                  .arg(number(f.r2), number(f.r2Adjusted), number(f.fStatistic))
                  .arg(significant ? QStringLiteral(">") : QStringLiteral("<="))
                  .arg(f.degree)
                  .arg(f.residualDof)
                  .arg(number(f.fCritical95))
                  .arg(significant ? QStringLiteral("the model is significant")
                                   : QStringLiteral("the model is NOT significant at 95 %")));
    printLine(QStringLiteral("Residual sigma %1 mm (2 sigma %2 mm)")
                  .arg(number(f.residualSigma), number(2.0 * f.residualSigma)));
    printLine(QStringLiteral("Largest error %1 mm at x = %2 mm; feed-forward y_ff(x) = -d(x)/2 = %3 mm there")
                  .arg(number(peak.value), number(peak.x), number(-0.5 * peak.value)));
}

QJsonObject toJson(const QString& path, const FitOutcome& o, const core::PolynomialPeak& peak, double xMin,
                   double xMax) {
    QJsonObject out = config::regressionToJson(o.fit);
    out.insert(QStringLiteral("file"), path);
    out.insert(QStringLiteral("degree_choice"),
               o.candidates.empty() ? QStringLiteral("given") : QStringLiteral("auto"));
    if (!o.candidates.empty()) {
        QJsonArray selection;
        for (const core::DegreeCandidate& c : o.candidates)
            selection.append(QJsonObject{{QStringLiteral("degree"), c.degree},
                                         {QStringLiteral("press"), config::finiteOrNull(c.press)}});
        out.insert(QStringLiteral("selection"), selection);
    }
    out.insert(QStringLiteral("x_range_mm"), QJsonArray{xMin, xMax});
    out.insert(QStringLiteral("peak"),
               QJsonObject{{QStringLiteral("x_mm"), peak.x}, {QStringLiteral("error_mm"), peak.value}});
    return out;
}

/// Writes the fitted model as a preset file (name, description, systematic_model) that
/// `--preset FILE.json` and the feed-forward read back; the part length is the largest x.
void savePreset(const QString& target, const QString& source, const core::PolynomialRegression& f, double xMax) {
    if (!(xMax > 0.0))
        throw UsageError(
            QStringLiteral("--save: the largest x is %1 mm; a part length must be positive").arg(xMax).toStdString());
    const core::SystematicErrorModel model(f.polynomial, xMax);
    QJsonObject section = config::systematicModelToJson(model);
    section.insert(QStringLiteral("fit_statistics"), config::regressionToJson(f));
    QJsonObject preset;
    preset.insert(QStringLiteral("name"), QFileInfo(target).completeBaseName());
    preset.insert(QStringLiteral("description"),
                  QStringLiteral("Systematic diameter error fitted by 'trueturn fit-profile' from %1: %2 points, "
                                 "degree %3, R² %4, residual sigma %5 mm. x in mm from the left end, d in mm.")
                      .arg(QFileInfo(source).fileName())
                      .arg(f.pointCount)
                      .arg(f.degree)
                      .arg(f.r2, 0, 'g', 4)
                      .arg(f.residualSigma, 0, 'g', 4));
    preset.insert(QStringLiteral("systematic_model"), section);
    writeOutputFile(target, QJsonDocument(preset).toJson(QJsonDocument::Indented));
}

/// `--preset`: shows the systematic model stored in a preset (the Table 1 groups or a saved fit).
int showPreset(const QString& nameOrPath, bool json) {
    core::SystematicErrorModel model = [&] {
        try {
            return config::systematicModelFromPreset(config::PresetLibrary::load(nameOrPath));
        } catch (const std::invalid_argument& e) {
            throw UsageError(
                QStringLiteral("--preset %1: %2").arg(nameOrPath, QString::fromStdString(e.what())).toStdString());
        }
    }();
    const core::PolynomialPeak peak = model.peak();
    const Eigen::VectorXd b = model.diameterError().powerCoefficients();
    if (json) {
        QJsonObject out;
        out.insert(QStringLiteral("preset"), nameOrPath);
        out.insert(QStringLiteral("degree"), model.diameterError().degree());
        QJsonArray coefficients;
        for (Eigen::Index k = 0; k < b.size(); ++k)
            coefficients.append(b(k));
        out.insert(QStringLiteral("coefficients"), coefficients);
        out.insert(QStringLiteral("part_length_mm"), model.partLengthMm());
        out.insert(QStringLiteral("peak"),
                   QJsonObject{{QStringLiteral("x_mm"), peak.x}, {QStringLiteral("error_mm"), peak.value}});
        out.insert(QStringLiteral("feed_forward_at_peak_mm"), model.feedForwardMm(peak.x));
        printJson(out);
        return kExitOk;
    }
    printLine(QStringLiteral("Systematic diameter error of preset %1 on a %2 mm part:")
                  .arg(nameOrPath, number(model.partLengthMm(), 6)));
    printLine(QStringLiteral("d(x) = b0 + b1 x + ... + b%1 x^%1, x in mm, d in mm:").arg(b.size() - 1));
    for (Eigen::Index k = 0; k < b.size(); ++k)
        printLine(QStringLiteral("  b%1 = %2").arg(k).arg(b(k), 14, 'e', 6));
    printLine(QStringLiteral("Largest error %1 mm at x = %2 mm; feed-forward y_ff(x) = -d(x)/2 = %3 mm there")
                  .arg(number(peak.value), number(peak.x), number(model.feedForwardMm(peak.x))));
    return kExitOk;
}

bool hasPositional(const CommandParser& parser) {
    try {
        parser.positionals(1);
        return true;
    } catch (const UsageError&) {
        return false;
    }
}

/// 0 for "auto", else the degree 1..6.
int parseDegree(const QString& text) {
    if (text.trimmed().compare(QStringLiteral("auto"), Qt::CaseInsensitive) == 0) return 0;
    bool ok = false;
    const int degree = text.trimmed().toInt(&ok);
    if (!ok || degree < 1 || degree > core::kMaxRegressionDegree)
        throw UsageError(QStringLiteral("--degree: '%1' is not a degree 1 .. %2 or 'auto'")
                             .arg(text)
                             .arg(core::kMaxRegressionDegree)
                             .toStdString());
    return degree;
}

int runFitProfile(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("fit-profile"),
                         QStringLiteral("Fits the systematic diameter error along the part, d(x) = b0 + b1 x + ... + "
                                        "bD x^D (x in mm, d in mm), with R², F test and residual sigma; the "
                                        "feed-forward cutter path is y_ff(x) = -d(x)/2."));
    parser.addPositional(QStringLiteral("FILE.csv"),
                         QStringLiteral("Gauged errors: header 'x_mm,error_mm', then one 'x,error' row per point "
                                        "(repeated positions from several parts are fine)."));
    parser.addOption(QStringLiteral("degree"),
                     QStringLiteral("Polynomial degree 1 .. 6, or 'auto' (leave-one-out cross-validation). "
                                    "Default: auto."),
                     QStringLiteral("D|auto"), QStringLiteral("auto"));
    parser.addOption(QStringLiteral("save"),
                     QStringLiteral("Also write the fitted model as a preset file (JSON) for the feed-forward."),
                     QStringLiteral("FILE.json"));
    parser.addOption(QStringLiteral("preset"),
                     QStringLiteral("Instead of fitting, show the systematic model of a preset "
                                    "(paper-2012-table1-group1..3, or a file saved with --save)."),
                     QStringLiteral("NAME|FILE.json"));
    parser.parse(arguments);
    if (parser.isSet(QStringLiteral("preset"))) {
        if (hasPositional(parser) || parser.isSet(QStringLiteral("save")) || parser.isSet(QStringLiteral("degree")))
            throw UsageError("--preset shows a stored model: give it without FILE.csv, --degree or --save");
        return showPreset(parser.required(QStringLiteral("preset")), parser.json());
    }
    const QString path = parser.positionals(1).first();
    const int degree = parseDegree(parser.value(QStringLiteral("degree")));

    const config::ProfileSamples samples = readSamples(path);
    const FitOutcome outcome = fit(path, samples, degree);
    const double xMin = samples.xMm.minCoeff();
    const double xMax = samples.xMm.maxCoeff();
    const core::PolynomialPeak peak = outcome.fit.polynomial.largestMagnitude(xMin, xMax);
    if (parser.isSet(QStringLiteral("save")))
        savePreset(parser.required(QStringLiteral("save")), path, outcome.fit, xMax);
    if (parser.json())
        printJson(toJson(path, outcome, peak, xMin, xMax));
    else
        printText(path, outcome, peak, xMin, xMax);
    return kExitOk;
}

}  // namespace

Command makeFitProfileCommand() {
    return {QStringLiteral("fit-profile"), QStringLiteral("systematic profile error regression from a CSV file"),
            runFitProfile};
}

}  // namespace tt::cli
