// arma_figures: prints the ARMA fit of core/control (prediction-error method) for values on stdin as
// JSON, so that scripts/crosscheck-arma.py can compare it with statsmodels' ARIMA.
//
//   arma_figures --ar P --ma Q < values      the fit: ar, ma, their standard errors, noise variance
//   arma_figures --simulate SEED             the ARMA(1, 1) series of the engine tests (a = 0.92,
//                                            b = 0.25, sigma = 0.01, 2,000 values), one per line
//
// Exit 2 with a one-line reason on stderr on bad input.

#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "core/control/arma_identification.h"
#include "tests/core/support/arma_series.h"

namespace {

void printList(const char* name, const std::vector<double>& v) {
    std::printf("\"%s\": [", name);
    for (std::size_t i = 0; i < v.size(); ++i)
        std::printf("%s%.17g", i ? ", " : "", v[i]);
    std::printf("]");
}

}  // namespace

int main(int argc, char** argv) {
    try {
        tt::core::ArmaOrders orders;
        for (int i = 1; i + 1 < argc; i += 2) {
            const std::string option = argv[i];
            const int value = std::stoi(argv[i + 1]);
            if (option == "--simulate") {
                for (double y : tt::core::test::simulateArma11(0.92, 0.25, 0.01, 2000, static_cast<unsigned>(value)))
                    std::printf("%.17g\n", y);
                return 0;
            }
            if (option == "--ar")
                orders.ar = value;
            else if (option == "--ma")
                orders.ma = value;
            else
                throw std::invalid_argument("unknown option " + option);
        }
        std::vector<double> values;
        for (double v; std::cin >> v;)
            values.push_back(v);
        const tt::core::ArmaFit fit = tt::core::fitArma(values, orders);
        std::printf("{");
        printList("ar", fit.ar);
        std::printf(", ");
        printList("ma", fit.ma);
        std::printf(", ");
        printList("ar_se", fit.arStdErr);
        std::printf(", ");
        printList("ma_se", fit.maStdErr);
        std::printf(", \"mean\": %.17g, \"noise_variance\": %.17g, \"ljung_box_q\": %.17g, \"ljung_box_p\": %.17g}\n",
                    fit.meanMm, fit.noiseVarianceMm2, fit.ljungBoxQ, fit.ljungBoxP);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "arma_figures: %s\n", e.what());
        return 2;
    }
}
