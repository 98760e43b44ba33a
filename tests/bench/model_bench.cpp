#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "core/control/correction_path_builder.h"
#include "core/model/polynomial_regression.h"

namespace {

// Table 1 of the 2012 shaft paper, group 1 (d in mm, x in mm), gauged every 25 mm on 325 mm with
// a fixed small scatter: the 14 points the regression sees per group.
std::pair<Eigen::VectorXd, Eigen::VectorXd> groupOneSamples() {
    const double b[6] = {0.071, -0.000132, 2.379e-5, -2.09e-7, 6.42e-10, -6.6e-13};
    Eigen::VectorXd x(14), y(14);
    for (int i = 0; i < 14; ++i) {
        x(i) = 25.0 * i;
        double d = 0.0;
        for (int k = 5; k >= 0; --k)
            d = d * x(i) + b[k];
        y(i) = d + 0.004 * std::sin(1.7 * i);
    }
    return {x, y};
}

void BM_RegressionFit14PointsDegree5(benchmark::State& state) {
    const auto [x, y] = groupOneSamples();
    for (auto _ : state)
        benchmark::DoNotOptimize(tt::core::fitPolynomialRegression(x, y, 5));
}
BENCHMARK(BM_RegressionFit14PointsDegree5);

void BM_RegressionAutoDegree14Points(benchmark::State& state) {
    const auto [x, y] = groupOneSamples();
    for (auto _ : state)
        benchmark::DoNotOptimize(tt::core::fitPolynomialRegressionAutoDegree(x, y));
}
BENCHMARK(BM_RegressionAutoDegree14Points);

// The cutter path of one part: 5 control points, feed-forward from the Table 1 group 1 model,
// 325 mm part sampled every 0.5 mm (651 samples). Arg 0 = PCHIP, 1 = natural spline.
void BM_CorrectionPath325mmStep05(benchmark::State& state) {
    Eigen::VectorXd b(6);
    b << 0.071, -0.000132, 2.379e-5, -2.09e-7, 6.42e-10, -6.6e-13;
    tt::core::CorrectionPathRequest request;
    request.pointZMm = {0.0, 27.5, 162.5, 262.5, 325.0};
    request.pointCorrectionMm = {0.004, -0.010, 0.015, -0.006, 0.002};
    request.method =
        state.range(0) == 0 ? tt::core::InterpolationMethod::Pchip : tt::core::InterpolationMethod::NaturalSpline;
    request.diameterErrorModel = tt::core::ScaledPolynomial::fromPowerCoefficients(b);
    request.partLengthMm = 325.0;
    request.stepMm = 0.5;
    for (auto _ : state)
        benchmark::DoNotOptimize(tt::core::buildCorrectionPath(request));
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 651);
}
BENCHMARK(BM_CorrectionPath325mmStep05)->Arg(0)->Arg(1);

}  // namespace
