#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "core/ports/boring_station.h"
#include "core/ports/clock.h"
#include "core/ports/correction_output.h"
#include "core/ports/deflection_probe.h"
#include "core/ports/drive_current.h"

namespace tt::core {

/// Samples of a device that lives in another thread (the GUI's, whose event loop runs it), for the
/// thread that runs the compensation. The device's side delivers the samples in order, stamped by
/// the device with the clock both sides share, and publishes the device's health; the
/// compensation's side takes them and sees that health, so a device that goes silent or is
/// unplugged holds the offset exactly as a device in the compensation's own thread would. At most
/// `maxQueued` samples wait; beyond that the oldest is dropped and counted. Thread-safe; no call
/// waits for more than a short lock.
template <class Sample>
class SampleRelay {
public:
    /// Throws std::invalid_argument for `maxQueued` 0.
    explicit SampleRelay(std::size_t maxQueued);

    // ---- the compensation's side ----
    /// The device's health as last published (Connecting, no message, before the first).
    DeviceHealth health() const;
    /// The oldest delivered sample not yet taken.
    std::optional<Sample> take();

    // ---- the device's side ----
    void publishHealth(DeviceHealth health);
    void deliver(const Sample& sample);
    /// Samples waiting for the compensation.
    std::size_t pending() const;
    /// Samples dropped because the compensation did not take them in time.
    std::uint64_t dropped() const;

private:
    const std::size_t m_maxQueued;
    mutable std::mutex m_mutex;
    DeviceHealth m_health{DeviceState::Connecting, {}};
    std::deque<Sample> m_samples;
    std::uint64_t m_dropped = 0;
};

/// The cross-feed drive read-out of a device in another thread (see SampleRelay).
class DriveRelay final : public DriveCurrentReadout, public SampleRelay<DriveSample> {
public:
    explicit DriveRelay(std::size_t maxQueued = 4096) : SampleRelay(maxQueued) {}
    DeviceHealth health() const override { return SampleRelay::health(); }
    std::optional<DriveSample> takeSample() override { return take(); }
};

/// The probe mandrel of a device in another thread (see SampleRelay).
class ProbeRelay final : public DeflectionProbe, public SampleRelay<ProbeSample> {
public:
    explicit ProbeRelay(std::size_t maxQueued = 4096) : SampleRelay(maxQueued) {}
    DeviceHealth health() const override { return SampleRelay::health(); }
    std::optional<ProbeSample> takeSample() override { return take(); }
};

/// The CNC output's dynamic X offset on a device in another thread, for the compensation's thread,
/// which never waits for it: a write hands the offset over (a newer one replaces one not yet taken)
/// and returns at once. The device's side takes the offset, writes it and replies with the
/// output's result: the offset the CNC confirmed is kept, a refusal is returned by the next write
/// (so the compensation holds and continues from the confirmed offset). An offset that the
/// device's side has not taken for longer than `maxWaitS` (its thread is busy) makes the output
/// not ready (Connecting, no message), so the compensation holds instead of running ahead of the
/// CNC by more than that. Thread-safe.
class OffsetRelay final : public CorrectionOutput {
public:
    /// `clock` is the compensation's (thread-safe, outlives the relay). Throws
    /// std::invalid_argument for `maxWaitS` not above 0.
    OffsetRelay(const Clock& clock, double maxWaitS);
    ~OffsetRelay() override;

    // ---- the compensation's side ----
    /// Disconnected once closed; Connecting while an offset waits too long; else the device's
    /// health as last published (Connecting, no message, before the first).
    DeviceHealth health() const override;
    /// Refused: the relay carries dynamic offsets only.
    OutputResult sendPartCorrection(const PartCorrection& correction) override;
    /// Hands the offset over and returns at once; refused when closed (no message) or when the
    /// device refused the previous offset (its message).
    OutputResult sendDynamicOffset(double xOffsetMm) override;
    /// The offset the device's side last wrote successfully, mm; nullopt before the first.
    std::optional<double> confirmedOffsetMm() const;

    // ---- the device's side ----
    void publishHealth(DeviceHealth health);
    /// Called with the relay's lock held whenever an offset is handed over (from the compensation's
    /// thread): it must only post a notification, never call back into the relay.
    void setRequestListener(std::function<void()> listener);
    /// The offset waiting to be written, if any (taken: the device's side must reply()).
    std::optional<double> takePending();
    /// The output's result for offset `xOffsetMm`.
    void reply(double xOffsetMm, const OutputResult& result);
    /// The run is over: every later write is refused and the listener dropped (after close()
    /// returns it is never called again).
    void close();
    bool closed() const;

private:
    const Clock& m_clock;
    const double m_maxWaitS;
    mutable std::mutex m_mutex;
    DeviceHealth m_health{DeviceState::Connecting, {}};
    std::optional<double> m_pending;
    std::optional<double> m_pendingSinceS;  ///< when the device's side was last given an offset it has not taken
    std::optional<double> m_confirmed;
    std::optional<std::string> m_refusal;
    bool m_closed = false;
    std::function<void()> m_listener;
};

/// A boring station whose devices (the drive read-out or the probe mandrel, and the CNC output)
/// live in another thread, seen by the compensation's thread through relays. The clock must be
/// the one the devices stamp their samples with, and thread-safe.
class RelayedBoringStation final : public BoringStation {
public:
    /// `withDrive` / `withProbe`: which source relays exist; `maxOffsetWaitS` as OffsetRelay.
    RelayedBoringStation(const Clock& clock, bool withDrive, bool withProbe, double maxOffsetWaitS);
    ~RelayedBoringStation() override;

    DriveCurrentReadout* driveReadout() override { return m_drive.get(); }
    DeflectionProbe* probe() override { return m_probe.get(); }
    CorrectionOutput& output() override { return m_output; }
    const Clock& clock() const override { return m_clock; }
    std::optional<double> confirmedOffsetMm() const override { return m_output.confirmedOffsetMm(); }

    // ---- the devices' side ----
    DriveRelay* driveRelay() { return m_drive.get(); }
    ProbeRelay* probeRelay() { return m_probe.get(); }
    OffsetRelay& outputRelay() { return m_output; }

private:
    const Clock& m_clock;
    std::unique_ptr<DriveRelay> m_drive;
    std::unique_ptr<ProbeRelay> m_probe;
    OffsetRelay m_output;
};

}  // namespace tt::core
