#pragma once

#include <QJsonObject>

namespace tt::config {

/// A preset with its base merged in (`based_on`), as JSON Merge Patch (RFC 7396) applies `overrides` to
/// `base`: an object in both is merged key by key, at every depth; an array or a plain value in `overrides`
/// replaces the base's (a list of tolerances or coefficients is one value); `null` in `overrides` removes
/// the key (e.g. `"max_correction_mm": null`: no limit, whatever the base had). Keys only in `base` stay.
QJsonObject mergePreset(const QJsonObject& base, const QJsonObject& overrides);

}  // namespace tt::config
