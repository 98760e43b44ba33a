#include "config/controller_model_config.h"

#include <QJsonArray>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "config/json_eigen.h"
#include "config/plant_config.h"

namespace tt::config {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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

[[noreturn]] void fail(const std::string& where, const std::string& why) {
    throw std::invalid_argument("controller_model" + where + ": " + why);
}

/// The ARMA of a recorded point as the presets' disturbance component.
QJsonArray disturbanceJson(const core::PointModelRecord& p) {
    if (p.ar.empty() && p.ma.empty())
        return QJsonArray{QJsonObject{{QStringLiteral("type"), QStringLiteral("white")},
                                      {QStringLiteral("variance_mm2"), p.noiseVarianceMm2}}};
    const std::size_t degree = std::max(p.ar.size(), p.ma.size());
    std::vector<double> numerator{1.0}, denominator{1.0};
    numerator.insert(numerator.end(), p.ma.begin(), p.ma.end());
    numerator.resize(degree + 1, 0.0);
    for (double a : p.ar)
        denominator.push_back(-a);
    denominator.resize(degree + 1, 0.0);
    return QJsonArray{QJsonObject{{QStringLiteral("type"), QStringLiteral("shaping_filter")},
                                  {QStringLiteral("numerator"), numbers(numerator)},
                                  {QStringLiteral("denominator"), numbers(denominator)},
                                  {QStringLiteral("input_variance_mm2"), p.noiseVarianceMm2}}};
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

Eigen::MatrixXd correlationAt(const QJsonValue& value, std::size_t m) {
    if (value.isUndefined()) return {};
    const QJsonArray rows = value.toArray();
    if (!value.isArray() || static_cast<std::size_t>(rows.size()) != m)
        fail(".innovation_correlation", "must be " + std::to_string(m) + " rows of " + std::to_string(m) + " numbers");
    Eigen::MatrixXd r(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
    for (std::size_t i = 0; i < m; ++i) {
        const std::vector<double> row = numbersOf(rows.at(static_cast<qsizetype>(i)));
        if (row.size() != m)
            fail(".innovation_correlation",
                 "must be " + std::to_string(m) + " rows of " + std::to_string(m) + " numbers");
        for (std::size_t j = 0; j < m; ++j) {
            if (!std::isfinite(row[j]) || std::abs(row[j]) > 1.0)
                fail(".innovation_correlation", "every entry must be a number in -1 .. 1");
            r(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = row[j];
        }
    }
    return r;
}

}  // namespace

std::optional<core::ControllerModel> controllerModelFromPreset(const QJsonObject& preset, std::size_t points,
                                                               int delay) {
    const QJsonValue section = preset.value(QStringLiteral("controller_model"));
    if (section.isUndefined()) return std::nullopt;
    if (!section.isObject()) fail("", "must be an object");
    const QJsonObject o = section.toObject();
    core::ControllerModel model;
    model.source = o.value(QStringLiteral("source")).toString().toStdString();
    const QJsonValue lag = o.value(QStringLiteral("lag_parts"));
    if (!lag.isUndefined()) {
        if (!lag.isDouble() || lag.toDouble() != std::floor(lag.toDouble()) || lag.toDouble() < 0.0 ||
            lag.toDouble() > core::kMaxDelay)
            fail(".lag_parts", "must be a whole number of parts 0 .. " + std::to_string(core::kMaxDelay));
        model.lagParts = lag.toInt();
    }
    const QJsonArray list = o.value(QStringLiteral("points")).toArray();
    if (static_cast<std::size_t>(list.size()) != points)
        fail(".points", "needs one entry per control point (" + std::to_string(points) + ")");
    for (qsizetype i = 0; i < list.size(); ++i) {
        const std::string where = ".points[" + std::to_string(i) + "]";
        const QJsonObject p = list.at(i).toObject();
        const double gain = numberOf(p.value(QStringLiteral("gain")));
        if (!(gain > 0.0 && gain <= 100.0)) fail(where + ".gain", "must be a number in (0, 100]");
        model.gain.push_back(gain);
        model.disturbance.push_back(disturbanceFromJson(
            p.value(QStringLiteral("disturbance")), QStringLiteral("controller_model.points[%1].disturbance").arg(i)));
    }
    model.innovationCorrelation = correlationAt(o.value(QStringLiteral("innovation_correlation")), points);
    try {
        model.validate(points, delay);
    } catch (const std::invalid_argument& e) {
        fail("", e.what());
    }
    return model;
}

QJsonObject controllerModelJson(const core::PlantModelRecord& model) {
    QJsonArray points;
    for (const core::PointModelRecord& p : model.points)
        points.append(QJsonObject{{QStringLiteral("gain"), p.gain},
                                  {QStringLiteral("gain_std_error"), finiteOrNull(p.gainStdErr)},
                                  {QStringLiteral("gain_std_error_joint"), finiteOrNull(p.gainStdErrJoint)},
                                  {QStringLiteral("ar"), numbers(p.ar)},
                                  {QStringLiteral("ma"), numbers(p.ma)},
                                  {QStringLiteral("ar_std_errors"), numbers(p.arStdErr)},
                                  {QStringLiteral("ma_std_errors"), numbers(p.maStdErr)},
                                  {QStringLiteral("noise_variance_mm2"), finiteOrNull(p.noiseVarianceMm2)},
                                  {QStringLiteral("mean_mm"), finiteOrNull(p.meanMm)},
                                  {QStringLiteral("disturbance"), disturbanceJson(p)}});
    QJsonObject o{{QStringLiteral("source"), QString::fromStdString(model.source)},
                  {QStringLiteral("lag_parts"), model.lagParts},
                  {QStringLiteral("points"), points}};
    if (!model.criterion.empty()) o.insert(QStringLiteral("criterion"), QString::fromStdString(model.criterion));
    if (!model.innovationCorrelation.empty())
        o.insert(QStringLiteral("innovation_correlation"),
                 matrixJson(model.innovationCorrelation, model.points.size()));
    return o;
}

}  // namespace tt::config
