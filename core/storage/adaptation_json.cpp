#include "core/storage/adaptation_json.h"

#include <QJsonArray>
#include <QStringList>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tt::storage {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

QJsonValue finiteOrNull(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue();
}

QJsonArray numbers(const std::vector<double>& values) {
    QJsonArray a;
    for (double v : values)
        a.append(finiteOrNull(v));
    return a;
}

std::vector<double> numbersOf(const QJsonValue& value) {
    std::vector<double> out;
    for (const QJsonValue& v : value.toArray())
        out.push_back(v.isDouble() ? v.toDouble() : kNaN);
    return out;
}

double numberOf(const QJsonValue& value) {
    return value.isDouble() ? value.toDouble() : kNaN;
}

QJsonArray matrixJson(const std::vector<double>& rowMajor, std::size_t m) {
    QJsonArray rows;
    for (std::size_t r = 0; r < m && rowMajor.size() == m * m; ++r) {
        QJsonArray row;
        for (std::size_t c = 0; c < m; ++c)
            row.append(rowMajor[r * m + c]);
        rows.append(row);
    }
    return rows;
}

}  // namespace

QJsonObject plantModelJson(const core::PlantModelRecord& model) {
    QJsonArray gain, gainErr, gainErrJoint, ar, ma, arErr, maErr, noise, mean;
    for (const core::PointModelRecord& p : model.points) {
        gain.append(p.gain);
        gainErr.append(finiteOrNull(p.gainStdErr));
        gainErrJoint.append(finiteOrNull(p.gainStdErrJoint));
        ar.append(numbers(p.ar));
        ma.append(numbers(p.ma));
        arErr.append(numbers(p.arStdErr));
        maErr.append(numbers(p.maStdErr));
        noise.append(finiteOrNull(p.noiseVarianceMm2));
        mean.append(finiteOrNull(p.meanMm));
    }
    QJsonObject o{{QStringLiteral("delay"), model.delayParts},
                  {QStringLiteral("lag"), model.lagParts},
                  {QStringLiteral("gain"), gain},
                  {QStringLiteral("gain_std_error"), gainErr},
                  {QStringLiteral("gain_std_error_joint"), gainErrJoint},
                  {QStringLiteral("ar"), ar},
                  {QStringLiteral("ma"), ma},
                  {QStringLiteral("ar_std_error"), arErr},
                  {QStringLiteral("ma_std_error"), maErr},
                  {QStringLiteral("noise_variance"), noise},
                  {QStringLiteral("mean"), mean},
                  {QStringLiteral("source"), QString::fromStdString(model.source)}};
    if (!model.criterion.empty()) o.insert(QStringLiteral("criterion"), QString::fromStdString(model.criterion));
    if (!model.innovationCorrelation.empty())
        o.insert(QStringLiteral("innovation_correlation"),
                 matrixJson(model.innovationCorrelation, model.points.size()));
    return o;
}

core::PlantModelRecord plantModelFromJson(const QJsonObject& o) {
    core::PlantModelRecord r;
    r.delayParts = o.value(QStringLiteral("delay")).toInt(0);
    r.lagParts = o.value(QStringLiteral("lag")).toInt(0);
    r.source = o.value(QStringLiteral("source")).toString().toStdString();
    r.criterion = o.value(QStringLiteral("criterion")).toString().toStdString();
    const QJsonArray gain = o.value(QStringLiteral("gain")).toArray();
    if (r.delayParts < 1 || gain.isEmpty()) throw std::invalid_argument("a recorded plant model is damaged");
    auto at = [&](const char* key, qsizetype i) { return o.value(QLatin1String(key)).toArray().at(i); };
    for (qsizetype i = 0; i < gain.size(); ++i) {
        core::PointModelRecord p;
        p.gain = numberOf(gain.at(i));
        p.gainStdErr = numberOf(at("gain_std_error", i));
        p.gainStdErrJoint = numberOf(at("gain_std_error_joint", i));
        p.ar = numbersOf(at("ar", i));
        p.ma = numbersOf(at("ma", i));
        p.arStdErr = numbersOf(at("ar_std_error", i));
        p.maStdErr = numbersOf(at("ma_std_error", i));
        p.noiseVarianceMm2 = numberOf(at("noise_variance", i));
        p.meanMm = numberOf(at("mean", i));
        r.points.push_back(std::move(p));
    }
    for (const QJsonValue& row : o.value(QStringLiteral("innovation_correlation")).toArray())
        for (double v : numbersOf(row))
            r.innovationCorrelation.push_back(v);
    return r;
}

QJsonObject marginsJson(const core::MarginsRecord& m) {
    return QJsonObject{{QStringLiteral("gain"), finiteOrNull(m.gain)},
                       {QStringLiteral("gain_lower"), finiteOrNull(m.gainLower)},
                       {QStringLiteral("phase_deg"), finiteOrNull(m.phaseDeg)},
                       {QStringLiteral("delay_parts"), finiteOrNull(m.delayParts)},
                       {QStringLiteral("extra_parts"), m.extraPartsTolerated}};
}

core::MarginsRecord marginsFromJson(const QJsonObject& o) {
    core::MarginsRecord m;
    m.gain = numberOf(o.value(QStringLiteral("gain")));
    m.gainLower = numberOf(o.value(QStringLiteral("gain_lower")));
    m.phaseDeg = numberOf(o.value(QStringLiteral("phase_deg")));
    m.delayParts = numberOf(o.value(QStringLiteral("delay_parts")));
    m.extraPartsTolerated = o.value(QStringLiteral("extra_parts")).toInt(0);
    return m;
}

QString modelSummary(const core::PlantModelRecord& model) {
    auto list = [](const std::vector<double>& v) {
        QStringList out;
        for (double x : v)
            out << QString::number(x, 'g', 4);
        return out.join(QStringLiteral(" "));
    };
    QStringList parts{QStringLiteral("delay %1 parts (lag %2)").arg(model.delayParts).arg(model.lagParts)};
    for (std::size_t i = 0; i < model.points.size(); ++i) {
        const core::PointModelRecord& p = model.points[i];
        QString text = QStringLiteral("point %1: gain %2").arg(i + 1).arg(p.gain, 0, 'g', 4);
        if (std::isfinite(p.gainStdErr)) text += QStringLiteral(" ± %1").arg(p.gainStdErr, 0, 'g', 2);
        if (std::isfinite(p.noiseVarianceMm2))
            text += QStringLiteral(", AR [%1], MA [%2], σ² %3 mm²")
                        .arg(list(p.ar), list(p.ma))
                        .arg(p.noiseVarianceMm2, 0, 'g', 3);
        parts << text;
    }
    if (!model.source.empty()) parts << QStringLiteral("from %1").arg(QString::fromStdString(model.source));
    return parts.join(QStringLiteral("; "));
}

QJsonObject adaptationJson(const core::AdaptationRecord& a) {
    return QJsonObject{
        {QStringLiteral("part"), static_cast<qint64>(a.partNumber)},
        {QStringLiteral("kind"), QString::fromStdString(a.kind)},
        {QStringLiteral("reason"), QString::fromStdString(a.reason)},
        {QStringLiteral("fallback"), a.fallback.empty() ? QJsonValue() : QString::fromStdString(a.fallback)},
        {QStringLiteral("fallback_weight"), finiteOrNull(a.fallbackWeight)},
        {QStringLiteral("model_before"), plantModelJson(a.modelBefore)},
        {QStringLiteral("model_after"), a.modelAfter ? QJsonValue(plantModelJson(*a.modelAfter)) : QJsonValue()},
        {QStringLiteral("margins"), marginsJson(a.margins)},
        {QStringLiteral("applied"), a.applied},
        {QStringLiteral("message"), QString::fromStdString(core::describe(a.notice))}};
}

}  // namespace tt::storage
