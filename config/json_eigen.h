#pragma once

#include <Eigen/Core>
#include <QJsonArray>
#include <QJsonObject>
#include <QString>

namespace tt::config {

/// A matrix as a JSON array of rows (the CLI's convention for matrices).
QJsonArray matrixToJson(const Eigen::MatrixXd& m);
/// A vector as a flat JSON array.
QJsonArray vectorToJson(const Eigen::VectorXd& v);

/// Reads a JSON array of rows; throws std::invalid_argument naming `what` when ragged or not numeric.
Eigen::MatrixXd matrixFromJson(const QJsonValue& value, const QString& what);
/// Reads a flat numeric JSON array; throws std::invalid_argument naming `what`.
Eigen::VectorXd vectorFromJson(const QJsonValue& value, const QString& what);

/// The number at `where` (a field path for messages, "plant.points[2].x_mm"); throws
/// std::invalid_argument "<where>: missing" / "must be a number" / "X is outside min .. max".
double numberAt(const QJsonValue& value, const QString& where, double minValue, double maxValue);
/// Required numeric field `key` of `object`; throws std::invalid_argument naming it when absent,
/// not a number, or outside [minValue, maxValue].
double requireNumber(const QJsonObject& object, const QString& key, double minValue, double maxValue);
/// Optional numeric field with a default; same checks as requireNumber when present.
double optionalNumber(const QJsonObject& object, const QString& key, double fallback, double minValue, double maxValue);

/// `v` as a JSON number, or null when it is NaN or infinite (JSON has no such numbers).
QJsonValue finiteOrNull(double v);

/// A limit in JSON output: null when there is none (+infinity: an absent `max_correction_mm`, unlimited),
/// else the value. A NaN stays a NaN, so the output's check still refuses it as a fault.
QJsonValue limitOrNull(double limit);

}  // namespace tt::config
