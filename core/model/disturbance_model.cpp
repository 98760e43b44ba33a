#include "core/model/disturbance_model.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/linalg/dare.h"
#include "core/linalg/stein.h"

namespace tt::core {

namespace {

void requirePositiveVariance(double v, const char* what) {
    if (!std::isfinite(v) || v <= 0.0)
        throw std::invalid_argument(std::string(what) + " must be a positive number of mm^2");
}

DisturbanceRealisation scalarRealisation(double a, double inputVariance) {
    DisturbanceRealisation r;
    r.A = Eigen::MatrixXd::Constant(1, 1, a);
    r.G = Eigen::MatrixXd::Ones(1, 1);
    r.C = Eigen::MatrixXd::Ones(1, 1);
    r.W = Eigen::MatrixXd::Constant(1, 1, inputVariance);
    return r;
}

}  // namespace

DisturbanceComponent::DisturbanceComponent(Kind kind, std::optional<ShapingFilter> filter, double pole,
                                           double inputVariance)
    : m_kind(kind), m_filter(std::move(filter)), m_pole(pole), m_inputVariance(inputVariance) {}

DisturbanceComponent DisturbanceComponent::shapingFilter(const ShapingFilter& filter, double inputVarianceMm2) {
    requirePositiveVariance(inputVarianceMm2, "shaping filter: the input variance");
    return DisturbanceComponent(Kind::ShapingFilter, filter, 0.0, inputVarianceMm2);
}

DisturbanceComponent DisturbanceComponent::shapingFilterWithVariance(const ShapingFilter& filter, double varianceMm2) {
    requirePositiveVariance(varianceMm2, "shaping filter: the output variance");
    return shapingFilter(filter, varianceMm2 / filter.unitInputVariance());
}

DisturbanceComponent DisturbanceComponent::ar1(double pole, double varianceMm2) {
    if (!std::isfinite(pole) || std::abs(pole) >= 1.0) {
        std::ostringstream why;
        why << "AR(1) disturbance: the pole " << pole
            << " must lie strictly inside (-1, 1); use a random walk for a drift that never returns";
        throw std::invalid_argument(why.str());
    }
    requirePositiveVariance(varianceMm2, "AR(1) disturbance: the variance");
    return DisturbanceComponent(Kind::Ar1, std::nullopt, pole, varianceMm2 * (1.0 - pole * pole));
}

DisturbanceComponent DisturbanceComponent::randomWalk(double stepVarianceMm2) {
    requirePositiveVariance(stepVarianceMm2, "random walk: the step variance");
    return DisturbanceComponent(Kind::RandomWalk, std::nullopt, 1.0, stepVarianceMm2);
}

DisturbanceComponent DisturbanceComponent::white(double varianceMm2) {
    requirePositiveVariance(varianceMm2, "white disturbance: the variance");
    return DisturbanceComponent(Kind::White, std::nullopt, 0.0, varianceMm2);
}

double DisturbanceComponent::stationaryVarianceMm2() const {
    switch (m_kind) {
        case Kind::ShapingFilter:
            return m_inputVariance * m_filter->unitInputVariance();
        case Kind::Ar1:
            return m_inputVariance / (1.0 - m_pole * m_pole);
        case Kind::RandomWalk:
            return std::numeric_limits<double>::infinity();
        case Kind::White:
            return m_inputVariance;
    }
    return 0.0;
}

DisturbanceRealisation DisturbanceComponent::realise() const {
    switch (m_kind) {
        case Kind::ShapingFilter:
            return m_filter->realise(m_inputVariance);
        case Kind::Ar1:
            return scalarRealisation(m_pole, m_inputVariance);
        case Kind::RandomWalk:
            return scalarRealisation(1.0, m_inputVariance);
        case Kind::White:
            return scalarRealisation(0.0, m_inputVariance);
    }
    return {};
}

std::string DisturbanceComponent::describe() const {
    std::ostringstream out;
    out.precision(4);
    switch (m_kind) {
        case Kind::ShapingFilter: {
            out << "shaping filter, poles";
            for (const auto& p : m_filter->poles())
                out << " " << formatMode(p);
            out << ", " << stationaryVarianceMm2() << " mm^2";
            break;
        }
        case Kind::Ar1:
            out << "AR(1) pole " << m_pole << ", " << stationaryVarianceMm2() << " mm^2";
            break;
        case Kind::RandomWalk:
            out << "random walk, step " << m_inputVariance << " mm^2";
            break;
        case Kind::White:
            out << "white, " << m_inputVariance << " mm^2";
            break;
    }
    return out.str();
}

DisturbanceModel::DisturbanceModel(std::vector<DisturbanceComponent> components) : m_components(std::move(components)) {
    if (m_components.empty()) throw std::invalid_argument("a control point needs at least one disturbance component");
}

bool DisturbanceModel::isStationary() const {
    for (const auto& c : m_components)
        if (!c.isStationary()) return false;
    return true;
}

double DisturbanceModel::stationaryVarianceMm2() const {
    double sum = 0.0;
    for (const auto& c : m_components)
        sum += c.stationaryVarianceMm2();
    return sum;
}

DisturbanceRealisation DisturbanceModel::realise() const {
    std::vector<DisturbanceRealisation> parts;
    for (const auto& c : m_components)
        parts.push_back(c.realise());
    DisturbanceRealisation r = stackRealisations(parts);
    r.C = r.C.colwise().sum().eval();  // the components add up at the one output
    return r;
}

DisturbanceRealisation stackRealisations(const std::vector<DisturbanceRealisation>& parts) {
    Eigen::Index states = 0;
    Eigen::Index inputs = 0;
    for (const auto& p : parts) {
        states += p.A.rows();
        inputs += p.G.cols();
    }
    const auto outputs = static_cast<Eigen::Index>(parts.size());
    DisturbanceRealisation r;
    r.A = Eigen::MatrixXd::Zero(states, states);
    r.G = Eigen::MatrixXd::Zero(states, inputs);
    r.C = Eigen::MatrixXd::Zero(outputs, states);
    r.W = Eigen::MatrixXd::Zero(inputs, inputs);
    Eigen::Index s = 0;
    Eigen::Index w = 0;
    for (Eigen::Index k = 0; k < outputs; ++k) {
        const DisturbanceRealisation& p = parts[static_cast<std::size_t>(k)];
        const Eigen::Index ns = p.A.rows();
        const Eigen::Index nw = p.G.cols();
        r.A.block(s, s, ns, ns) = p.A;
        r.G.block(s, w, ns, nw) = p.G;
        r.C.block(k, s, 1, ns) = p.C;
        r.W.block(w, w, nw, nw) = p.W;
        s += ns;
        w += nw;
    }
    return r;
}

std::string DisturbanceModel::describe() const {
    std::string out;
    for (const auto& c : m_components)
        out += (out.empty() ? "" : " + ") + c.describe();
    return out;
}

Eigen::MatrixXd DisturbanceModel::priorCovariance(double randomWalkPriorMm2) const {
    std::vector<Eigen::MatrixXd> blocks;
    Eigen::Index states = 0;
    for (const auto& c : m_components) {
        const DisturbanceRealisation r = c.realise();
        blocks.push_back(c.isStationary() ? solveDiscreteLyapunov(r.A, r.G * r.W * r.G.transpose())
                                          : Eigen::MatrixXd::Identity(r.A.rows(), r.A.rows()) * randomWalkPriorMm2);
        states += r.A.rows();
    }
    Eigen::MatrixXd P = Eigen::MatrixXd::Zero(states, states);
    Eigen::Index s = 0;
    for (const auto& b : blocks) {
        P.block(s, s, b.rows(), b.cols()) = b;
        s += b.rows();
    }
    return P;
}

}  // namespace tt::core
