#include "config/json_eigen.h"

#include <cstdio>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace tt::config {

namespace {

std::invalid_argument bad(const QString& what, const std::string& why) {
    return std::invalid_argument(what.toStdString() + ": " + why);
}

/// Shortest readable form: "0.5", "86400", "1e+300", "1e-300" (%.15g; std::to_string's %f printed 1e300
/// as 301 digits and 1e-300 as 0).
std::string formatNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", v);
    return text;
}

}  // namespace

QJsonArray matrixToJson(const Eigen::MatrixXd& m) {
    QJsonArray rows;
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
        QJsonArray row;
        for (Eigen::Index c = 0; c < m.cols(); ++c)
            row.append(m(r, c));
        rows.append(row);
    }
    return rows;
}

QJsonArray vectorToJson(const Eigen::VectorXd& v) {
    QJsonArray out;
    for (Eigen::Index i = 0; i < v.size(); ++i)
        out.append(v(i));
    return out;
}

Eigen::MatrixXd matrixFromJson(const QJsonValue& value, const QString& what) {
    if (!value.isArray()) throw bad(what, "expected an array of rows");
    const QJsonArray rows = value.toArray();
    if (rows.isEmpty()) return Eigen::MatrixXd(0, 0);
    const qsizetype cols = rows.first().toArray().size();
    Eigen::MatrixXd m(rows.size(), cols);
    for (qsizetype r = 0; r < rows.size(); ++r) {
        const QJsonArray row = rows.at(r).toArray();
        if (!rows.at(r).isArray() || row.size() != cols)
            throw bad(what, "row " + std::to_string(r + 1) + " must have " + std::to_string(cols) + " numbers");
        for (qsizetype c = 0; c < cols; ++c) {
            if (!row.at(c).isDouble())
                throw bad(what, "entry (" + std::to_string(r + 1) + "," + std::to_string(c + 1) + ") is not a number");
            m(r, c) = row.at(c).toDouble();
        }
    }
    return m;
}

Eigen::VectorXd vectorFromJson(const QJsonValue& value, const QString& what) {
    if (!value.isArray()) throw bad(what, "expected an array of numbers");
    const QJsonArray items = value.toArray();
    Eigen::VectorXd v(items.size());
    for (qsizetype i = 0; i < items.size(); ++i) {
        if (!items.at(i).isDouble()) throw bad(what, "entry " + std::to_string(i + 1) + " is not a number");
        v(i) = items.at(i).toDouble();
    }
    return v;
}

double numberAt(const QJsonValue& value, const QString& where, double minValue, double maxValue) {
    if (value.isUndefined()) throw bad(where, "missing");
    if (!value.isDouble() || !std::isfinite(value.toDouble())) throw bad(where, "must be a number");
    const double v = value.toDouble();
    if (v < minValue || v > maxValue)
        throw bad(where, formatNumber(v) + " is outside " + formatNumber(minValue) + " .. " + formatNumber(maxValue));
    return v;
}

double requireNumber(const QJsonObject& object, const QString& key, double minValue, double maxValue) {
    return numberAt(object.value(key), key, minValue, maxValue);
}

double optionalNumber(const QJsonObject& object, const QString& key, double fallback, double minValue,
                      double maxValue) {
    return object.contains(key) ? requireNumber(object, key, minValue, maxValue) : fallback;
}

QJsonValue finiteOrNull(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue(QJsonValue::Null);
}

QJsonValue limitOrNull(double limit) {
    return limit == std::numeric_limits<double>::infinity() ? QJsonValue(QJsonValue::Null) : QJsonValue(limit);
}

}  // namespace tt::config
