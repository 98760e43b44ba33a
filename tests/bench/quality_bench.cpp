#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/quality/capability.h"
#include "core/quality/ewma_cusum.h"
#include "core/quality/individual_charts.h"
#include "core/quality/point_analysis.h"
#include "core/quality/xbar_charts.h"
#include "core/sim/statistics/normal_stream.h"

namespace {

using namespace tt::core;

constexpr std::size_t kValues = 1'000'000;
constexpr double kNominalMm = 20.0;
constexpr double kSigmaMm = 0.01;
const SpecLimits kSpec{19.95, 20.05, {}};

/// One control point's history of 1,000,000 diameters: the file named by TRUETURN_QUALITY_BENCH_VALUES
/// (little-endian doubles, written by scripts/crosscheck-quality.py --bench so that the peer times the same
/// values), or else N(20 mm, 0.01 mm) from the simulators' normal stream, seed 12345.
const std::vector<double>& values() {
    static const std::vector<double> v = [] {
        std::vector<double> out;
        if (const char* path = std::getenv("TRUETURN_QUALITY_BENCH_VALUES")) {
            std::ifstream in(path, std::ios::binary);
            for (double x; in.read(reinterpret_cast<char*>(&x), sizeof x);)
                out.push_back(x);
            if (out.empty()) throw std::runtime_error(std::string("no values in ") + path);
            return out;
        }
        NormalStream normal(12345);
        out.reserve(kValues);
        for (std::size_t i = 0; i < kValues; ++i)
            out.push_back(kNominalMm + kSigmaMm * normal.next());
        return out;
    }();
    return v;
}

void BM_QualityCapability(benchmark::State& state) {
    CapabilitySettings settings;
    settings.within = WithinSigmaMethod::Range;
    settings.subgroupSize = 5;
    for (auto _ : state)
        benchmark::DoNotOptimize(capabilityStudy(values(), kSpec, settings));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(values().size()));
}
BENCHMARK(BM_QualityCapability)->Unit(benchmark::kMillisecond);

void BM_QualityXbarR(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(xbarChart(values(), 5, SubgroupSpread::Range));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(values().size()));
}
BENCHMARK(BM_QualityXbarR)->Unit(benchmark::kMillisecond);

void BM_QualityIndividuals(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(individualsChart(values()));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(values().size()));
}
BENCHMARK(BM_QualityIndividuals)->Unit(benchmark::kMillisecond);

void BM_QualityEwma(benchmark::State& state) {
    EwmaSettings settings;
    settings.lambda = 0.2;
    settings.reference.targetMm = kNominalMm;
    settings.reference.sigmaMm = kSigmaMm;
    for (auto _ : state)
        benchmark::DoNotOptimize(ewmaChart(values(), settings));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(values().size()));
}
BENCHMARK(BM_QualityEwma)->Unit(benchmark::kMillisecond);

void BM_QualityCusum(benchmark::State& state) {
    CusumSettings settings;
    settings.reference.targetMm = kNominalMm;
    settings.reference.sigmaMm = kSigmaMm;
    for (auto _ : state)
        benchmark::DoNotOptimize(cusumChart(values(), settings));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(values().size()));
}
BENCHMARK(BM_QualityCusum)->Unit(benchmark::kMillisecond);

/// Everything the report shows for one point: X-bar-R chart (n = 5), Western Electric rules, capability.
void BM_QualityPointAnalysis(benchmark::State& state) {
    MeasuredSeries series;
    series.valuesMm = values();
    for (std::size_t i = 0; i < series.valuesMm.size(); ++i) {
        series.partNumbers.push_back(static_cast<std::int64_t>(i + 1));
        series.timesS.push_back(60.0 * static_cast<double>(i));
    }
    PointAnalysisSettings settings;
    settings.subgroupSize = 5;
    settings.spec = kSpec;
    for (auto _ : state)
        benchmark::DoNotOptimize(analysePoint(series, settings));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(series.valuesMm.size()));
}
BENCHMARK(BM_QualityPointAnalysis)->Unit(benchmark::kMillisecond);

}  // namespace
