#pragma once

#include <QList>
#include <optional>

#include "devices/api/device.h"
#include "devices/parsers/probe_session.h"

namespace tt::devices {

/// The device-API view of a probe session's upload state.
TableUploadStatus toUploadStatus(const probe::ProbeSession::UploadState& state);
/// The device-API view of the table the mandrel reported.
std::optional<MandrelTableInfo> toTableInfo(const std::optional<probe::TableInfoPayload>& info);
/// The device-API view of what the session knows about the mandrel.
std::optional<MandrelInfo> toMandrelInfo(const probe::ProbeSession& session);
/// The Devices page counters of a probe session (frames, lost, duplicated, corrupt, ...).
QList<DeviceStatistic> probeStatistics(const probe::ProbeSession& session, std::uint64_t queueOverflow);

}  // namespace tt::devices
