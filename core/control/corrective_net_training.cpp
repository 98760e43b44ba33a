#include "core/control/corrective_net_training.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "core/common/operation_cancelled.h"

namespace tt::core {

namespace {

// Uniform in [0, 1) from 53 bits of the engine (std::uniform_real_distribution differs between
// standard libraries; this does not).
double uniform01(std::mt19937_64& engine) {
    return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

struct Split {
    std::vector<int> training;
    std::vector<int> validation;
};

Split splitSamples(int n, double validationFraction, std::mt19937_64& engine) {
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        order[static_cast<std::size_t>(i)] = i;
    for (int i = n - 1; i > 0; --i) {  // Fisher–Yates
        const int j = std::min(i, static_cast<int>(uniform01(engine) * (i + 1)));
        std::swap(order[static_cast<std::size_t>(i)], order[static_cast<std::size_t>(j)]);
    }
    const int validation = std::clamp(static_cast<int>(std::lround(validationFraction * n)), 1, n - 2);
    Split s;
    s.validation.assign(order.begin(), order.begin() + validation);
    s.training.assign(order.begin() + validation, order.end());
    return s;
}

struct Batch {
    Eigen::MatrixXd inputs;
    Eigen::VectorXd targets;
    Eigen::VectorXd weights;
};

Batch makeBatch(const std::vector<NetSample>& samples, const std::vector<int>& indices, const CorrectiveNet& shape) {
    const auto n = static_cast<Eigen::Index>(indices.size());
    Batch b{Eigen::MatrixXd(n, CorrectiveNet::kInputs), Eigen::VectorXd(n), Eigen::VectorXd(n)};
    const NetNormalisation& norm = shape.normalisation();
    for (Eigen::Index k = 0; k < n; ++k) {
        const NetSample& s = samples[static_cast<std::size_t>(indices[static_cast<std::size_t>(k)])];
        b.inputs.row(k) = shape.normaliseInputs(s.speedsRadPerS).transpose();
        b.targets(k) = (s.amplitudeV - norm.outputOffset) / norm.outputScale;
        b.weights(k) = s.weight;
    }
    return b;
}

NetWeights initialWeights(int hidden, std::mt19937_64& engine) {
    // Xavier (Glorot) uniform limits sqrt(6 / (fan_in + fan_out)); biases 0.
    const double limit1 = std::sqrt(6.0 / (CorrectiveNet::kInputs + hidden));
    const double limit2 = std::sqrt(6.0 / (hidden + 1));
    NetWeights w;
    w.hidden.resize(hidden, CorrectiveNet::kInputs);
    for (Eigen::Index c = 0; c < w.hidden.cols(); ++c)
        for (Eigen::Index r = 0; r < w.hidden.rows(); ++r)
            w.hidden(r, c) = limit1 * (2.0 * uniform01(engine) - 1.0);
    w.hiddenBias = Eigen::VectorXd::Zero(hidden);
    w.output.resize(hidden);
    for (Eigen::Index r = 0; r < hidden; ++r)
        w.output(r) = limit2 * (2.0 * uniform01(engine) - 1.0);
    return w;
}

void validateSamples(const std::vector<NetSample>& samples) {
    if (samples.size() < 10 || samples.size() > 1000000)
        throw std::invalid_argument("training needs 10 .. 1 000 000 samples, got " + std::to_string(samples.size()));
    for (const NetSample& s : samples) {
        for (double v : s.speedsRadPerS)
            if (!std::isfinite(v)) throw std::invalid_argument("a training sample has a speed that is not finite");
        if (!std::isfinite(s.amplitudeV) || !std::isfinite(s.weight) || s.weight < 0.0)
            throw std::invalid_argument("a training sample has an amplitude or weight that is not finite or negative");
    }
}

// Full-batch Adam with early stopping; `weights` ends at the best validation epoch.
void runAdam(NetWeights& weights, const Batch& training, const Batch& validation, const NetTrainingSettings& settings,
             const NetTrainingProgress& progress, NetTrainingRecord& record) {
    constexpr double kBeta1 = 0.9;
    constexpr double kBeta2 = 0.999;
    constexpr double kEpsilon = 1e-8;
    const int hidden = weights.hiddenCount();
    Eigen::VectorXd flat = weights.flatten();
    Eigen::VectorXd m = Eigen::VectorXd::Zero(flat.size());
    Eigen::VectorXd v = Eigen::VectorXd::Zero(flat.size());
    Eigen::VectorXd best = flat;
    double bestLoss = std::numeric_limits<double>::infinity();
    double bestTraining = 0.0;
    record.trainingLoss.clear();
    record.validationLoss.clear();
    record.stopReason = "epoch limit";
    for (int epoch = 1; epoch <= settings.maxEpochs; ++epoch) {
        const NetWeights current = NetWeights::unflatten(flat, hidden);
        const NetLoss train = netLossAndGradient(current, training.inputs, training.targets, training.weights);
        const double valLoss =
            netLossAndGradient(current, validation.inputs, validation.targets, validation.weights).loss;
        record.trainingLoss.push_back(train.loss);
        record.validationLoss.push_back(valLoss);
        record.epochs = epoch;
        if (valLoss < bestLoss) {
            bestLoss = valLoss;
            bestTraining = train.loss;
            best = flat;
            record.bestEpoch = epoch;
        }
        if (progress && !progress(epoch, train.loss, valLoss)) throw OperationCancelled();
        if (epoch - record.bestEpoch >= settings.patience) {
            record.stopReason = "early stop";
            break;
        }
        m = kBeta1 * m + (1.0 - kBeta1) * train.gradient;
        v = kBeta2 * v + (1.0 - kBeta2) * train.gradient.cwiseProduct(train.gradient);
        const double c1 = 1.0 - std::pow(kBeta1, epoch);
        const double c2 = 1.0 - std::pow(kBeta2, epoch);
        flat -= (settings.learningRate * (m / c1).array() / ((v / c2).array().sqrt() + kEpsilon)).matrix();
    }
    weights = NetWeights::unflatten(best, hidden);
    record.trainingRmsV = std::sqrt(2.0 * bestTraining);
    record.validationRmsV = std::sqrt(2.0 * bestLoss);
}

CorrectiveNet train(const CorrectiveNet& start, const std::vector<NetSample>& samples,
                    const NetTrainingSettings& settings, const NetTrainingProgress& progress, std::mt19937_64& engine,
                    NetTrainingRecord record) {
    const Split split = splitSamples(static_cast<int>(samples.size()), settings.validationFraction, engine);
    const Batch training = makeBatch(samples, split.training, start);
    const Batch validation = makeBatch(samples, split.validation, start);
    NetWeights weights = start.weights();
    record.seed = settings.seed;
    record.trainingSamples = static_cast<int>(split.training.size());
    record.validationSamples = static_cast<int>(split.validation.size());
    runAdam(weights, training, validation, settings, progress, record);
    const double scale = start.normalisation().outputScale;
    record.trainingRmsV *= scale;
    record.validationRmsV *= scale;
    return CorrectiveNet(std::move(weights), start.normalisation(), std::move(record));
}

}  // namespace

NetNormalisation normalisationFor(const std::vector<NetSample>& samples) {
    double total = 0.0;
    double mean = 0.0;
    for (const NetSample& s : samples) {
        total += s.weight;
        mean += s.weight * s.amplitudeV;
    }
    mean /= total;
    double variance = 0.0;
    for (const NetSample& s : samples)
        variance += s.weight * (s.amplitudeV - mean) * (s.amplitudeV - mean);
    NetNormalisation n;
    n.outputOffset = mean;
    n.outputScale = std::max(std::sqrt(variance / total), 1e-3);
    return n;
}

void validateNetTraining(const NetTrainingSettings& s) {
    const auto fail = [](const std::string& what) { throw std::invalid_argument("network training: " + what); };
    if (s.hiddenCount < 1 || s.hiddenCount > 100) fail("hidden neurons must be 1 .. 100");
    if (s.maxEpochs < 1 || s.maxEpochs > 100000) fail("epochs must be 1 .. 100 000");
    if (s.patience < 1 || s.patience > s.maxEpochs) fail("patience must be 1 .. the epochs");
    if (!(s.validationFraction >= 0.05 && s.validationFraction <= 0.5)) fail("validation share must be 0.05 .. 0.5");
    if (!(s.learningRate >= 1e-5 && s.learningRate <= 1.0)) fail("learning rate must be 1e-5 .. 1");
}

CorrectiveNet trainCorrectiveNet(const std::vector<NetSample>& samples, const NetTrainingSettings& settings,
                                 const NetTrainingProgress& progress) {
    validateNetTraining(settings);
    validateSamples(samples);
    std::mt19937_64 engine(settings.seed);
    const CorrectiveNet start(initialWeights(settings.hiddenCount, engine), normalisationFor(samples));
    return train(start, samples, settings, progress, engine, {});
}

CorrectiveNet retrainCorrectiveNet(const CorrectiveNet& start, const std::vector<NetSample>& samples,
                                   const NetTrainingSettings& settings, const NetTrainingProgress& progress) {
    validateNetTraining(settings);
    validateSamples(samples);
    NetTrainingRecord record = start.record();
    ++record.retrainings;
    std::mt19937_64 engine(settings.seed + static_cast<unsigned long long>(record.retrainings));
    return train(start, samples, settings, progress, engine, std::move(record));
}

}  // namespace tt::core
