#include <benchmark/benchmark.h>

#include <vector>

#include "core/common/crc16.h"

// CRC-16 over one probe-mandrel frame payload (32 bytes) and over a 64 KiB linearisation table image.
static void BM_Crc16(benchmark::State& state) {
    std::vector<std::uint8_t> data(static_cast<std::size_t>(state.range(0)));
    for (std::size_t i = 0; i < data.size(); ++i)
        data[i] = static_cast<std::uint8_t>(i * 31U);
    for (auto _ : state)
        benchmark::DoNotOptimize(tt::core::crc16Ccitt(data));
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}
BENCHMARK(BM_Crc16)->Arg(32)->Arg(65536);
