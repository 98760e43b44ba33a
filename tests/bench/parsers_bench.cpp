// Hot byte parsers of the devices (devices/parsers, Qt-free): a micrometer's ASCII line, a
// Digimatic frame, probe-mandrel frames (one sample frame and a 4 KiB stream of them) and Modbus
// register values. Every input is valid, so the figures are the cost of the normal path.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "devices/parsers/digimatic.h"
#include "devices/parsers/gauge_ascii.h"
#include "devices/parsers/gauge_decoder.h"
#include "devices/parsers/modbus_registers.h"
#include "devices/parsers/probe_protocol.h"

namespace {

using namespace tt::devices;

// One line of a Mitutoyo-format data cable, without its CR: 26.812 mm.
void BM_GaugeAsciiLine(benchmark::State& state) {
    const std::string line = "01A+00026.812";
    for (auto _ : state) {
        auto frame = parseAsciiGaugeLine(line);
        benchmark::DoNotOptimize(frame);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GaugeAsciiLine);

// The same line with its CR through the gauge's decoder (line framing, parse, unit check, mm).
void BM_GaugeDecoderAsciiLine(benchmark::State& state) {
    GaugeDecoder decoder(GaugeFormat::Ascii, LengthUnit::Millimetre, LengthUnit::Millimetre);
    const std::string text = formatAsciiGaugeLine(26.812, 3);
    const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    for (auto _ : state) {
        auto readings = decoder.feed(bytes);
        benchmark::DoNotOptimize(readings);
    }
    if (decoder.accepted() != static_cast<std::uint64_t>(state.iterations())) state.SkipWithError("line refused");
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GaugeDecoderAsciiLine);

// One 13-nibble Digimatic frame: F F F F 0 2 1 0 7 6 5 4 0 = +21.0765 mm.
void BM_DigimaticFrame(benchmark::State& state) {
    const DigimaticNibbles frame = encodeDigimatic(21.0765, 4, LengthUnit::Millimetre);
    for (auto _ : state) {
        auto reading = decodeDigimatic(frame);
        benchmark::DoNotOptimize(reading);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_DigimaticFrame);

// A probe SAMPLE frame (4 + 22 + 2 bytes) with sequence number `sequence`.
std::vector<std::uint8_t> sampleFrame(std::uint8_t sequence) {
    probe::SamplePayload s;
    s.timeUs = 1000u * sequence;
    s.adcCode = {32768 + sequence, 30000};
    s.deflectionNm = {12345, -678};
    s.status = probe::kStatusTableValid | probe::kStatusStreaming;
    return probe::encodeFrame(sequence, probe::MessageType::Sample, probe::encodeSample(s));
}

// One sample frame through the frame reader (SYNC, length, CRC-16, sequence) and its payload
// decoded. The 256 frames cycle through every sequence number, as a streaming mandrel sends them.
void BM_ProbeSampleFrame(benchmark::State& state) {
    std::array<std::vector<std::uint8_t>, 256> frames;
    for (std::size_t i = 0; i < frames.size(); ++i)
        frames[i] = sampleFrame(static_cast<std::uint8_t>(i));
    probe::FrameReader reader;
    std::size_t next = 0;
    for (auto _ : state) {
        const std::vector<probe::Frame> got = reader.feed(frames[next]);
        auto sample = probe::decodeSample(got.front().payload);
        benchmark::DoNotOptimize(sample);
        next = (next + 1) % frames.size();
    }
    if (reader.stats().frames != static_cast<std::uint64_t>(state.iterations()) || reader.stats().lost != 0)
        state.SkipWithError("frames were refused or lost");
    state.SetItemsProcessed(state.iterations());
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(frames[0].size()));
}
BENCHMARK(BM_ProbeSampleFrame);

// A 4 KiB read from the serial port: 146 consecutive sample frames (4088 bytes), every one
// decoded. 256 such reads cycle so that the sequence numbers run on without a gap.
void BM_ProbeStream4KiB(benchmark::State& state) {
    constexpr std::size_t kFramesPerRead = 4096 / (probe::kHeaderBytes + probe::kSamplePayloadBytes + probe::kCrcBytes);
    std::vector<std::vector<std::uint8_t>> reads(256);
    std::size_t sequence = 0;
    for (auto& read : reads)
        for (std::size_t f = 0; f < kFramesPerRead; ++f) {
            const std::vector<std::uint8_t> frame = sampleFrame(static_cast<std::uint8_t>(sequence++ % 256));
            read.insert(read.end(), frame.begin(), frame.end());
        }
    probe::FrameReader reader;
    std::size_t next = 0;
    std::int64_t decoded = 0;
    for (auto _ : state) {
        for (const probe::Frame& frame : reader.feed(reads[next])) {
            auto sample = probe::decodeSample(frame.payload);
            benchmark::DoNotOptimize(sample);
            ++decoded;
        }
        next = (next + 1) % reads.size();
    }
    if (decoded != state.iterations() * static_cast<std::int64_t>(kFramesPerRead) || reader.stats().lost != 0)
        state.SkipWithError("frames were refused or lost");
    state.SetItemsProcessed(decoded);
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(reads[0].size()));
}
BENCHMARK(BM_ProbeStream4KiB);

// One engineering value from drive registers: int16 (1 register), int32 and float32 (2 registers,
// low word first), raw x 0.01.
void BM_ModbusRegisterDecode(benchmark::State& state) {
    const auto type = static_cast<modbus::RegisterType>(state.range(0));
    const std::vector<std::uint16_t> words = modbus::encodeValue(12.34, type, modbus::WordOrder::LowWordFirst,
                                                                 type == modbus::RegisterType::Float32 ? 1.0 : 0.01);
    const double scale = type == modbus::RegisterType::Float32 ? 1.0 : 0.01;
    for (auto _ : state) {
        auto value = modbus::decodeValue(words, type, modbus::WordOrder::LowWordFirst, scale);
        benchmark::DoNotOptimize(value);
    }
    state.SetLabel(std::string(modbus::typeKey(type)));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ModbusRegisterDecode)
    ->Arg(static_cast<int>(modbus::RegisterType::Int16))
    ->Arg(static_cast<int>(modbus::RegisterType::Int32))
    ->Arg(static_cast<int>(modbus::RegisterType::Float32));

}  // namespace
