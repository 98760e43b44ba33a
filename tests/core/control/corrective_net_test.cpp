// The corrective network of paper 002 (4 inputs, 10 sigmoid hidden neurons, 1 linear output): its
// backpropagated gradient against finite differences, reproducible training, and early stopping.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/common/operation_cancelled.h"
#include "core/control/corrective_net.h"
#include "core/control/corrective_net_training.h"

namespace tt::core {
namespace {

double uniform(std::mt19937_64& engine, double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

NetWeights randomWeights(int hidden, std::mt19937_64& engine) {
    Eigen::VectorXd flat(hidden * 6 + 1);
    for (Eigen::Index i = 0; i < flat.size(); ++i)
        flat(i) = uniform(engine, -1.5, 1.5);
    return NetWeights::unflatten(flat, hidden);
}

// A smooth stand-in for the amplitude map: what the network must be able to learn from 4 speeds.
double target(const NetInputs& v) {
    return 0.04 * (v[0] - v[2]) - 0.03 * (v[1] - v[3]) + 0.1 * std::sin(0.4 * v[0] * v[3] / 9.0);
}

std::vector<NetSample> samples(int n, unsigned long long seed) {
    std::mt19937_64 engine(seed);
    std::vector<NetSample> out;
    for (int i = 0; i < n; ++i) {
        NetSample s;
        for (double& v : s.speedsRadPerS)
            v = uniform(engine, 0.5, 9.0);
        s.amplitudeV = target(s.speedsRadPerS);
        out.push_back(s);
    }
    return out;
}

TEST(CorrectiveNet, BackpropagatedGradientMatchesCentralDifferences) {
    std::mt19937_64 engine(42);
    const NetWeights w = randomWeights(CorrectiveNet::kPaperHidden, engine);
    const int n = 25;
    Eigen::MatrixXd u(n, 4);
    Eigen::VectorXd t(n), weights(n);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < 4; ++j)
            u(i, j) = uniform(engine, -1.0, 1.0);
        t(i) = uniform(engine, -1.0, 1.0);
        weights(i) = uniform(engine, 0.1, 1.0);  // weighted, as when retraining with the old set
    }
    const NetLoss analytic = netLossAndGradient(w, u, t, weights);
    const Eigen::VectorXd flat = w.flatten();
    ASSERT_EQ(flat.size(), 61);  // 10 × 4 + 10 + 10 + 1
    for (Eigen::Index k = 0; k < flat.size(); ++k) {
        const double h = 1e-6;
        Eigen::VectorXd plus = flat, minus = flat;
        plus(k) += h;
        minus(k) -= h;
        const double numeric = (netLossAndGradient(NetWeights::unflatten(plus, 10), u, t, weights).loss -
                                netLossAndGradient(NetWeights::unflatten(minus, 10), u, t, weights).loss) /
                               (2.0 * h);
        // Central differences: truncation O(h²) ≈ 1e-12, rounding about 1e-16 / h = 1e-10.
        EXPECT_NEAR(analytic.gradient(k), numeric, 1e-8 + 1e-6 * std::abs(numeric)) << "weight " << k;
    }
}

TEST(CorrectiveNet, ForwardPassIsTheDocumentedFormula) {
    std::mt19937_64 engine(3);
    const NetWeights w = randomWeights(3, engine);
    NetNormalisation n;
    n.outputOffset = 0.1;
    n.outputScale = 0.2;
    const CorrectiveNet net(w, n);
    const NetInputs v{1.0, 2.0, 3.0, 9.0};
    double y = w.outputBias;
    for (int j = 0; j < 3; ++j) {
        double z = w.hiddenBias(j);
        for (int i = 0; i < 4; ++i)
            z += w.hidden(j, i) * (v[static_cast<std::size_t>(i)] - 4.75) / 4.25;
        y += w.output(j) / (1.0 + std::exp(-z));
    }
    EXPECT_NEAR(net.amplitudeV(v), 0.1 + 0.2 * y, 1e-15);
    EXPECT_EQ(logisticSigmoid(-1000.0), 0.0);  // no overflow either way
    EXPECT_EQ(logisticSigmoid(1000.0), 1.0);
    EXPECT_EQ(NetWeights::unflatten(w.flatten(), 3).flatten(), w.flatten());
}

TEST(CorrectiveNetTraining, LearnsASmoothMapAndIsReproducibleFromItsSeed) {
    const std::vector<NetSample> train = samples(200, 1);
    NetTrainingSettings s;
    s.maxEpochs = 3000;
    const CorrectiveNet a = trainCorrectiveNet(train, s);
    const CorrectiveNet b = trainCorrectiveNet(train, s);
    EXPECT_EQ(a.weights().flatten(), b.weights().flatten());  // bit for bit
    EXPECT_EQ(a.record().trainingLoss, b.record().trainingLoss);
    s.seed = 2;
    const CorrectiveNet c = trainCorrectiveNet(train, s);
    EXPECT_NE(a.weights().flatten(), c.weights().flatten());
    // Unseen inputs: the map's spread is about 0.2 V; the net must be within 0.02 V RMS.
    double sum = 0.0;
    const std::vector<NetSample> test = samples(200, 99);
    for (const NetSample& t : test)
        sum += std::pow(a.amplitudeV(t.speedsRadPerS) - t.amplitudeV, 2);
    EXPECT_LT(std::sqrt(sum / 200.0), 0.02);
    const NetTrainingRecord& r = a.record();
    EXPECT_EQ(r.trainingSamples, 160);
    EXPECT_EQ(r.validationSamples, 40);
    EXPECT_EQ(static_cast<int>(r.trainingLoss.size()), r.epochs);
    EXPECT_LE(r.bestEpoch, r.epochs);
    EXPECT_LT(r.validationLoss[static_cast<std::size_t>(r.bestEpoch - 1)], r.validationLoss.front() / 50.0);
}

TEST(CorrectiveNetTraining, EarlyStoppingKeepsTheBestValidationEpoch) {
    // Noisy targets on few samples: the validation loss turns up while the training loss keeps falling.
    std::vector<NetSample> noisy = samples(30, 5);
    std::mt19937_64 engine(8);
    for (NetSample& s : noisy)
        s.amplitudeV += uniform(engine, -0.1, 0.1);
    NetTrainingSettings s;
    s.hiddenCount = 30;
    s.patience = 200;
    s.maxEpochs = 20000;
    const CorrectiveNet net = trainCorrectiveNet(noisy, s);
    const NetTrainingRecord& r = net.record();
    EXPECT_EQ(r.stopReason, "early stop");
    EXPECT_EQ(r.epochs, r.bestEpoch + 200);
    const auto best = static_cast<std::size_t>(r.bestEpoch - 1);
    for (double v : r.validationLoss)
        EXPECT_GE(v, r.validationLoss[best]);
    EXPECT_LT(r.trainingLoss.back(), r.trainingLoss[best]);
}

TEST(CorrectiveNetTraining, RetrainingStartsFromTheNetworkAndFollowsTheNewTargets) {
    const std::vector<NetSample> train = samples(50, 1);
    NetTrainingSettings s;
    s.maxEpochs = 1500;
    s.patience = 300;
    const CorrectiveNet first = trainCorrectiveNet(train, s);
    std::vector<NetSample> shifted = train;
    for (NetSample& x : shifted)
        x.amplitudeV += 0.05;  // the machine now needs 50 mV more on every corner
    const CorrectiveNet again = retrainCorrectiveNet(first, shifted, s);
    EXPECT_EQ(again.record().retrainings, 1);
    EXPECT_EQ(again.normalisation().outputOffset, first.normalisation().outputOffset);
    double before = 0.0;
    double after = 0.0;
    for (const NetSample& x : shifted) {
        before += first.amplitudeV(x.speedsRadPerS) - x.amplitudeV;
        after += again.amplitudeV(x.speedsRadPerS) - x.amplitudeV;
    }
    EXPECT_NEAR(before / 50.0, -0.05, 0.02);  // the first network's own fit error is up to 15 mV
    EXPECT_NEAR(after / 50.0, 0.0, 0.01);
}

TEST(CorrectiveNetTraining, CancelsWhenAskedAndRefusesBadInput) {
    const std::vector<NetSample> train = samples(20, 1);
    EXPECT_THROW(trainCorrectiveNet(train, {}, [](int epoch, double, double) { return epoch < 5; }),
                 OperationCancelled);
    EXPECT_THROW(trainCorrectiveNet(samples(5, 1), {}), std::invalid_argument);
    NetTrainingSettings s;
    s.hiddenCount = 0;
    EXPECT_THROW(trainCorrectiveNet(train, s), std::invalid_argument);
    std::mt19937_64 engine(1);
    NetWeights w = randomWeights(2, engine);
    w.output(0) = std::nan("");
    EXPECT_THROW(CorrectiveNet(w, {}), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
