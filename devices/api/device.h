#pragma once

#include <QList>
#include <QString>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/ports/correction_output.h"
#include "core/ports/deflection_probe.h"
#include "core/ports/device_health.h"
#include "core/ports/diameter_gauge.h"
#include "core/ports/drive_current.h"
#include "devices/api/device_kind.h"

namespace tt::core {
class Clock;
}

namespace tt::devices {

/// A counter or fact shown on the Devices page ("Frames lost: 3").
struct DeviceStatistic {
    QString label;
    QString value;
};

/// Fault switches of the built-in simulator's devices (what a real instrument can do wrong).
struct FaultSwitches {
    bool silent = false;        ///< sends nothing (cable intact, instrument quiet)
    bool noisy = false;         ///< adds noise of `noiseAmplitude` (in the device's unit: mm, A)
    bool stuck = false;         ///< repeats the last value
    bool malformed = false;     ///< corrupts the frames on the wire (parsers must refuse them)
    bool disconnected = false;  ///< the cable is unplugged: state error until switched off
    double noiseAmplitude = 0.005;
};

/// Status of a linearisation-table upload to the probe mandrel.
struct TableUploadStatus {
    enum class Phase { Idle, Running, Done, Failed };
    Phase phase = Phase::Idle;
    double progress = 0.0;  ///< 0..1
    QString message;        ///< what is happening or why it failed
};

/// The table the probe mandrel reports: version, CRC-16 of its stored image (every protocol) and
/// CRC-32C (probe protocol 2).
struct MandrelTableInfo {
    std::uint16_t version = 0;
    std::uint16_t crc = 0;  ///< CRC-16/CCITT-FALSE of the stored image
    std::uint32_t sizeBytes = 0;
    bool valid = false;
    std::optional<std::uint32_t> crc32c;  ///< CRC-32C of the stored image; protocol 2 only
};

/// What the probe mandrel says about itself (probe protocol 2's DEVICE_INFO); a mandrel of the
/// first protocol says only that it is one.
struct MandrelInfo {
    int protocol = 1;
    std::optional<int> adcBits;       ///< its ADC resolution, when it says
    std::uint32_t maxTableBytes = 0;  ///< largest table image it stores, bytes
};

/// Uploading the linearisation table (ADC code -> deflection, built by core/calibration) into
/// the probe mandrel's microcontroller. The image is opaque to the device: it is chunked,
/// sent, CRC-checked by the mandrel and verified by reading back its version and CRC (CRC-32C on
/// protocol 2, up to 256 KiB; CRC-16 on protocol 1, up to 64 KiB).
class TableUploadTarget {
public:
    virtual ~TableUploadTarget() = default;
    /// Starts the upload (returns at once; follow uploadStatus()). `crc32c` is the CRC-32C of the
    /// whole image as the caller has it on record. Throws std::invalid_argument when the image is
    /// empty, too large for the mandrel or its CRC-32C is not `crc32c`.
    virtual void uploadTable(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) = 0;
    virtual TableUploadStatus uploadStatus() const = 0;
    /// What the mandrel last reported; nullopt before it answered.
    virtual std::optional<MandrelTableInfo> tableInfo() const = 0;
    /// The mandrel's protocol, ADC and capacity; nullopt until the handshake found out.
    virtual std::optional<MandrelInfo> mandrelInfo() const = 0;
};

/// Inputs of the built-in simulator's devices, so a lathe simulator can drive them: the true
/// values the simulated instrument measures. Without a source each device uses its stand-alone
/// default (a constant diameter, a constant deflection, the paper-001 oscillating cross-feed).
class SimulationInputs {
public:
    virtual ~SimulationInputs() = default;
    /// Gauge: the true diameter under the anvils for each reading, mm.
    virtual void setDiameterSource(std::function<double()> source) = 0;
    /// Probe: the true deflection of both bending planes at a time, mm.
    virtual void setDeflectionSource(std::function<std::array<double, 2>(double timeS)> source) = 0;
    /// Drive: current, velocity and position at a time (timeS of the result is ignored).
    virtual void setDriveSource(std::function<core::DriveSample(double timeS)> source) = 0;
    /// Correction output: called with every correction the simulated CNC accepts.
    virtual void setCorrectionSink(std::function<void(const core::PartCorrection&)> sink) = 0;
    /// Correction output: called with every dynamic X offset the simulated PLC applies, mm.
    virtual void setOffsetSink(std::function<void(double)> sink) = 0;
};

/// One device instance created by a plugin's factory: open/close, state, live value, and the
/// engine port it implements. All I/O is asynchronous in the thread's event loop; nothing here
/// blocks. Created with validated settings; changing settings means creating a new instance.
/// Not thread-safe: use an instance (and its ports) only from the thread that created it, whose
/// event loop runs its serial port, Modbus client and timers.
class Device {
public:
    virtual ~Device() = default;

    virtual DeviceKind kind() const = 0;
    /// Starts connecting (state Connecting, then Ready or Error). Calling it again reconnects.
    virtual void open() = 0;
    /// Closes the connection (state Disconnected) and stops reconnect attempts.
    virtual void close() = 0;
    /// Opens if needed and makes the device prove it answers: a polled gauge is asked for a
    /// reading, a probe for its table, a Modbus readout is read once. Watch health()/liveValue().
    virtual void testConnection() = 0;
    /// Connection state and message in the user's terms.
    virtual core::DeviceHealth health() const = 0;
    /// The latest value for display ("26.812 mm"); peeking, it consumes nothing from the port.
    virtual QString liveValue() const = 0;
    /// The last problem seen (refused reading, corrupt frame, Modbus exception), kept after the
    /// device recovers so the operator can see what happened; empty if none.
    virtual QString lastError() const = 0;
    /// Counters for the Devices page (frames, lost, corrupt, ...).
    virtual QList<DeviceStatistic> statistics() const { return {}; }

    /// The engine ports; the one matching kind() is non-null.
    virtual core::DiameterGauge* diameterGauge() { return nullptr; }
    virtual core::DeflectionProbe* deflectionProbe() { return nullptr; }
    virtual core::DriveCurrentReadout* driveCurrentReadout() { return nullptr; }
    virtual core::CorrectionOutput* correctionOutput() { return nullptr; }
    /// Table upload, for probe mandrels that support it.
    virtual TableUploadTarget* tableUploadTarget() { return nullptr; }

    /// Called (in the device's thread) whenever state, live value or last error change.
    void setChangeListener(std::function<void()> listener) { m_listener = std::move(listener); }

protected:
    void notifyChanged() const {
        if (m_listener) m_listener();
    }

private:
    std::function<void()> m_listener;
};

/// What the host gives every instance: the clock that stamps samples.
struct DeviceContext {
    const core::Clock* clock = nullptr;  ///< never null; outlives the device
};

}  // namespace tt::devices
