#include "core/sim/statistics/stochastic_plant.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

#include "core/linalg/stein.h"

namespace tt::core {

StochasticPlant::StochasticPlant(const RunToRunPlant& plant, std::uint64_t seed)
    : m_gain(plant.gain), m_gaugeSigma(plant.V.diagonal().cwiseSqrt()), m_random(seed) {
    std::size_t offset = 0;
    std::size_t maxOrder = 0;
    for (int p = 0; p < plant.pointCount(); ++p) {
        for (const DisturbanceComponent& dc : plant.disturbances[static_cast<std::size_t>(p)].components()) {
            const DisturbanceRealisation r = dc.realise();
            Component c;
            c.point = p;
            c.offset = offset;
            c.order = static_cast<std::size_t>(r.A.rows());
            for (Eigen::Index i = 0; i < r.A.rows(); ++i) {
                for (Eigen::Index j = 0; j < r.A.cols(); ++j)
                    c.A.push_back(r.A(i, j));
                c.G.push_back(r.G(i, 0));
                c.C.push_back(r.C(0, i));
            }
            c.inputSigma = std::sqrt(r.W(0, 0));
            offset += c.order;
            maxOrder = std::max(maxOrder, c.order);
            m_components.push_back(std::move(c));
        }
    }
    m_state.assign(offset, 0.0);
    m_scratch.assign(maxOrder, 0.0);
    // Stationary start: s ~ N(0, Sigma), Sigma = A Sigma A' + G W G' (random walks start at 0).
    std::size_t componentIndex = 0;
    for (int p = 0; p < plant.pointCount(); ++p) {
        for (const DisturbanceComponent& dc : plant.disturbances[static_cast<std::size_t>(p)].components()) {
            Component& c = m_components[componentIndex++];
            if (!dc.isStationary()) continue;
            const DisturbanceRealisation r = dc.realise();
            const Eigen::MatrixXd sigma = solveDiscreteLyapunov(r.A, r.G * r.W * r.G.transpose());
            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(sigma);
            const Eigen::VectorXd root = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
            Eigen::VectorXd normal(static_cast<Eigen::Index>(c.order));
            for (Eigen::Index i = 0; i < normal.size(); ++i)
                normal(i) = m_random.next();
            const Eigen::VectorXd s0 = eig.eigenvectors() * root.asDiagonal() * normal;
            for (std::size_t i = 0; i < c.order; ++i)
                m_state[c.offset + i] = s0(static_cast<Eigen::Index>(i));
        }
    }
    m_draw.disturbanceMm = Eigen::VectorXd::Zero(m_gain.size());
    m_draw.gaugeNoiseMm = Eigen::VectorXd::Zero(m_gain.size());
}

const PartDraw& StochasticPlant::draw(std::int64_t partNumber) {
    if (m_started && partNumber != m_lastPart + 1)
        throw std::invalid_argument("plant: part numbers must increase by one (expected " +
                                    std::to_string(m_lastPart + 1) + ", got " + std::to_string(partNumber) + ")");
    m_started = true;
    m_lastPart = partNumber;
    m_draw.partNumber = partNumber;
    m_draw.disturbanceMm.setZero();
    for (const Component& c : m_components) {
        double* s = m_state.data() + c.offset;
        double d = 0.0;
        for (std::size_t i = 0; i < c.order; ++i)
            d += c.C[i] * s[i];
        m_draw.disturbanceMm(c.point) += d;
        const double w = c.inputSigma * m_random.next();
        for (std::size_t i = 0; i < c.order; ++i) {
            double acc = c.G[i] * w;
            const double* row = c.A.data() + i * c.order;
            for (std::size_t j = 0; j < c.order; ++j)
                acc += row[j] * s[j];
            m_scratch[i] = acc;
        }
        std::copy_n(m_scratch.data(), c.order, s);
    }
    for (Eigen::Index i = 0; i < m_gaugeSigma.size(); ++i)
        m_draw.gaugeNoiseMm(i) = m_gaugeSigma(i) * m_random.next();
    return m_draw;
}

Eigen::VectorXd StochasticPlant::deviationMm(const PartDraw& part, const Eigen::VectorXd& correctionMm) const {
    if (correctionMm.size() != m_gain.size())
        throw std::invalid_argument("plant: a correction needs " + std::to_string(m_gain.size()) + " values");
    return part.disturbanceMm + m_gain.cwiseProduct(correctionMm);
}

MachinedPart StochasticPlant::machine(std::int64_t partNumber, const Eigen::VectorXd& correctionMm) {
    const PartDraw& part = draw(partNumber);
    MachinedPart out;
    out.partNumber = partNumber;
    out.trueDeviationMm = deviationMm(part, correctionMm);
    out.measuredDeviationMm = out.trueDeviationMm + part.gaugeNoiseMm;
    return out;
}

StochasticPlantState StochasticPlant::saveState() const {
    StochasticPlantState s;
    s.values = {static_cast<double>(m_state.size()), m_started ? 1.0 : 0.0, static_cast<double>(m_lastPart)};
    s.values.insert(s.values.end(), m_state.begin(), m_state.end());
    s.random = m_random.saveState();
    return s;
}

void StochasticPlant::restoreState(const StochasticPlantState& state) {
    const auto& v = state.values;
    if (v.size() != 3 + m_state.size() || v[0] != static_cast<double>(m_state.size()))
        throw std::invalid_argument("saved plant state does not match this plant's disturbance models");
    for (double x : v)
        if (!std::isfinite(x)) throw std::invalid_argument("saved plant state contains a NaN or Inf");
    NormalStream random = m_random;
    random.restoreState(state.random);
    m_random = random;
    m_started = v[1] != 0.0;
    m_lastPart = static_cast<std::int64_t>(v[2]);
    std::copy(v.begin() + 3, v.end(), m_state.begin());
}

}  // namespace tt::core
