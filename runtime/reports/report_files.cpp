#include "runtime/reports/report_files.h"

#include <QDateTime>
#include <QFile>
#include <QSaveFile>
#include <QTextStream>
#include <map>
#include <stdexcept>

namespace tt::runtime {

namespace {

/// Rows between two progress calls.
constexpr std::size_t kProgressStep = 4096;

QString csvNumber(double v) {
    return QString::number(v, 'f', 4);
}

QString csvText(const std::string& text) {
    QString s = QString::fromStdString(text);
    if (s.contains(QLatin1Char(',')) || s.contains(QLatin1Char('"')) || s.contains(QLatin1Char('\n')))
        s = QLatin1Char('"') + s.replace(QLatin1String("\""), QLatin1String("\"\"")) + QLatin1Char('"');
    return s;
}

/// AQDEF date/time: DD.MM.YYYY/HH:MM:SS, from the stored ISO 8601 UTC.
QString dfqTime(const std::string& iso) {
    const QDateTime t = QDateTime::fromString(QString::fromStdString(iso), Qt::ISODateWithMs);
    return t.isValid() ? t.toUTC().toString(QStringLiteral("dd.MM.yyyy/HH:mm:ss")) : QString();
}

void openFile(QSaveFile& file, const QString& path, QIODevice::OpenMode mode) {
    if (!file.open(mode))
        throw std::runtime_error("cannot write '" + path.toStdString() + "': " + file.errorString().toStdString());
}

void commitFile(QSaveFile& file, QTextStream& out, const QString& path) {
    out.flush();
    if (out.status() != QTextStream::Ok || !file.commit())
        throw std::runtime_error("writing '" + path.toStdString() + "' failed: " + file.errorString().toStdString());
}

void step(const ReportProgress& progress, std::size_t done, std::size_t total) {
    if (progress && done % kProgressStep == 0 && !progress(done, total)) throw ReportCancelled();
}

}  // namespace

void writeMeasurementsCsv(const QString& path, const std::vector<storage::MeasurementRow>& rows,
                          const ReportProgress& progress) {
    QSaveFile file(path);  // nothing is left behind when cancelled or failed
    openFile(file, path, QIODevice::WriteOnly | QIODevice::Text);
    QTextStream out(&file);
    out << "run,machine,part,time,point,x_mm,nominal_mm,measured_mm,deviation_mm,verdict\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        step(progress, i, rows.size());
        const storage::MeasurementRow& r = rows[i];
        out << r.runId << ',' << csvText(r.machine) << ',' << r.partNumber << ','
            << QString::fromStdString(r.recordedAt) << ',' << r.pointIndex + 1 << ',' << csvNumber(r.zMm) << ','
            << csvNumber(r.nominalMm) << ',' << csvNumber(r.measuredMm) << ',' << csvNumber(r.measuredMm - r.nominalMm)
            << ',' << (r.verdict ? QString::fromStdString(core::toleranceVerdictName(*r.verdict)) : QString()) << '\n';
    }
    commitFile(file, out, path);
    if (progress) progress(rows.size(), rows.size());
}

void writeMeasurementsDfq(const QString& path, const std::vector<storage::MeasurementRow>& rows,
                          const ReportProgress& progress) {
    if (rows.empty()) throw std::invalid_argument("a DFQ file needs at least one reading");
    QSaveFile file(path);
    openFile(file, path, QIODevice::WriteOnly);
    QTextStream out(&file);
    out.setEncoding(QStringConverter::Latin1);
    const std::vector<PointRows> points = rowsByPoint(rows);
    std::map<int, int> characteristic;  // point index -> K-field index 1..
    for (const PointRows& point : points)
        characteristic[point.pointIndex] = static_cast<int>(characteristic.size()) + 1;
    out << "K0100 " << characteristic.size() << "\r\n";
    out << "K1001 "
        << (rows.front().machine.empty() ? QStringLiteral("shaft") : QString::fromStdString(rows.front().machine))
        << "\r\n";
    out << "K1002 TrueTurn shaft, run(s) " << rows.front().runId << ".." << rows.back().runId << "\r\n";
    for (const PointRows& point : points) {
        const QString k = QStringLiteral("/%1 ").arg(characteristic[point.pointIndex]);
        const std::optional<core::SpecLimits> spec = specOf(point);
        out << "K2001" << k << "P" << point.pointIndex + 1 << "\r\n";
        out << "K2002" << k << "Diameter at x = " << QString::number(point.rows.front()->zMm, 'f', 1) << " mm\r\n";
        out << "K2022" << k << "4\r\n";
        out << "K2101" << k << QString::number(point.rows.front()->nominalMm, 'f', 4) << "\r\n";
        if (spec) {
            out << "K2110" << k << QString::number(spec->lowerMm, 'f', 4) << "\r\n";
            out << "K2111" << k << QString::number(spec->upperMm, 'f', 4) << "\r\n";
        }
        out << "K2142" << k << "mm\r\n";
    }
    for (std::size_t i = 0; i < rows.size(); ++i) {
        step(progress, i, rows.size());
        const storage::MeasurementRow& r = rows[i];
        const QString k = QStringLiteral("/%1 ").arg(characteristic[r.pointIndex]);
        out << "K0001" << k << QString::number(r.measuredMm, 'f', 4) << "\r\n";
        out << "K0004" << k << dfqTime(r.recordedAt) << "\r\n";
    }
    commitFile(file, out, path);
    if (progress) progress(rows.size(), rows.size());
}

}  // namespace tt::runtime
