#include <QDateTime>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <cstdio>
#include <stdexcept>

#include "app/cli/command.h"
#include "app/cli/command_files.h"
#include "app/cli/command_parser.h"
#include "core/calibration/calibration_csv.h"
#include "core/calibration/linearisation_image.h"
#include "core/calibration/probe_linearisation.h"

namespace tt::cli {

namespace {

std::vector<core::CalibrationPoint> readPoints(const QString& path) {
    const QByteArray bytes = readInputFile(path);
    try {
        return core::parseCalibrationCsv(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    } catch (const std::invalid_argument& e) {
        throw inputError(path, e.what());
    }
}

int parseDegree(const QString& text) {
    const QString t = text.trimmed().toLower();
    if (t == QStringLiteral("auto")) return core::kAutoDegree;
    if (t == QStringLiteral("2") || t == QStringLiteral("3") || t == QStringLiteral("4")) return t.toInt();
    throw UsageError(QStringLiteral("--degree: '%1' is not 2, 3, 4 or auto").arg(text).toStdString());
}

QJsonArray scoresJson(const core::CharacteristicFit& fit) {
    QJsonArray scores;
    for (const core::DegreeScore& s : fit.scores)
        scores.append(QJsonObject{{QStringLiteral("degree"), s.degree},
                                  {QStringLiteral("cv_rms_um"), s.cvRmsUm},
                                  {QStringLiteral("cv_standard_error_um"), s.cvStandardErrorUm},
                                  {QStringLiteral("rms_residual_um"), s.rmsResidualUm}});
    return scores;
}

QJsonObject fitJson(const QString& path, const std::vector<core::CalibrationPoint>& points,
                    const core::CharacteristicFit& fit) {
    QJsonArray coefficients;
    for (Eigen::Index i = 0; i < fit.coefficients.size(); ++i)
        coefficients.append(fit.coefficients(i));
    QJsonArray residuals;
    for (double r : fit.residualsUm)
        residuals.append(r);
    QJsonObject out{
        {QStringLiteral("file"), path},
        {QStringLiteral("points"), static_cast<int>(points.size())},
        {QStringLiteral("adc_bits"), fit.adcBits},
        {QStringLiteral("degree"), fit.degree},
        {QStringLiteral("degree_choice"), fit.chosenAutomatically ? QStringLiteral("auto") : QStringLiteral("given")},
        {QStringLiteral("choice_reason"), QString::fromStdString(fit.choiceReason)},
        {QStringLiteral("scores"), scoresJson(fit)},
        {QStringLiteral("coefficients"), coefficients},
        {QStringLiteral("coefficients_unit"), QStringLiteral("adc_code = sum c_i * deflection_um^i")},
        {QStringLiteral("residuals_um"), residuals},
        {QStringLiteral("rms_residual_um"), fit.rmsResidualUm},
        {QStringLiteral("calibrated_range_um"), QJsonArray{fit.calibratedMinUm, fit.calibratedMaxUm}},
        {QStringLiteral("monotonic"), fit.monotonicity.monotonic},
        {QStringLiteral("increasing"), fit.monotonicity.increasing}};
    if (!fit.monotonicity.monotonic) {
        out.insert(QStringLiteral("turning_point"),
                   QJsonObject{{QStringLiteral("deflection_um"), *fit.monotonicity.turningDeflectionUm},
                               {QStringLiteral("adc_code"), *fit.monotonicity.turningCode}});
        out.insert(QStringLiteral("refused"), QString::fromStdString(fit.monotonicity.message));
        out.insert(QStringLiteral("entries"), 0);
    }
    return out;
}

/// Writes the table in the format the extension names; returns {format, image CRC}.
QJsonObject writeTable(const QString& path, const core::LinearisationTable& table, const core::TableImageInfo& info) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    const std::vector<std::uint8_t> image = core::encodeTableImage(table, info);
    QByteArray bytes;
    if (suffix == QStringLiteral("csv"))
        bytes = QByteArray::fromStdString(core::tableToCsv(table));
    else if (suffix == QStringLiteral("h"))
        bytes = QByteArray::fromStdString(core::tableToCHeader(table, info));
    else
        bytes = QByteArray(reinterpret_cast<const char*>(image.data()), static_cast<qsizetype>(image.size()));
    writeOutputFile(path, bytes);
    return QJsonObject{
        {QStringLiteral("file"), path},
        {QStringLiteral("format"), suffix},
        {QStringLiteral("version"), static_cast<int>(info.version)},
        {QStringLiteral("image_crc"), QString::fromStdString(core::crcText(core::tableImageCrc(image)))}};
}

void printText(const QString& path, const core::Linearisation& lin, const QJsonObject& written) {
    const core::CharacteristicFit& f = lin.fit;
    printLine(QStringLiteral("Probe linearisation of %1: %2 points, %3 .. %4 µm, %5-bit ADC")
                  .arg(path)
                  .arg(f.residualsUm.size())
                  .arg(f.calibratedMinUm, 0, 'f', 1)
                  .arg(f.calibratedMaxUm, 0, 'f', 1)
                  .arg(f.adcBits));
    printLine(QStringLiteral("Degree %1 (%2)").arg(f.degree).arg(QString::fromStdString(f.choiceReason)));
    for (const core::DegreeScore& s : f.scores)
        printLine(QStringLiteral("  degree %1: leave-one-out %2 µm, in-sample %3 µm%4")
                      .arg(s.degree)
                      .arg(s.cvRmsUm, 0, 'f', 3)
                      .arg(s.rmsResidualUm, 0, 'f', 3)
                      .arg(s.degree == f.degree ? QStringLiteral("  <- chosen") : QString()));
    printLine(QStringLiteral("adc_code = c0 + c1 d + ... (d in µm):"));
    for (Eigen::Index i = 0; i < f.coefficients.size(); ++i)
        printLine(QStringLiteral("  c%1 = %2").arg(i).arg(f.coefficients(i), 0, 'e', 8));
    printLine(QStringLiteral("Residual RMS %1 µm; table error at the points up to %2 µm; table step %3 µm; %4 of %5 "
                             "entries extrapolated")
                  .arg(f.rmsResidualUm, 0, 'f', 3)
                  .arg(lin.maxTableErrorUm, 0, 'f', 3)
                  .arg(lin.tableResolutionUm, 0, 'f', 3)
                  .arg(lin.extrapolatedEntries)
                  .arg(lin.table.entries.size()));
    for (const std::string& w : lin.warnings)
        printLine(QStringLiteral("Warning: ") + QString::fromStdString(w));
    if (!written.isEmpty())
        printLine(QStringLiteral("Wrote %1 (image CRC %2)")
                      .arg(written.value(QStringLiteral("file")).toString(),
                           written.value(QStringLiteral("image_crc")).toString()));
}

int runLinearise(const QStringList& arguments) {
    CommandParser parser(QStringLiteral("linearise"),
                         QStringLiteral("Fits the probe mandrel's static characteristic (ADC code against reference "
                                        "deflection, polynomial of degree 2..4, paper 001) and builds the table ADC "
                                        "code -> deflection with 2^bits entries for its microcontroller."));
    parser.addPositional(QStringLiteral("FILE.csv"),
                         QStringLiteral("Calibration pairs: header 'reference_um,adc_code', one row per point "
                                        "(reference deflection from a dial indicator or micrometer, µm)."));
    parser.addOption(QStringLiteral("adc-bits"), QStringLiteral("ADC resolution of the mandrel, 10 .. 16 bits."),
                     QStringLiteral("B"));
    parser.addOption(QStringLiteral("degree"),
                     QStringLiteral("Degree 2, 3, 4, or 'auto' (leave-one-out cross-validation with the "
                                    "one-standard-error rule). Default: auto."),
                     QStringLiteral("2|3|4|auto"), QStringLiteral("auto"));
    parser.addOption(QStringLiteral("out"),
                     QStringLiteral("Write the table: .csv (adc_code,deflection_um), .h (C header for the "
                                    "microcontroller) or .bin (image with version and CRC for upload)."),
                     QStringLiteral("FILE"));
    parser.addOption(QStringLiteral("table-version"),
                     QStringLiteral("Version number stored in the table image (1 .. 65535). Default: 1."),
                     QStringLiteral("N"), QStringLiteral("1"));
    parser.addOption(QStringLiteral("plane"),
                     QStringLiteral("Bending plane of the table: x (radial) or y. Default: x."), QStringLiteral("x|y"),
                     QStringLiteral("x"));
    parser.parse(arguments);
    const QString path = parser.positionals(1).first();
    const int bits = static_cast<int>(parser.integer(QStringLiteral("adc-bits"), core::kMinAdcBits, core::kMaxAdcBits));
    const int degree = parseDegree(parser.value(QStringLiteral("degree")));
    const QString out = parser.value(QStringLiteral("out"));
    if (!out.isEmpty()) {
        const QString suffix = QFileInfo(out).suffix().toLower();
        if (suffix != QStringLiteral("csv") && suffix != QStringLiteral("h") && suffix != QStringLiteral("bin"))
            throw UsageError(
                QStringLiteral("--out: '%1' must end in .csv, .h or .bin (the table's format)").arg(out).toStdString());
    }
    core::TableImageInfo info;
    info.version = static_cast<std::uint16_t>(parser.integer(QStringLiteral("table-version"), 1, 65535));
    info.plane =
        parser.choice(QStringLiteral("plane"), {QStringLiteral("x"), QStringLiteral("y")}) == QStringLiteral("x") ? 0
                                                                                                                  : 1;
    info.createdUnixS = QDateTime::currentSecsSinceEpoch();

    const std::vector<core::CalibrationPoint> points = readPoints(path);
    core::CharacteristicFit fit;
    try {
        fit = core::fitCharacteristic(points, bits, degree);
    } catch (const core::LinearisationRefused& e) {
        throw inputError(path, e.what());
    }
    if (!fit.monotonicity.monotonic) {
        if (parser.json()) printJson(fitJson(path, points, fit));
        throw inputError(path, fit.monotonicity.message);
    }
    core::Linearisation lin;
    try {
        lin = core::linearise(points, bits, degree);
    } catch (const core::LinearisationRefused& e) {
        throw inputError(path, e.what());
    }
    info.degree = static_cast<std::uint8_t>(lin.fit.degree);
    const QJsonObject written = out.isEmpty() ? QJsonObject{} : writeTable(out, lin.table, info);
    if (parser.json()) {
        QJsonObject json = fitJson(path, points, lin.fit);
        json.insert(QStringLiteral("max_table_error_um"), lin.maxTableErrorUm);
        json.insert(QStringLiteral("table_resolution_um"), lin.tableResolutionUm);
        json.insert(QStringLiteral("entries"), static_cast<int>(lin.table.entries.size()));
        json.insert(QStringLiteral("scale_nm"), lin.table.scaleNm);
        json.insert(QStringLiteral("extrapolated_entries"), lin.extrapolatedEntries);
        QJsonArray warnings;
        for (const std::string& w : lin.warnings)
            warnings.append(QString::fromStdString(w));
        json.insert(QStringLiteral("warnings"), warnings);
        if (!written.isEmpty()) json.insert(QStringLiteral("out"), written);
        printJson(json);
    } else {
        printText(path, lin, written);
    }
    return kExitOk;
}

}  // namespace

Command makeLineariseCommand() {
    return {QStringLiteral("linearise"),
            QStringLiteral("probe mandrel linearisation table from calibration pairs (CSV, C header, binary image)"),
            runLinearise};
}

}  // namespace tt::cli
