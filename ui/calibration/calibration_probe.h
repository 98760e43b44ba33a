#pragma once

#include <QString>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/calibration/linearisation_image.h"
#include "core/ports/deflection_probe.h"

namespace tt::ui {

/// Progress of a table upload, as the wizard shows it.
struct ProbeUploadStatus {
    enum class Phase { Idle, Running, Done, Failed };
    Phase phase = Phase::Idle;
    double progress = 0.0;  ///< 0..1
    QString message;
};

/// What the mandrel reports about the table it holds: version, CRC-16 of the stored image, and
/// its CRC-32C when the mandrel speaks probe protocol 2.
struct ProbeTableReadback {
    std::uint16_t version = 0;
    std::uint16_t crc16 = 0;
    std::optional<std::uint32_t> crc32c;
    std::uint32_t sizeBytes = 0;
    bool valid = false;

    /// The CRC the upload is verified with: the CRC-32C, or the CRC-16 of a protocol-1 mandrel.
    std::uint32_t crc() const { return crc32c ? *crc32c : crc16; }
    /// "CRC-32C 0x1A2B3C4D" or "CRC-16 0x1A2B".
    QString crcText() const;
    /// True when the mandrel holds `image` as table `version`, valid, with the same size and CRC.
    bool matches(int version, std::span<const std::uint8_t> image) const;
};

/// A probe mandrel as the calibration wizard sees it: live samples through the engine's port
/// (core::DeflectionProbe), its ADC resolution when known, and the upload of a table image with
/// the read-back of what the mandrel stored. Implemented by the built-in simulated mandrel and,
/// for configured devices, by an adapter over the device plugin API.
class CalibrationProbe {
public:
    virtual ~CalibrationProbe() = default;
    virtual QString name() const = 0;
    /// ADC resolution, bits, when the probe knows it (otherwise the wizard asks).
    virtual std::optional<int> adcBits() const = 0;
    /// The live samples (raw ADC code per plane).
    virtual core::DeflectionProbe& port() = 0;

    virtual bool canUpload() const = 0;
    /// Starts uploading `image` (opaque bytes) as table `version`; `crc32c` = CRC-32C of the whole
    /// image (the record's upload CRC). Throws std::invalid_argument with the reason (too large
    /// for the mandrel, CRC wrong, busy).
    virtual void startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) = 0;
    /// The table image format the mandrel's firmware reads (docs/protocols/linearisation-table.md):
    /// 2, or 1 for a mandrel of probe protocol 1.
    virtual std::uint8_t imageFormat() const { return core::kTableImageFormat; }
    virtual ProbeUploadStatus uploadStatus() const = 0;
    /// Asks the mandrel again which table it holds; the answer arrives in readback().
    virtual void requestReadback() = 0;
    /// What the mandrel last reported; nullopt before it answered.
    virtual std::optional<ProbeTableReadback> readback() const = 0;

    /// Lets the probe work for `seconds`: the simulator advances its clock; a device runs in
    /// the event loop and ignores it.
    virtual void poll(double seconds) { (void)seconds; }

    /// The simulator's screw jack that bends the bar for calibration; false on a machine, where
    /// the operator loads the bar and reads the dial indicator.
    virtual bool hasJack() const { return false; }
    /// Bends the bar to a tip deflection in a plane, mm (simulator only).
    virtual void setJackDeflectionMm(int plane, double deflectionMm) {
        (void)plane;
        (void)deflectionMm;
    }
};

}  // namespace tt::ui
