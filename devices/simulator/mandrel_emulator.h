#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "devices/parsers/probe_protocol.h"

namespace tt::devices {

/// The probe mandrel's microcontroller, emulated byte for byte (docs/protocols/probe-mandrel.md):
/// answers commands, streams samples at the set rate, and stores uploaded linearisation tables,
/// answering with their version and CRC. Used by the simulator's probe and, over a
/// pseudo-terminal, by the tests of the probe-mandrel plugin. Pure C++, no I/O.
///
/// The sensor model (paper 001): the differential inductive bridge of core::InductiveProbe with
/// a static characteristic symmetric about the middle, bridge ratio r(u) = 1.15 u − 0.15 u³ of the
/// normalised gap u (monotonic over the whole ADC range: r' = 1.15 − 0.45 u² ≥ 0.70 for |u| ≤ 1,
/// the turning points at u = ±1.63 lie beyond the ADC's limits), coils at 0.9 of the overhang,
/// 0.25 mm gap at full scale (±0.294 mm at the tool tip), ratiometric 16-bit ADC, codes clamped
/// to 0..65535 and over-range flagged. With a valid table stored, the linearised deflection
/// reported is the model's true deflection (the emulator does not interpret the image, whose
/// format belongs to core/calibration); without one the deflection is 0 and the table-valid bit
/// is clear. Speaks probe protocol 2 (DEVICE_INFO, uploads up to 256 KiB with CRC-32C) or, for
/// tests of older firmware, protocol 1.
class MandrelEmulator {
public:
    static constexpr int kAdcBits = 16;
    static constexpr std::int32_t kMaxCode = 65535;
    static constexpr double kFullScaleGapMm = 0.25;         ///< gap change at u = ±1
    static constexpr double kSensorPositionFraction = 0.9;  ///< coils along the overhang (0 clamp .. 1 tip)
    static constexpr double kLinearTerm = 1.15;             ///< c1 of r(u)
    static constexpr double kCubicTerm = -0.15;             ///< c3 of r(u)

    /// `protocol` 2 (default) or 1 (firmware of the first protocol: no DEVICE_INFO, uploads up to
    /// 64 KiB with CRC-16). Throws std::invalid_argument otherwise.
    explicit MandrelEmulator(int protocol = probe::kProtocolVersion);

    /// True deflection of both planes at a time, mm (default: 0.020 mm and -0.005 mm).
    void setDeflectionSource(std::function<std::array<double, 2>(double timeS)> source);
    /// Host bytes in; the replies (ACK, TABLE_INFO) out.
    std::vector<std::uint8_t> receive(std::span<const std::uint8_t> bytes);
    /// Advances the emulator's clock by `dtS` seconds; returns the sample frames due.
    std::vector<std::uint8_t> advance(double dtS);

    /// ADC code of a tool tip deflection, mm (the bridge model above), rounded, clamped to 0..65535.
    static std::int32_t adcCode(double deflectionMm);
    /// The same without rounding (what a calibration against a perfect reference sees).
    static double exactCode(double deflectionMm);
    /// Tool tip deflection at which the ADC reaches its limits, mm.
    static double fullScaleDeflectionMm();
    /// The table a mandrel is delivered with: the bridge above calibrated against a perfect
    /// reference at 41 points over ±90 % of full scale, fitted with degree 3 (core/calibration)
    /// and encoded as a format-2 image of 2^16 entries, version 1 (131 104 bytes).
    static const std::vector<std::uint8_t>& deliveryTableImage();

    // Faults, for tests and the simulator.
    void corruptNextFrames(int count) { m_corrupt += count; }      ///< flip a bit in their payload
    void dropNextFrames(int count) { m_drop += count; }            ///< skip them (sequence gap)
    void duplicateNextFrames(int count) { m_duplicate += count; }  ///< send them twice
    void setSilent(bool silent) { m_silent = silent; }             ///< send nothing at all
    void setFaultyFlash(bool faulty) { m_faultyFlash = faulty; }   ///< store tables with one byte wrong
    void setNoise(double amplitudeMm) { m_noiseMm = amplitudeMm; }
    void setStuck(bool stuck) { m_stuck = stuck; }  ///< repeat the last sample's values

    /// Stores a table as if uploaded earlier (power-up state).
    void preloadTable(std::vector<std::uint8_t> image, std::uint16_t version);

    int protocol() const { return m_protocol; }
    bool streaming() const { return m_streaming; }
    int rateHz() const { return m_rateHz; }
    probe::TableInfoPayload tableInfo() const;
    const std::vector<std::uint8_t>& tableImage() const { return m_table; }
    std::uint64_t commandsHandled() const { return m_commands; }
    std::uint64_t framesSent() const { return m_framesSent; }

private:
    std::vector<std::uint8_t> handle(const probe::Frame& frame);
    std::vector<std::uint8_t> send(probe::MessageType type, const std::vector<std::uint8_t>& payload);
    std::vector<std::uint8_t> ack(std::uint8_t command, probe::AckResult result, std::uint32_t detail = 0);
    probe::SamplePayload makeSample(double timeS);

    std::function<std::array<double, 2>(double)> m_source;
    probe::FrameReader m_reader;
    std::uint8_t m_sequence = 0;
    double m_timeS = 0.0;
    double m_nextSampleS = 0.0;
    bool m_streaming = false;
    int m_rateHz = 100;
    std::vector<std::uint8_t> handleBegin(std::uint8_t command, std::uint16_t version, std::uint32_t sizeBytes,
                                          std::size_t maxBytes);
    std::vector<std::uint8_t> handleChunk(const probe::Frame& frame);
    std::vector<std::uint8_t> handleCommit(std::uint8_t command);
    void store(std::vector<std::uint8_t> image, std::uint16_t version);

    int m_protocol;
    std::vector<std::uint8_t> m_table;
    std::uint16_t m_tableVersion = 0;
    std::uint16_t m_tableCrc = 0;
    std::uint32_t m_tableCrc32 = 0;
    bool m_tableValid = false;
    bool m_uploading = false;
    std::uint16_t m_uploadVersion = 0;
    std::uint32_t m_uploadSize = 0;
    std::optional<std::uint16_t> m_uploadCrc16;  ///< announced by TABLE_BEGIN
    std::optional<std::uint32_t> m_uploadCrc32;  ///< announced by TABLE_BEGIN_32
    std::vector<std::uint8_t> m_pending;
    int m_corrupt = 0;
    int m_drop = 0;
    int m_duplicate = 0;
    bool m_silent = false;
    bool m_faultyFlash = false;
    bool m_stuck = false;
    double m_noiseMm = 0.0;
    std::uint32_t m_noiseState = 12345;
    probe::SamplePayload m_last;
    bool m_haveLast = false;
    std::uint64_t m_commands = 0;
    std::uint64_t m_framesSent = 0;
};

}  // namespace tt::devices
