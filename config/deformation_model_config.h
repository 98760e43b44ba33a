#pragma once

#include <QJsonObject>
#include <QString>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/model/deformation_model.h"
#include "devices/parsers/gcode_writer.h"

namespace tt::config {

/// One term of a fitted model with its statistics (coded variables, µm).
struct DeformationTermReport {
    std::string name;          ///< "a*f*z^2"
    double coefficient = 0.0;  ///< µm
    double stdError = 0.0;     ///< µm
    double tValue = 0.0;       ///< coefficient / standard error
};

/// What a planner judges a force-deformation model by (R², adjusted R², F against its table value,
/// residual sigma, every term's standard error and t-value).
struct DeformationModelStatistics {
    int pointCount = 0;
    int termCount = 0;
    int residualDof = 0;
    double r2 = 0.0;
    double r2Adjusted = 0.0;
    double fStatistic = 0.0;
    double fCritical95 = 0.0;
    double tCritical95 = 0.0;
    double residualSigmaUm = 0.0;
    std::vector<DeformationTermReport> terms;
    std::vector<std::pair<std::string, double>> removed;  ///< terms removed stepwise, with |t| then
    std::string termSet;                                  ///< "cubic-z", ...
    bool stepwise = false;

    /// Residual 2σ, µm.
    double twoSigmaUm() const { return 2.0 * residualSigmaUm; }
    /// F above its table value: the model is significant at 95 %.
    bool significant() const { return fStatistic > fCritical95; }
};

/// The model file that `fit-deformation` writes and `schedule-feed` and the Feed schedule page read.
struct DeformationModelFile {
    core::DeformationModel model;
    DeformationModelStatistics statistics;
    QString sourceFile;                       ///< the experiment CSV it was fitted from
    QString preset;                           ///< the set-up of the experiments (a preset name or file), may be empty
    std::optional<std::uint64_t> seed;        ///< the simulator seed of the experiments, if simulated
    std::optional<devices::FeedPassJob> job;  ///< spindle, coolant, tool, Z origin of the set-up, if known
};

/// The file of a fresh fit.
DeformationModelFile deformationModelFile(const core::DeformationFit& fit);

/// The model file as JSON:
///   {"kind": "trueturn-deformation-model", "format": 1, "units": {...},
///    "factors": {"a_mm"|"f_mm_rev"|"z_mm": {"centre", "half_range", "min", "max"}},
///    "term_set", "stepwise", "terms": [{"term", "powers": [i, j, k], "coefficient_um", "std_error_um", "t"}],
///    "removed_terms": [{"term", "t"}],
///    "statistics": {"n", "terms", "residual_dof", "r2", "r2_adj", "f", "f_critical", "significant",
///                   "t_critical", "sigma_resid_um", "two_sigma_um"},
///    "source": {"file", "preset", "seed"}, "job": {...}}.
/// Non-finite statistics are written as null.
QJsonObject deformationModelToJson(const DeformationModelFile& file);

/// Reads a model file (inverse of deformationModelToJson). Throws std::invalid_argument naming the
/// field ("terms[3].powers: ...") when it is not such a file or a value is missing or out of range.
DeformationModelFile deformationModelFromJson(const QJsonObject& json);

/// The "job" section: {"finish_diameter_mm", "spindle_rpm", "coolant", "tool", "program_number",
/// "z_origin_mm", "z_direction", "clearance_mm"}.
QJsonObject feedPassJobToJson(const devices::FeedPassJob& job);
/// Reads a "job" section named `where` in messages; absent fields keep FeedPassJob's defaults except
/// finish_diameter_mm and spindle_rpm, which are required. Throws std::invalid_argument naming the field.
devices::FeedPassJob feedPassJobFromJson(const QJsonObject& job, const QString& where);

}  // namespace tt::config
