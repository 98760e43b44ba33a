#pragma once

#include <QJsonObject>

#include "core/model/polynomial_regression.h"
#include "core/model/systematic_error_model.h"

namespace tt::config {

/// Reads the "systematic_model" section of a preset (resources/presets/paper-2012-table1-group*.json):
/// {"x_unit": "mm", "error_unit": "mm", "part_length_mm": L, "coefficients": [b0, ..., bD]}, the
/// diameter error d(x) in mm with x in mm (paper 000, Table 1). Throws std::invalid_argument naming
/// the field when the section is missing, a unit is not "mm", the length is not positive, or there
/// are not 1..7 finite coefficients.
core::SystematicErrorModel systematicModelFromPreset(const QJsonObject& preset);

/// The "systematic_model" section for a model (inverse of systematicModelFromPreset).
QJsonObject systematicModelToJson(const core::SystematicErrorModel& model);

/// The regression result as the `fit-profile --json` fields: degree, coefficients [b0..bD], r2,
/// r2_adj, f, f_critical, sigma_resid, n, plus coefficient_std_errors, residual_dof, sse, sst and
/// press. Non-finite values (F of an exact fit) are written as null.
QJsonObject regressionToJson(const core::PolynomialRegression& fit);

}  // namespace tt::config
