#include "config/controller_tuning_json.h"

#include <QJsonArray>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "config/json_eigen.h"
#include "config/json_section.h"
#include "config/plant_config.h"

namespace tt::config {

namespace {

using core::DisturbanceComponent;

QJsonArray numbers(const std::vector<double>& values) {
    QJsonArray a;
    for (double v : values)
        a.append(v);
    return a;
}

QJsonObject componentToJson(const DisturbanceComponent& c) {
    switch (c.kind()) {
        case DisturbanceComponent::Kind::ShapingFilter:
            return {{QStringLiteral("type"), QStringLiteral("shaping_filter")},
                    {QStringLiteral("numerator"), numbers(c.filter()->numerator())},
                    {QStringLiteral("denominator"), numbers(c.filter()->denominator())},
                    {QStringLiteral("input_variance_mm2"), c.inputVarianceMm2()}};
        case DisturbanceComponent::Kind::Ar1:
            return {{QStringLiteral("type"), QStringLiteral("ar1")},
                    {QStringLiteral("pole"), c.pole()},
                    {QStringLiteral("variance_mm2"), c.stationaryVarianceMm2()}};
        case DisturbanceComponent::Kind::RandomWalk:
            return {{QStringLiteral("type"), QStringLiteral("random_walk")},
                    {QStringLiteral("step_variance_mm2"), c.inputVarianceMm2()}};
        case DisturbanceComponent::Kind::White:
            return {{QStringLiteral("type"), QStringLiteral("white")},
                    {QStringLiteral("variance_mm2"), c.inputVarianceMm2()}};
    }
    throw std::logic_error("unknown disturbance component");
}

/// A finite limit as a number; an unlimited one is left out.
void putLimit(QJsonObject& o, const QString& key, double valueMm) {
    if (std::isfinite(valueMm)) o.insert(key, valueMm);
}

QJsonObject ewmaToJson(const core::EwmaOptions& e) {
    QJsonObject o{{QStringLiteral("weight"), e.weight},
                  {QStringLiteral("dead_band_mm"), e.deadBandMm},
                  {QStringLiteral("drift_weight"), e.driftWeight}};
    putLimit(o, QStringLiteral("warning_mm"), e.warningMm);
    putLimit(o, QStringLiteral("alarm_mm"), e.alarmMm);
    return o;
}

/// A square matrix with one row per control point, as the field names it.
Eigen::MatrixXd weightAt(const JsonSection& s, const QString& key, Eigen::Index points) {
    if (!s.has(key)) s.fail(key, "missing");
    const Eigen::MatrixXd m = matrixFromJson(s.value(key), s.name() + QLatin1Char('.') + key);
    if (m.rows() != points || m.cols() != points)
        s.fail(key, "must be " + std::to_string(points) + " x " + std::to_string(points) + " (one row per point)");
    return m;
}

void readEwma(const JsonSection& tuning, core::EwmaOptions& e) {
    const JsonSection s(QJsonObject{{QStringLiteral("ewma"), tuning.value(QStringLiteral("ewma"))}},
                        QStringLiteral("ewma"), tuning.name());
    const double inf = std::numeric_limits<double>::infinity();
    e.weight = s.number(QStringLiteral("weight"), e.weight, 1e-9, 1.0);
    e.deadBandMm = s.number(QStringLiteral("dead_band_mm"), e.deadBandMm, 0.0, 1.0);
    e.driftWeight = s.number(QStringLiteral("drift_weight"), e.driftWeight, 0.0, 0.999);
    e.warningMm = s.number(QStringLiteral("warning_mm"), inf, 0.0, 10.0);
    e.alarmMm = s.number(QStringLiteral("alarm_mm"), inf, 0.0, 10.0);
}

void readDisturbances(const JsonSection& tuning, core::RunToRunSetup& setup) {
    const QJsonValue value = tuning.value(QStringLiteral("disturbances"));
    const QString where = tuning.name() + QStringLiteral(".disturbances");
    if (!value.isArray() || value.toArray().size() != static_cast<qsizetype>(setup.plant.points.size()))
        tuning.fail(QStringLiteral("disturbances"), "must be an array with one model per control point (" +
                                                        std::to_string(setup.plant.points.size()) + ")");
    const QJsonArray models = value.toArray();
    for (qsizetype i = 0; i < models.size(); ++i)
        setup.plant.points[static_cast<std::size_t>(i)].disturbance =
            disturbanceFromJson(models.at(i), where + QStringLiteral("[%1]").arg(i));
}

}  // namespace

QJsonObject controllerTuningToJson(const core::RunToRunSetup& setup) {
    QJsonArray disturbances;
    for (const core::ControlPointSpec& p : setup.plant.points) {
        QJsonArray components;
        for (const DisturbanceComponent& c : p.disturbance.components())
            components.append(componentToJson(c));
        disturbances.append(components);
    }
    QJsonObject o{{QStringLiteral("output_weight"), matrixToJson(setup.weights.R1)},
                  {QStringLiteral("correction_weight"), matrixToJson(setup.weights.R2)},
                  {QStringLiteral("gate_sigma"), setup.lqg.gateSigma},
                  {QStringLiteral("history_parts"), setup.lqg.historyParts},
                  {QStringLiteral("ewma"), ewmaToJson(setup.ewma)},
                  {QStringLiteral("ewma_weight_auto"), setup.ewmaWeightAuto},
                  {QStringLiteral("integral"), QJsonObject{{QStringLiteral("enabled"), setup.integral.enabled},
                                                           {QStringLiteral("weight"), setup.integral.weight}}},
                  {QStringLiteral("disturbances"), disturbances}};
    putLimit(o, QStringLiteral("max_correction_mm"), setup.limits.maxAbsMm);
    putLimit(o, QStringLiteral("max_step_mm"), setup.limits.maxStepMm);
    return o;
}

core::RunToRunSetup tunedSetupFromJson(const QJsonObject& json, core::RunToRunSetup base) {
    const JsonSection s = JsonSection::of(json, QStringLiteral("tuning"));
    const auto points = static_cast<Eigen::Index>(base.plant.points.size());
    const double inf = std::numeric_limits<double>::infinity();
    base.weights.R1 = weightAt(s, QStringLiteral("output_weight"), points);
    base.weights.R2 = weightAt(s, QStringLiteral("correction_weight"), points);
    base.limits.maxAbsMm = s.number(QStringLiteral("max_correction_mm"), inf, 1e-9, 10.0);
    base.limits.maxStepMm = s.number(QStringLiteral("max_step_mm"), inf, 1e-9, 10.0);
    base.lqg.gateSigma = s.number(QStringLiteral("gate_sigma"), base.lqg.gateSigma, 1e-3, 1e3);
    base.lqg.historyParts = s.integer(QStringLiteral("history_parts"), base.lqg.historyParts, 1, 4096);
    readEwma(s, base.ewma);
    base.ewmaWeightAuto = s.flag(QStringLiteral("ewma_weight_auto"), base.ewmaWeightAuto);
    const JsonSection integral(json, QStringLiteral("integral"), s.name());
    base.integral.enabled = integral.flag(QStringLiteral("enabled"), base.integral.enabled);
    base.integral.weight = integral.number(QStringLiteral("weight"), base.integral.weight, core::kMinIntegralWeight,
                                           core::kMaxIntegralWeight);
    readDisturbances(s, base);
    return base;
}

}  // namespace tt::config
