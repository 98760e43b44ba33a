#include "devices/api/device_log.h"

Q_LOGGING_CATEGORY(lcDevices, "trueturn.devices", QtWarningMsg)
Q_LOGGING_CATEGORY(lcDeviceTraffic, "trueturn.devices.traffic", QtWarningMsg)
