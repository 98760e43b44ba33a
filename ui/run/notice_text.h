#pragma once

#include <QString>

#include "core/common/notice.h"

namespace tt::ui {

/// A notice of the engine (the loop's state, an alarm, why a measured value is not used) in the
/// operator's language (translation context "Notice"); the words of a device in `cause` come as the
/// device gave them.
QString noticeText(const core::Notice& notice);

/// An alarm as the Run page lists it: a rejected measurement with its part and point first.
QString alarmText(const core::Notice& notice);

/// The controller in use after an adaptation notice of the adaptive loop ("Controller: robust EWMA fallback
/// (weight 0.49) from part 13, while the plant is identified"); empty for any other notice.
QString controllerInUseText(const core::Notice& notice);
/// True while such a notice leaves the loop on its fallback (amber on the Run page).
bool controllerInUseIsFallback(const core::Notice& notice);

}  // namespace tt::ui
