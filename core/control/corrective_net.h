#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace tt::core {

/// The inputs of the corrective network: motor speeds of X and Z before and after the velocity change,
/// rad/s (paper 002).
using NetInputs = std::array<double, 4>;

/// Affine maps that put the inputs and the output on the scale the weights work at:
/// normalised = (value − offset) / scale.
struct NetNormalisation {
    NetInputs inputOffset{4.75, 4.75, 4.75, 4.75};  ///< middle of the paper's 0.5 .. 9 rad/s
    NetInputs inputScale{4.25, 4.25, 4.25, 4.25};   ///< half its width: inputs land in [−1, 1]
    double outputOffset = 0.0;                      ///< V
    double outputScale = 1.0;                       ///< V
};

/// The weights of the 4–10–1 network: hidden = σ(W1 u + b1), output = w2·hidden + b2 (σ the logistic
/// sigmoid, the output linear; paper 002: "sigmoid for the hidden neurons, linear for the output").
struct NetWeights {
    Eigen::MatrixXd hidden;      ///< W1, hidden × 4
    Eigen::VectorXd hiddenBias;  ///< b1, hidden
    Eigen::VectorXd output;      ///< w2, hidden
    double outputBias = 0.0;     ///< b2

    /// Number of hidden neurons.
    int hiddenCount() const { return static_cast<int>(hidden.rows()); }
    /// All weights as one vector [W1 column-major, b1, w2, b2] (for the optimiser and the gradient check).
    Eigen::VectorXd flatten() const;
    /// The inverse of flatten() for `hiddenCount` neurons; throws std::invalid_argument on a wrong size.
    static NetWeights unflatten(const Eigen::VectorXd& flat, int hiddenCount);
};

/// How a network was trained (kept with it in its file).
struct NetTrainingRecord {
    unsigned long long seed = 0;  ///< initial weights and validation split
    int trainingSamples = 0;
    int validationSamples = 0;
    int epochs = 0;                      ///< epochs run
    int bestEpoch = 0;                   ///< epoch whose weights were kept (lowest validation loss)
    double trainingRmsV = 0.0;           ///< RMS amplitude error on the training samples at the best epoch, V
    double validationRmsV = 0.0;         ///< the same on the validation samples, V
    std::string stopReason;              ///< "early stop" or "epoch limit"
    std::vector<double> trainingLoss;    ///< per epoch, mean squared error in normalised units
    std::vector<double> validationLoss;  ///< per epoch
    int retrainings = 0;                 ///< retrainings on drift since the first training
};

/// The corrective-pulse network of paper 002: 4 inputs (normalised motor speeds), one hidden layer of
/// sigmoid neurons (10 in the paper), one linear output, the pulse amplitude in volts.
class CorrectiveNet {
public:
    /// Number of inputs (Vx1, Vz1, Vx2, Vz2).
    static constexpr int kInputs = 4;
    /// Hidden neurons of the paper's best configuration.
    static constexpr int kPaperHidden = 10;

    /// A network with these weights and normalisation; throws std::invalid_argument on inconsistent
    /// sizes, a non-finite value or a scale that is not above 0.
    CorrectiveNet(NetWeights weights, NetNormalisation normalisation, NetTrainingRecord record = {});

    /// The amplitude for motor speeds `speeds` (rad/s), V, before any limit.
    double amplitudeV(const NetInputs& speeds) const;
    /// The normalised output for normalised inputs (what training fits).
    double forwardNormalised(const Eigen::Vector4d& u) const;

    const NetWeights& weights() const { return m_weights; }
    const NetNormalisation& normalisation() const { return m_normalisation; }
    const NetTrainingRecord& record() const { return m_record; }
    /// Normalised inputs of `speeds`.
    Eigen::Vector4d normaliseInputs(const NetInputs& speeds) const;

private:
    NetWeights m_weights;
    NetNormalisation m_normalisation;
    NetTrainingRecord m_record;
};

/// The logistic sigmoid 1 / (1 + e^−x).
double logisticSigmoid(double x);

/// Weighted mean squared error L = Σ w_i (y(u_i) − t_i)² / (2 Σ w_i) of `weights` over normalised inputs
/// `inputs` (n × 4), normalised targets `targets` and sample weights `sampleWeights` (n, ≥ 0, not all
/// zero), and its gradient with respect to flatten() by backpropagation.
struct NetLoss {
    double loss = 0.0;
    Eigen::VectorXd gradient;
};
NetLoss netLossAndGradient(const NetWeights& weights, const Eigen::MatrixXd& inputs, const Eigen::VectorXd& targets,
                           const Eigen::VectorXd& sampleWeights);

}  // namespace tt::core
