// quality_figures: prints the figures of core/quality for values on stdin as JSON, so that
// scripts/crosscheck-quality.py can compare them with a peer implementation (scipy, statsmodels, numpy).
//
//   quality_figures --lsl L --usl U [--target T] [--subgroup N] [--spread range|stddev] [--confidence C]
//                   < values        capability, normality, chart limits of the values
//   quality_figures --quantiles     normal and chi-square quantiles on a fixed grid
//
// Exit 2 with a one-line reason on stderr on bad input.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "core/quality/capability.h"
#include "core/quality/distributions.h"
#include "core/quality/individual_charts.h"
#include "core/quality/normality.h"
#include "core/quality/xbar_charts.h"

namespace {

using namespace tt::core;

struct Options {
    SpecLimits spec;
    int subgroupSize = 1;
    SubgroupSpread spread = SubgroupSpread::Range;
    double confidence = 0.95;
    bool quantiles = false;
};

double number(const std::string& text, const std::string& option) {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument(option + " needs a number (got " + text + ")");
    return v;
}

Options parse(int argc, char** argv) {
    Options o;
    bool haveLower = false, haveUpper = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--quantiles") {
            o.quantiles = true;
            continue;
        }
        if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
        const std::string value = argv[++i];
        if (arg == "--lsl") {
            o.spec.lowerMm = number(value, arg);
            haveLower = true;
        } else if (arg == "--usl") {
            o.spec.upperMm = number(value, arg);
            haveUpper = true;
        } else if (arg == "--target") {
            o.spec.targetMm = number(value, arg);
        } else if (arg == "--subgroup") {
            o.subgroupSize = static_cast<int>(number(value, arg));
        } else if (arg == "--spread") {
            if (value != "range" && value != "stddev") throw std::invalid_argument("--spread is range or stddev");
            o.spread = value == "range" ? SubgroupSpread::Range : SubgroupSpread::StdDev;
        } else if (arg == "--confidence") {
            o.confidence = number(value, arg);
        } else {
            throw std::invalid_argument("unknown option " + arg);
        }
    }
    if (!o.quantiles && !(haveLower && haveUpper)) throw std::invalid_argument("--lsl and --usl are required");
    return o;
}

void field(const char* name, double v, bool last = false) {
    std::printf("\"%s\": %.17g%s", name, v, last ? "" : ", ");
}

void interval(const char* name, const std::optional<ConfidenceInterval>& ci, bool last = false) {
    std::printf("\"%s\": [%.17g, %.17g]%s", name, ci->lower, ci->upper, last ? "" : ", ");
}

void printQuantiles() {
    const std::vector<double> probabilities = {1e-10, 1e-6, 0.00135, 0.025, 0.3, 0.5, 0.975, 0.99865, 1.0 - 1e-6};
    const std::vector<double> dofs = {1.0, 4.0, 19.0, 99.0, 123.7, 999.0, 1e5};
    std::printf("{\"normal\": [");
    for (std::size_t i = 0; i < probabilities.size(); ++i)
        std::printf("%s[%.17g, %.17g]", i ? ", " : "", probabilities[i], normalQuantile(probabilities[i]));
    std::printf("], \"chi2\": [");
    bool first = true;
    for (const double dof : dofs)
        for (const double p : {0.005, 0.025, 0.5, 0.975, 0.995}) {
            std::printf("%s[%.17g, %.17g, %.17g]", first ? "" : ", ", p, dof, chiSquareQuantile(p, dof));
            first = false;
        }
    std::printf("]}\n");
}

void printFigures(const std::vector<double>& values, const Options& o) {
    CapabilitySettings settings;
    settings.confidence = o.confidence;
    settings.subgroupSize = o.subgroupSize;
    settings.within = o.subgroupSize == 1
                          ? WithinSigmaMethod::MovingRange
                          : (o.spread == SubgroupSpread::Range ? WithinSigmaMethod::Range : WithinSigmaMethod::StdDev);
    const CapabilityStudy study = capabilityStudy(values, o.spec, settings);
    const CapabilityIndices normal = normalCapabilityIndices(
        {study.count, study.meanMm, study.sigmaWithinMm, study.sigmaOverallMm}, o.spec, o.confidence);
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    const PercentileSpread spread{empiricalQuantile(sorted, 0.00135), empiricalQuantile(sorted, 0.5),
                                  empiricalQuantile(sorted, 0.99865)};
    const CapabilityIndices percentile = percentileCapabilityIndices(spread, o.spec);
    const ChartLimits limits =
        o.subgroupSize == 1 ? individualsLimits(values) : xbarLimits(values, o.subgroupSize, o.spread);

    std::printf("{");
    field("n", static_cast<double>(study.count));
    field("mean", study.meanMm);
    field("sigma_within", study.sigmaWithinMm);
    field("sigma_overall", study.sigmaOverallMm);
    field("a2", study.normality.a2);
    field("a2_adjusted", study.normality.a2Adjusted);
    field("ad_p", study.normality.pValue);
    std::printf("\"method\": \"%s\", ", study.method == CapabilityMethod::Normal ? "normal" : "percentile");
    std::printf("\"normal\": {");
    field("cp", normal.cp);
    field("cpk", normal.cpk);
    field("pp", normal.pp);
    field("ppk", normal.ppk);
    field("cpm", *normal.cpm);
    interval("cp_ci", normal.cpInterval);
    interval("cpk_ci", normal.cpkInterval);
    interval("pp_ci", normal.ppInterval);
    interval("ppk_ci", normal.ppkInterval);
    interval("cpm_ci", normal.cpmInterval, true);
    std::printf("}, \"percentile\": {");
    field("low", spread.lowerMm);
    field("median", spread.medianMm);
    field("high", spread.upperMm);
    field("pp", percentile.pp);
    field("ppk", percentile.ppk, true);
    std::printf("}, \"chart\": {");
    field("centre", limits.location.centreMm);
    field("ucl", limits.location.upperMm);
    field("lcl", limits.location.lowerMm);
    field("spread_centre", limits.spread.centreMm);
    field("spread_ucl", limits.spread.upperMm);
    field("spread_lcl", limits.spread.lowerMm);
    field("sigma_within", limits.sigmaWithinMm, true);
    std::printf("}}\n");
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Options options = parse(argc, argv);
        if (options.quantiles) {
            printQuantiles();
            return 0;
        }
        std::vector<double> values;
        for (double v; std::cin >> v;)
            values.push_back(v);
        if (!std::cin.eof()) throw std::invalid_argument("stdin holds something that is not a number");
        printFigures(values, options);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quality_figures: %s\n", e.what());
        return 2;
    }
}
