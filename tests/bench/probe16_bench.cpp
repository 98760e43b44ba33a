#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "core/calibration/linearisation_image.h"
#include "core/calibration/probe_linearisation.h"
#include "core/common/crc16.h"
#include "core/common/crc32c.h"
#include "devices/parsers/probe_protocol.h"

// 16-bit linearisation tables (image format 2, 131 104 bytes) and probe protocol 2.
namespace {

std::vector<std::uint8_t> sixteenBitImage() {
    std::vector<tt::core::CalibrationPoint> points;
    for (int i = 0; i <= 30; ++i) {
        const double um = -300.0 + 20.0 * i;
        points.push_back({um, 32767.5 + 90.0 * um + 1.0e-4 * um * um * um, 0});
    }
    return tt::core::encodeTableImage(tt::core::linearise(points, 16, 3).table, {1, 0, 0, 3});
}

}  // namespace

// The two CRCs over a whole 16-bit table image (what the host checks before an upload).
static void BM_Crc16Image16Bit(benchmark::State& state) {
    const std::vector<std::uint8_t> image = sixteenBitImage();
    for (auto _ : state)
        benchmark::DoNotOptimize(tt::core::crc16Ccitt(image));
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * image.size()));
}
BENCHMARK(BM_Crc16Image16Bit);

static void BM_Crc32cImage16Bit(benchmark::State& state) {
    const std::vector<std::uint8_t> image = sixteenBitImage();
    for (auto _ : state)
        benchmark::DoNotOptimize(tt::core::crc32c(image));
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * image.size()));
}
BENCHMARK(BM_Crc32cImage16Bit);

// Decoding (and checking) a format-2 16-bit image, as the wizard and the fuzz target do.
static void BM_DecodeImage16Bit(benchmark::State& state) {
    const std::vector<std::uint8_t> image = sixteenBitImage();
    for (auto _ : state)
        benchmark::DoNotOptimize(tt::core::decodeTableImage(image).crc);
}
BENCHMARK(BM_DecodeImage16Bit);

// The host side of a whole 16-bit upload without a wire: 1025 chunk frames built and acknowledged.
static void BM_UploaderWalk16Bit(benchmark::State& state) {
    using namespace tt::devices::probe;
    const std::vector<std::uint8_t> image = sixteenBitImage();
    const std::uint32_t crc = tt::core::crc32c(image);
    for (auto _ : state) {
        TableUploader up(image, 1, crc);
        std::uint32_t received = 0;
        while (up.phase() != TableUploader::Phase::Verify) {
            const TableUploader::Command c = up.current();
            benchmark::DoNotOptimize(encodeFrame(0, c.type, c.payload));
            if (c.type == MessageType::TableChunk) received += static_cast<std::uint32_t>(c.payload.size() - 4);
            up.onAck({static_cast<std::uint8_t>(c.type), AckResult::Ok, received});
        }
    }
}
BENCHMARK(BM_UploaderWalk16Bit);
