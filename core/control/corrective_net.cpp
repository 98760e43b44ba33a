#include "core/control/corrective_net.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace {

void requireFinite(const Eigen::MatrixXd& m, const char* what) {
    if (!m.allFinite())
        throw std::invalid_argument(std::string("network ") + what + " holds a value that is not finite");
}

Eigen::MatrixXd sigmoid(const Eigen::MatrixXd& z) {
    return z.unaryExpr([](double v) { return logisticSigmoid(v); });
}

}  // namespace

double logisticSigmoid(double x) {
    // Written so neither branch overflows: e^−|x| ≤ 1.
    if (x >= 0.0) return 1.0 / (1.0 + std::exp(-x));
    const double e = std::exp(x);
    return e / (1.0 + e);
}

Eigen::VectorXd NetWeights::flatten() const {
    const Eigen::Index h = hidden.rows();
    Eigen::VectorXd flat(h * CorrectiveNet::kInputs + 2 * h + 1);
    flat.head(h * CorrectiveNet::kInputs) = Eigen::Map<const Eigen::VectorXd>(hidden.data(), hidden.size());
    flat.segment(h * CorrectiveNet::kInputs, h) = hiddenBias;
    flat.segment(h * (CorrectiveNet::kInputs + 1), h) = output;
    flat(flat.size() - 1) = outputBias;
    return flat;
}

NetWeights NetWeights::unflatten(const Eigen::VectorXd& flat, int hiddenCount) {
    const Eigen::Index h = hiddenCount;
    if (h < 1 || flat.size() != h * CorrectiveNet::kInputs + 2 * h + 1)
        throw std::invalid_argument("network weights: " + std::to_string(flat.size()) + " values do not make a 4-" +
                                    std::to_string(hiddenCount) + "-1 network");
    NetWeights w;
    w.hidden = Eigen::Map<const Eigen::MatrixXd>(flat.data(), h, CorrectiveNet::kInputs);
    w.hiddenBias = flat.segment(h * CorrectiveNet::kInputs, h);
    w.output = flat.segment(h * (CorrectiveNet::kInputs + 1), h);
    w.outputBias = flat(flat.size() - 1);
    return w;
}

CorrectiveNet::CorrectiveNet(NetWeights weights, NetNormalisation normalisation, NetTrainingRecord record)
    : m_weights(std::move(weights)), m_normalisation(normalisation), m_record(std::move(record)) {
    const Eigen::Index h = m_weights.hidden.rows();
    if (h < 1 || h > 100 || m_weights.hidden.cols() != kInputs || m_weights.hiddenBias.size() != h ||
        m_weights.output.size() != h)
        throw std::invalid_argument("network weights must make a 4-H-1 network with 1 .. 100 hidden neurons");
    requireFinite(m_weights.hidden, "hidden weights");
    requireFinite(m_weights.hiddenBias, "hidden biases");
    requireFinite(m_weights.output, "output weights");
    if (!std::isfinite(m_weights.outputBias)) throw std::invalid_argument("network output bias is not finite");
    for (int i = 0; i < kInputs; ++i)
        if (!std::isfinite(normalisation.inputOffset[i]) || !(normalisation.inputScale[i] > 0.0) ||
            !std::isfinite(normalisation.inputScale[i]))
            throw std::invalid_argument("network input normalisation " + std::to_string(i + 1) +
                                        ": the offset must be finite and the scale above 0");
    if (!std::isfinite(normalisation.outputOffset) || !(normalisation.outputScale > 0.0) ||
        !std::isfinite(normalisation.outputScale))
        throw std::invalid_argument("network output normalisation: the offset must be finite and the scale above 0");
}

Eigen::Vector4d CorrectiveNet::normaliseInputs(const NetInputs& speeds) const {
    Eigen::Vector4d u;
    for (int i = 0; i < kInputs; ++i)
        u(i) = (speeds[i] - m_normalisation.inputOffset[i]) / m_normalisation.inputScale[i];
    return u;
}

double CorrectiveNet::forwardNormalised(const Eigen::Vector4d& u) const {
    const Eigen::VectorXd h = sigmoid(m_weights.hidden * u + m_weights.hiddenBias);
    return m_weights.output.dot(h) + m_weights.outputBias;
}

double CorrectiveNet::amplitudeV(const NetInputs& speeds) const {
    return m_normalisation.outputOffset + m_normalisation.outputScale * forwardNormalised(normaliseInputs(speeds));
}

NetLoss netLossAndGradient(const NetWeights& w, const Eigen::MatrixXd& inputs, const Eigen::VectorXd& targets,
                           const Eigen::VectorXd& sampleWeights) {
    const Eigen::Index n = inputs.rows();
    if (inputs.cols() != CorrectiveNet::kInputs || targets.size() != n || sampleWeights.size() != n || n == 0)
        throw std::invalid_argument("training data: inputs must be n x 4 with n targets and n weights, n >= 1");
    const double totalWeight = sampleWeights.sum();
    if (!(totalWeight > 0.0) || (sampleWeights.array() < 0.0).any())
        throw std::invalid_argument("training data: sample weights must not be negative nor all zero");
    // Forward over the batch: columns are samples.
    const Eigen::MatrixXd z = (w.hidden * inputs.transpose()).colwise() + w.hiddenBias;
    const Eigen::MatrixXd h = sigmoid(z);
    const Eigen::VectorXd y = (w.output.transpose() * h).transpose().array() + w.outputBias;
    const Eigen::VectorXd r = y - targets;
    NetLoss out;
    out.loss = 0.5 * (sampleWeights.array() * r.array().square()).sum() / totalWeight;
    // Backward: dL/dy_i = w_i r_i / W.
    const Eigen::VectorXd g = (sampleWeights.array() * r.array()).matrix() / totalWeight;
    const Eigen::MatrixXd dz = ((w.output * g.transpose()).array() * h.array() * (1.0 - h.array())).matrix();
    NetWeights grad;
    grad.hidden = dz * inputs;
    grad.hiddenBias = dz.rowwise().sum();
    grad.output = h * g;
    grad.outputBias = g.sum();
    out.gradient = grad.flatten();
    return out;
}

}  // namespace tt::core
