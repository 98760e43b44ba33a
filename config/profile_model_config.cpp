#include "config/profile_model_config.h"

#include <QJsonArray>
#include <cmath>
#include <stdexcept>
#include <string>

#include "config/json_eigen.h"

namespace tt::config {

namespace {

const QString kSection = QStringLiteral("systematic_model");

std::invalid_argument bad(const QString& field, const std::string& why) {
    return std::invalid_argument(kSection.toStdString() + "." + field.toStdString() + ": " + why);
}

void requireMillimetres(const QJsonObject& section, const QString& key) {
    const QJsonValue unit = section.value(key);
    if (!unit.isUndefined() && unit.toString() != QStringLiteral("mm"))
        throw bad(key, "must be \"mm\" (got " + unit.toVariant().toString().toStdString() + ")");
}

/// The largest systematic diameter error a model may reach along the part, mm: ten times the largest
/// barrel of the 2012 paper's Table 1 would still be under 2 mm; beyond 10 mm the "error" is no
/// longer a deformation of the part, and the loop's corrections would be clipped into a silent no-op.
constexpr double kMaxSystematicErrorMm = 10.0;

/// The model's diameter error within ±kMaxSystematicErrorMm at 201 points along the part.
void requirePlausible(const core::SystematicErrorModel& model) {
    constexpr int kSamples = 200;
    for (int i = 0; i <= kSamples; ++i) {
        const double x = model.partLengthMm() * i / kSamples;
        const double y = model.diameterErrorMm(x);
        if (!std::isfinite(y) || std::abs(y) > kMaxSystematicErrorMm)
            throw bad(QStringLiteral("coefficients"),
                      "the model reaches " + QString::number(y, 'g', 4).toStdString() +
                          " mm at x = " + QString::number(x, 'g', 6).toStdString() + " mm; the limit is ±" +
                          QString::number(kMaxSystematicErrorMm).toStdString() + " mm on diameter");
    }
}

}  // namespace

core::SystematicErrorModel systematicModelFromPreset(const QJsonObject& preset) {
    if (!preset.value(kSection).isObject())
        throw std::invalid_argument("the preset has no \"" + kSection.toStdString() + "\" section");
    const QJsonObject section = preset.value(kSection).toObject();
    requireMillimetres(section, QStringLiteral("x_unit"));
    requireMillimetres(section, QStringLiteral("error_unit"));
    const double length = requireNumber(section, QStringLiteral("part_length_mm"), 1e-3, 1e5);
    const Eigen::VectorXd b =
        vectorFromJson(section.value(QStringLiteral("coefficients")), kSection + QStringLiteral(".coefficients"));
    if (b.size() < 1 || b.size() > core::kMaxRegressionDegree + 1)
        throw bad(QStringLiteral("coefficients"), "expected 1 .. " + std::to_string(core::kMaxRegressionDegree + 1) +
                                                      " numbers b0..bD, got " + std::to_string(b.size()));
    if (!b.allFinite()) throw bad(QStringLiteral("coefficients"), "must be finite numbers");
    core::SystematicErrorModel model(core::ScaledPolynomial::fromPowerCoefficients(b), length);
    requirePlausible(model);
    return model;
}

QJsonObject systematicModelToJson(const core::SystematicErrorModel& model) {
    QJsonObject o;
    o.insert(QStringLiteral("x_unit"), QStringLiteral("mm"));
    o.insert(QStringLiteral("error_unit"), QStringLiteral("mm"));
    o.insert(QStringLiteral("quantity"), QStringLiteral("diameter error"));
    o.insert(QStringLiteral("part_length_mm"), model.partLengthMm());
    o.insert(QStringLiteral("coefficients"), vectorToJson(model.diameterError().powerCoefficients()));
    return o;
}

QJsonObject regressionToJson(const core::PolynomialRegression& fit) {
    QJsonObject o;
    o.insert(QStringLiteral("degree"), fit.degree);
    o.insert(QStringLiteral("coefficients"), vectorToJson(fit.coefficients));
    o.insert(QStringLiteral("coefficient_std_errors"), vectorToJson(fit.coefficientStdErrors));
    o.insert(QStringLiteral("r2"), finiteOrNull(fit.r2));
    o.insert(QStringLiteral("r2_adj"), finiteOrNull(fit.r2Adjusted));
    o.insert(QStringLiteral("f"), finiteOrNull(fit.fStatistic));
    o.insert(QStringLiteral("f_critical"), finiteOrNull(fit.fCritical95));
    o.insert(QStringLiteral("sigma_resid"), finiteOrNull(fit.residualSigma));
    o.insert(QStringLiteral("n"), fit.pointCount);
    o.insert(QStringLiteral("residual_dof"), fit.residualDof);
    o.insert(QStringLiteral("sse"), finiteOrNull(fit.residualSumOfSquares));
    o.insert(QStringLiteral("sst"), finiteOrNull(fit.totalSumOfSquares));
    o.insert(QStringLiteral("press"), finiteOrNull(fit.press));
    return o;
}

}  // namespace tt::config
