#include "config/profile_csv.h"

#include "core/common/text_format.h"

#include <QList>
#include <QString>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace tt::config {

namespace {

std::invalid_argument lineError(int line, const QString& why) {
    return std::invalid_argument("line " + std::to_string(line) + ": " + why.toStdString());
}

double parseField(const QString& field, const char* column, int line, double limitMm) {
    if (field.isEmpty()) throw lineError(line, QStringLiteral("the %1 value is empty").arg(QLatin1String(column)));
    bool ok = false;
    const double v = field.toDouble(&ok);
    if (!ok)
        throw lineError(line, QStringLiteral("%1 '%2' is not a number").arg(QLatin1String(column), field.left(40)));
    if (!std::isfinite(v))
        throw lineError(line,
                        QStringLiteral("%1 '%2' is not a finite number").arg(QLatin1String(column), field.left(40)));
    if (std::abs(v) > limitMm)
        throw lineError(line, QStringLiteral("%1 '%2' is outside %3 .. %4 mm")
                                  .arg(QLatin1String(column), field.left(40))
                                  .arg(-limitMm, 0, 'g', 17)
                                  .arg(limitMm, 0, 'g', 17));
    return v;
}

}  // namespace

ProfileSamples parseProfileCsv(const QByteArray& text) {
    QString content = QString::fromUtf8(text);
    if (content.startsWith(QChar(0xFEFF))) content.remove(0, 1);
    const QStringList lines = content.split(QLatin1Char('\n'));
    std::vector<double> x, error;
    bool headerSeen = false;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const int lineNumber = static_cast<int>(i) + 1;
        const QString line = lines.at(i).trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1Char('#'))) continue;
        QStringList fields = line.split(QLatin1Char(','));
        for (QString& f : fields)
            f = f.trimmed();
        if (!headerSeen) {
            if (fields.size() != 2 || fields.at(0).compare(QStringLiteral("x_mm"), Qt::CaseInsensitive) != 0 ||
                fields.at(1).compare(QStringLiteral("error_mm"), Qt::CaseInsensitive) != 0)
                throw lineError(lineNumber,
                                QStringLiteral("expected the header 'x_mm,error_mm', found '%1'").arg(line.left(60)));
            headerSeen = true;
            continue;
        }
        if (fields.size() < 2) throw lineError(lineNumber, QStringLiteral("missing the error_mm column"));
        if (fields.size() > 2)
            throw lineError(lineNumber, QStringLiteral("%1 columns, expected 2 (x_mm,error_mm)%2")
                                            .arg(fields.size())
                                            .arg(QLatin1String(core::kCLocaleNote)));
        x.push_back(parseField(fields.at(0), "x_mm", lineNumber, kMaxAbsXMm));
        error.push_back(parseField(fields.at(1), "error_mm", lineNumber, kMaxAbsErrorMm));
    }
    if (!headerSeen) throw std::invalid_argument("line 1: the file is empty; expected the header 'x_mm,error_mm'");
    if (x.empty()) throw std::invalid_argument("no data rows after the header 'x_mm,error_mm'");
    ProfileSamples samples;
    samples.xMm = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
    samples.errorMm = Eigen::Map<const Eigen::VectorXd>(error.data(), static_cast<Eigen::Index>(error.size()));
    return samples;
}

}  // namespace tt::config
