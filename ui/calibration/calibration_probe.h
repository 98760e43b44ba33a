#pragma once

#include <QString>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/ports/deflection_probe.h"

namespace tt::ui {

/// Progress of a table upload, as the wizard shows it.
struct ProbeUploadStatus {
    enum class Phase { Idle, Running, Done, Failed };
    Phase phase = Phase::Idle;
    double progress = 0.0;  ///< 0..1
    QString message;
};

/// What the mandrel reports about the table it holds (version and CRC-16 of the stored image).
struct ProbeTableReadback {
    std::uint16_t version = 0;
    std::uint16_t crc = 0;
    std::uint32_t sizeBytes = 0;
    bool valid = false;
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
    /// Starts uploading `image` (opaque bytes) as table `version`; `crc` = CRC-16/CCITT-FALSE of the
    /// whole image. Throws std::invalid_argument with the reason (too large, CRC wrong, busy).
    virtual void startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint16_t crc) = 0;
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
