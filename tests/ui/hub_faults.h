#pragma once

// Setting one fault switch of a simulated instrument that lives in the device thread, as the Devices page does.
#include <QString>

#include "runtime/devices/device_hub.h"

namespace tt::ui::test {

/// Sets `flag` of the fault switches of `id` to `on` (a simulated instrument; nothing for another device).
inline void setFault(runtime::DeviceHub& hub, const QString& id, bool devices::FaultSwitches::*flag, bool on) {
    hub.sync();
    const runtime::DeviceView* view = hub.view(id);
    if (!view || !view->faults) return;
    devices::FaultSwitches faults = *view->faults;
    faults.*flag = on;
    hub.setFaults(id, faults);
}

}  // namespace tt::ui::test
