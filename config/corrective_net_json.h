#pragma once

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <string>
#include <vector>

#include "core/control/corrective_net.h"
#include "core/control/corrective_net_training.h"
#include "core/sim/feed_drives/corrective_pulse.h"

namespace tt::config {

/// A corrective-pulse network as saved by `trueturn corner train --out NET.json`: the network with its
/// normalisation and training record, the pulse it was trained for, the preset, and the training set
/// (kept for retraining on drift, paper 002).
struct CornerNetFile {
    core::CorrectiveNet net;
    core::PulseSettings pulse;
    std::string preset;
    std::vector<core::NetSample> samples;
};

/// The file as JSON: {"format": "trueturn-corrective-net", "version": 1, "preset", "pulse": {"axis",
/// "lead_s", "duration_s", "limit_v"}, "network": {"inputs", "hidden_activation", "output_activation",
/// "normalisation": {"input_offset", "input_scale", "output_offset_v", "output_scale_v"},
/// "hidden_weights": [[w11 .. w14], ..], "hidden_bias", "output_weights", "output_bias"},
/// "training": {"seed", "training_samples", "validation_samples", "epochs", "best_epoch",
/// "training_rms_v", "validation_rms_v", "stop_reason", "retrainings", "training_loss",
/// "validation_loss"}, "samples": [[vx1, vz1, vx2, vz2, amplitude_v, weight], ..]}. Numbers are written
/// in the shortest form that reads back to the same double, so a file round-trips bit-exactly.
QJsonObject cornerNetToJson(const CornerNetFile& file);

/// Reads cornerNetToJson's output; throws std::invalid_argument naming the field ("network.hidden_bias:
/// must hold 10 numbers") for anything missing, of the wrong type or not finite.
CornerNetFile cornerNetFromJson(const QJsonObject& json);

/// cornerNetToJson as indented UTF-8 text.
QByteArray cornerNetToBytes(const CornerNetFile& file);
/// Parses `bytes` (a JSON object) and reads it; throws std::invalid_argument with the parse error.
CornerNetFile cornerNetFromBytes(const QByteArray& bytes);

}  // namespace tt::config
