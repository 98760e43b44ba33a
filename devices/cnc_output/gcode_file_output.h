#pragma once

#include <QString>
#include <QVariantMap>

#include "devices/api/device_base.h"
#include "devices/parsers/gcode_writer.h"

namespace tt::devices {

/// The corrected cutting path of the next part as a G-code file (lathe, G21 metric, diameter or
/// radius mode stated in the header, one G1 segment per path point with its correction; see
/// writeCorrectionGCode) written atomically into a folder the CNC reads (network share, DNC).
/// Settings: folder, fileName (with {part}), and the GCodeJob fields (nominalDiameterMm,
/// feedMmPerRev, spindleRpm, xMode, emitModeCode, zOriginMm, zDirection, clearanceMm,
/// toolNumber, programNumber, maxCorrectionMm).
class GCodeFileOutput final : public DeviceBase, public core::CorrectionOutput {
public:
    GCodeFileOutput(const QVariantMap& settings, const DeviceContext& context);

    void open() override;
    void close() override;
    void testConnection() override { open(); }
    core::DeviceHealth health() const override { return DeviceBase::health(); }
    /// Writes the file; ok when it is on disk (message: the reason otherwise).
    core::OutputResult sendPartCorrection(const core::PartCorrection& correction) override;
    /// Not possible with a file: refused with the reason.
    core::OutputResult sendDynamicOffset(double xOffsetMm) override;
    core::CorrectionOutput* correctionOutput() override { return this; }
    QList<DeviceStatistic> statistics() const override;

    /// Path of the last file written; empty before the first.
    QString lastFile() const { return m_lastFile; }

private:
    core::OutputResult refuse(const QString& message);

    QString m_folder;
    QString m_fileName;
    GCodeJob m_job;
    QString m_lastFile;
    std::uint64_t m_written = 0;
    std::uint64_t m_refused = 0;
};

}  // namespace tt::devices
