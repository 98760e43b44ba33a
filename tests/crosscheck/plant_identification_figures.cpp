// plant_identification_figures: the closed-loop identification of core/control (plant_identification.h) on a
// simulated run of paper-2012's LQG, as JSON, so that scripts/crosscheck-plant-identification.py can compare it with
// statsmodels' ARIMA with the correction as regressor (regression with ARMA errors, exact likelihood) on the same
// data, and with the simulated truth.
//
//   plant_identification_figures --delay Z --gain-factor F --lag L --parts N --seed S [--prior-ar-pole P]
//
// Prints {delay, lag, lag_scores, points: [{gain, gain_se, mean, ar, ma, ar_se, ma_se, noise_variance, p, q,
// disturbance_kept,
// y: [...], u: [...]}], truth: {...}}: y the measured deviations the fit used, u the corrections acting on those
// parts (sent lag parts earlier). Exit 2 with a one-line reason on stderr on bad input.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "core/control/plant_identification.h"
#include "tests/core/support/closed_loop_record.h"

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
        int delay = 1, lag = 0, parts = 2000;
        double gainFactor = 1.0;
        double priorArPole = 0.0;  // 0: the model's own disturbance as the prior
        unsigned long long seed = 1;
        for (int i = 1; i + 1 < argc; i += 2) {
            const std::string option = argv[i];
            const std::string value = argv[i + 1];
            if (option == "--delay")
                delay = std::stoi(value);
            else if (option == "--lag")
                lag = std::stoi(value);
            else if (option == "--parts")
                parts = std::stoi(value);
            else if (option == "--gain-factor")
                gainFactor = std::stod(value);
            else if (option == "--seed")
                seed = std::stoull(value);
            else if (option == "--prior-ar-pole")
                priorArPole = std::stod(value);
            else
                throw std::invalid_argument("unknown option " + option);
        }
        using namespace tt::core;
        const auto controller = test::paperLqg(delay);
        const LoopHistory h =
            test::runClosedLoop(*controller, delay, gainFactor, lag, static_cast<std::size_t>(parts + delay), seed);
        // The options the adaptive loop uses: the fits start from the model it had (gain 2, the ARMA(1, 1)), or
        // from a wrong disturbance (AR(1) with --prior-ar-pole), which the criterion must refuse to keep.
        PlantIdentificationOptions o = test::paperIdentification(delay);
        if (priorArPole != 0.0) {
            o.priorAr.assign(5, {priorArPole});
            o.priorMa.assign(5, {});
        }
        const PlantIdentification id = identifyPlant(h, o);
        std::printf("{\"delay\": %d, \"lag\": %d, ", id.delayParts(), id.lagParts);
        printList("lag_scores", id.lagScores);
        std::printf(", \"points\": [");
        for (std::size_t k = 0; k < id.points.size(); ++k) {
            const PointPlantFit& p = id.points[k];
            std::vector<double> y, u;
            for (std::int64_t part = p.firstPart; part <= p.lastPart; ++part) {
                const auto t = static_cast<std::size_t>(part - h.firstPart);
                y.push_back(h.deviationMm[t](p.point));
                u.push_back(h.appliedMm[t - static_cast<std::size_t>(id.lagParts)](p.point));
            }
            std::printf(
                "%s{\"gain\": %.17g, \"gain_se\": %.17g, \"mean\": %.17g, \"noise_variance\": %.17g, "
                "\"p\": %d, \"q\": %d, \"disturbance_kept\": %s, ",
                k ? ", " : "", p.fit.gain, p.fit.gainStdErr, p.fit.meanMm, p.fit.noise.noiseVarianceMm2, p.orders.ar,
                p.orders.ma, p.disturbanceKept ? "true" : "false");
            printList("ar", p.fit.noise.ar);
            std::printf(", ");
            printList("ma", p.fit.noise.ma);
            std::printf(", ");
            printList("ar_se", p.fit.noise.arStdErr);
            std::printf(", ");
            printList("ma_se", p.fit.noise.maStdErr);
            std::printf(", ");
            printList("y", y);
            std::printf(", ");
            printList("u", u);
            std::printf("}");
        }
        std::printf(
            "], \"truth\": {\"gain\": %.17g, \"delay\": %d, \"pole\": %.17g, \"zero\": %.17g, "
            "\"noise_variance\": %.17g}}\n",
            2.0 * gainFactor, delay + lag, test::kPaperPole, test::kPaperZero, test::paperInnovationVariance());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "plant_identification_figures: %s\n", e.what());
        return 2;
    }
}
