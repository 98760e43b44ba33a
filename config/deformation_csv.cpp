#include "config/deformation_csv.h"

#include "core/common/text_format.h"

#include <QString>
#include <QStringList>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace tt::config {

namespace {

constexpr qsizetype kMaxRows = 1000000;
const std::array<const char*, 4> kColumns = {"a_mm", "f_mm_rev", "z_mm", "y_um"};
const QString kHeader = QStringLiteral("a_mm,f_mm_rev,z_mm,y_um");

std::invalid_argument lineError(int line, const QString& why) {
    return std::invalid_argument("line " + std::to_string(line) + ": " + why.toStdString());
}

double parseField(const QString& field, const char* column, int line) {
    if (field.isEmpty()) throw lineError(line, QStringLiteral("the %1 value is empty").arg(QLatin1String(column)));
    bool ok = false;
    const double v = field.toDouble(&ok);
    if (!ok || !std::isfinite(v))
        throw lineError(line,
                        QStringLiteral("%1 '%2' is not a finite number").arg(QLatin1String(column), field.left(40)));
    return v;
}

/// "# key: value" of a comment line into the metadata it names.
void readComment(const QString& line, int lineNumber, DeformationCsv& csv) {
    const QString body = line.mid(1).trimmed();
    const qsizetype colon = body.indexOf(QLatin1Char(':'));
    if (colon < 0) return;
    const QString key = body.left(colon).trimmed().toLower();
    const QString value = body.mid(colon + 1).trimmed();
    if (key == QStringLiteral("preset")) {
        csv.preset = value;
    } else if (key == QStringLiteral("seed")) {
        bool ok = false;
        const qulonglong seed = value.toULongLong(&ok);
        if (!ok) throw lineError(lineNumber, QStringLiteral("the seed '%1' is not a whole number").arg(value.left(40)));
        csv.seed = seed;
    }
}

Eigen::VectorXd toVector(const std::vector<double>& v) {
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

}  // namespace

DeformationCsv parseDeformationCsv(const QByteArray& text) {
    QString content = QString::fromUtf8(text);
    if (content.startsWith(QChar(0xFEFF))) content.remove(0, 1);
    const QStringList lines = content.split(QLatin1Char('\n'));
    DeformationCsv csv;
    std::array<std::vector<double>, 4> columns;
    bool headerSeen = false;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const int lineNumber = static_cast<int>(i) + 1;
        const QString line = lines.at(i).trimmed();
        if (line.isEmpty()) continue;
        if (line.startsWith(QLatin1Char('#'))) {
            readComment(line, lineNumber, csv);
            continue;
        }
        QStringList fields = line.split(QLatin1Char(','));
        for (QString& f : fields)
            f = f.trimmed();
        if (!headerSeen) {
            if (fields.join(QLatin1Char(',')).compare(kHeader, Qt::CaseInsensitive) != 0)
                throw lineError(lineNumber,
                                QStringLiteral("expected the header '%1', found '%2'").arg(kHeader, line.left(60)));
            headerSeen = true;
            continue;
        }
        if (fields.size() != 4)
            throw lineError(lineNumber, QStringLiteral("%1 columns, expected 4 (%2)%3")
                                            .arg(fields.size())
                                            .arg(kHeader, QLatin1String(core::kCLocaleNote)));
        if (columns[0].size() >= static_cast<std::size_t>(kMaxRows))
            throw lineError(lineNumber, QStringLiteral("more than %1 rows").arg(kMaxRows));
        for (std::size_t c = 0; c < 4; ++c)
            columns[c].push_back(parseField(fields.at(static_cast<qsizetype>(c)), kColumns[c], lineNumber));
    }
    if (!headerSeen)
        throw std::invalid_argument("line 1: the file is empty; expected the header '" + kHeader.toStdString() + "'");
    if (columns[0].empty())
        throw std::invalid_argument("no data rows after the header '" + kHeader.toStdString() + "'");
    csv.samples.depthMm = toVector(columns[0]);
    csv.samples.feedMmPerRev = toVector(columns[1]);
    csv.samples.zMm = toVector(columns[2]);
    csv.samples.deformationUm = toVector(columns[3]);
    return csv;
}

QByteArray deformationCsvText(const DeformationCsv& csv) {
    const core::DeformationSamples& s = csv.samples;
    QString out;
    out += QStringLiteral("# force-deformation experiment (paper 004): depth a mm, feed f mm/rev, z mm, Y um\n");
    if (!csv.preset.isEmpty()) out += QStringLiteral("# preset: %1\n").arg(csv.preset);
    if (csv.seed) out += QStringLiteral("# seed: %1\n").arg(*csv.seed);
    out += kHeader + QLatin1Char('\n');
    for (Eigen::Index i = 0; i < s.size(); ++i)
        out += QStringLiteral("%1,%2,%3,%4\n")
                   .arg(s.depthMm(i), 0, 'g', 10)
                   .arg(s.feedMmPerRev(i), 0, 'g', 10)
                   .arg(s.zMm(i), 0, 'g', 10)
                   .arg(s.deformationUm(i), 0, 'g', 10);
    return out.toUtf8();
}

}  // namespace tt::config
