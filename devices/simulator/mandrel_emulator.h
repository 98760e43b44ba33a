#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "devices/parsers/probe_protocol.h"

namespace tt::devices {

/// The probe mandrel's microcontroller, emulated byte for byte (docs/protocols/probe-mandrel.md):
/// answers commands, streams samples at the set rate, and stores uploaded linearisation tables,
/// answering with their version and CRC. Used by the simulator's probe and, over a
/// pseudo-terminal, by the tests of the probe-mandrel plugin. Pure C++, no I/O.
///
/// The sensor model (paper 001): a differential inductive bridge whose static transfer function
/// is nonlinear but symmetric about the middle, code = mid + k1 d + k3 d^3 (16-bit ADC, clamped,
/// over-range flagged). With a valid table stored, the linearised deflection reported is the
/// model's true deflection (the emulator does not interpret the image, whose format belongs to
/// core/calibration); without one the deflection is 0 and the table-valid bit is clear.
class MandrelEmulator {
public:
    static constexpr double kCountsPerMm = 200000.0;      ///< k1: ADC counts per mm of deflection
    static constexpr double kCubicCountsPerMm3 = -5.0e6;  ///< k3: nonlinearity, counts per mm^3
    static constexpr std::int32_t kMidCode = 32768;       ///< code at zero deflection
    static constexpr std::int32_t kMaxCode = 65535;

    MandrelEmulator();

    /// True deflection of both planes at a time, mm (default: 0.020 mm and -0.005 mm).
    void setDeflectionSource(std::function<std::array<double, 2>(double timeS)> source);
    /// Host bytes in; the replies (ACK, TABLE_INFO) out.
    std::vector<std::uint8_t> receive(std::span<const std::uint8_t> bytes);
    /// Advances the emulator's clock by `dtS` seconds; returns the sample frames due.
    std::vector<std::uint8_t> advance(double dtS);

    /// ADC code of a deflection (the bridge model above), clamped to 0..65535.
    static std::int32_t adcCode(double deflectionMm);

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
    std::vector<std::uint8_t> m_table;
    std::uint16_t m_tableVersion = 0;
    std::uint16_t m_tableCrc = 0;
    bool m_tableValid = false;
    bool m_uploading = false;
    probe::TableBeginPayload m_upload;
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
