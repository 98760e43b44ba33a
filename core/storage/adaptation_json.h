#pragma once

#include <QJsonObject>
#include <QString>

#include "core/ports/adaptation_record.h"

namespace tt::storage {

/// A plant model as recorded, in JSON (the history's stored text and the adaptations of `simulate --json`):
/// {delay, lag, gain, gain_std_error, gain_std_error_joint, ar, ma, ar_std_error, ma_std_error, noise_variance, mean,
/// source, criterion, innovation_correlation}, the point values as arrays in point order (null: none).
QJsonObject plantModelJson(const core::PlantModelRecord& model);
/// Back; throws std::invalid_argument on a damaged object.
core::PlantModelRecord plantModelFromJson(const QJsonObject& json);

/// Margins as recorded: {gain, gain_lower, phase_deg, delay_parts, extra_parts} (null where there is none: the
/// loop tolerates any such change).
QJsonObject marginsJson(const core::MarginsRecord& margins);
/// Back.
core::MarginsRecord marginsFromJson(const QJsonObject& json);

/// A model in a line for people (the audit trail): "delay 3 parts (lag 1); point 1: gain 1.93 ± 0.04, AR 0.92,
/// MA 0.25, σ² 1.29e-04 mm²; point 2: ...".
QString modelSummary(const core::PlantModelRecord& model);

/// One adaptation in the form of `simulate --json`'s adaptations: {part, kind, reason, fallback, fallback_weight,
/// model_before, model_after (null: none), margins, applied, message}.
QJsonObject adaptationJson(const core::AdaptationRecord& adaptation);

}  // namespace tt::storage
