#pragma once

#include <functional>
#include <vector>

#include "core/control/corrective_net.h"

namespace tt::core {

/// One training example: the motor speeds of a corner and the amplitude that minimised its cost.
struct NetSample {
    NetInputs speedsRadPerS{};
    double amplitudeV = 0.0;
    double weight = 1.0;  ///< share in the loss (old samples weigh less when retraining on drift)
};

/// How the network is trained: full-batch backpropagation with Adam (Kingma & Ba, ICLR 2015), early
/// stopping on a validation split. Everything random (initial weights, split) comes from `seed`.
struct NetTrainingSettings {
    int hiddenCount = CorrectiveNet::kPaperHidden;  ///< hidden sigmoid neurons (paper: 10)
    int maxEpochs = 8000;                           ///< full passes at most
    int patience = 1000;                            ///< stop after this many epochs without a better validation loss
    double validationFraction = 0.2;                ///< share of the samples held out for early stopping
    double learningRate = 0.03;                     ///< Adam step size
    unsigned long long seed = 1;
};

/// Throws std::invalid_argument when a setting is outside its range (hidden 1 .. 100, epochs 1 .. 100 000,
/// patience 1 .. epochs, validation 0.05 .. 0.5, learning rate 1e-5 .. 1).
void validateNetTraining(const NetTrainingSettings& settings);

/// The output normalisation trainCorrectiveNet uses: offset = weighted mean of the amplitudes, scale =
/// their weighted standard deviation (at least 1 mV); the inputs keep the paper's fixed 0.5 .. 9 rad/s map.
NetNormalisation normalisationFor(const std::vector<NetSample>& samples);

/// Called after every epoch with the epoch (1-based), the training and the validation loss; returning
/// false cancels (OperationCancelled).
using NetTrainingProgress = std::function<bool(int epoch, double trainingLoss, double validationLoss)>;

/// Trains a new network on `samples` (at least 10; speeds finite, amplitudes finite): inputs scaled
/// from the paper's 0.5 .. 9 rad/s to [−1, 1], the output by the targets' weighted mean and standard
/// deviation; Xavier-uniform initial weights; the weights of the epoch with the lowest validation loss
/// are kept. Deterministic for a given seed.
CorrectiveNet trainCorrectiveNet(const std::vector<NetSample>& samples, const NetTrainingSettings& settings,
                                 const NetTrainingProgress& progress = {});

/// Retrains `start` on `samples` from its current weights and normalisation (retraining on drift:
/// the recent corners and the old set with a lower weight); the record counts one more retraining.
CorrectiveNet retrainCorrectiveNet(const CorrectiveNet& start, const std::vector<NetSample>& samples,
                                   const NetTrainingSettings& settings, const NetTrainingProgress& progress = {});

}  // namespace tt::core
