#include "core/control/lqg_controller.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/common/text_format.h"
#include "core/control/run_to_run_checks.h"

namespace tt::core {

namespace {

constexpr double kStateFormat = 2.0;
constexpr std::int64_t kNoStep = std::numeric_limits<std::int64_t>::min();
/// The tracked covariance counts as steady when every entry is within this fraction of the largest
/// steady-state entry.
constexpr double kSteadyTolerance = 1e-10;

using PointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxControlPoints, 1>;

/// Sequential reader of a saved state with a clear error when it runs short.
class StateReader {
public:
    explicit StateReader(const std::vector<double>& values) : m_values(values) {}
    double next() {
        if (m_pos >= m_values.size()) throw std::invalid_argument("saved LQG controller state is truncated");
        return m_values[m_pos++];
    }
    std::int64_t nextStep() {
        const bool none = next() < 0.0;
        const double value = next();
        return none ? kNoStep : static_cast<std::int64_t>(value);
    }
    bool atEnd() const { return m_pos == m_values.size(); }

private:
    const std::vector<double>& m_values;
    std::size_t m_pos = 0;
};

}  // namespace

void LqgControllerOptions::validate() const {
    if (!std::isfinite(gateSigma) || gateSigma <= 0.0)
        throw std::invalid_argument("LQG controller: the innovation gate must be > 0 sigma");
    requireHistoryParts(historyParts, "LQG controller");
}

LqgController::LqgController(const RunToRunPlant& plant, const LqgDesign& design, const CorrectionLimits& limits,
                             const LqgControllerOptions& options)
    : m_points(plant.pointCount()),
      m_delay(plant.delay),
      m_states(plant.stateCount()),
      m_limits(limits),
      m_options(options) {
    limits.validate();
    options.validate();
    if (design.K.rows() != m_points || design.K.cols() != m_states)
        throw std::invalid_argument("LQG controller: the design does not match the plant");
    if (!plant.D.isZero(0.0))
        throw std::invalid_argument("LQG controller: a plant with feed-through (D != 0) is not a run-to-run plant");
    Eigen::Index offset = 0;
    for (const LqgBlock& b : design.blocks) {
        Block blk;
        static_cast<LqgBlock&>(blk) = b;
        blk.offset = offset;
        blk.size = static_cast<Eigen::Index>(b.states.size());
        blk.covOffset = m_covSize;
        blk.steadyVariance.resize(m_delay, static_cast<Eigen::Index>(b.points.size()));
        Eigen::MatrixXd P = b.P;
        for (int lead = 0; lead < m_delay; ++lead) {
            blk.steadyVariance.row(lead) = (b.C * P * b.C.transpose() + b.V).diagonal().transpose();
            P = (b.A * P * b.A.transpose() + b.Q).eval();
        }
        offset += blk.size;
        m_covSize += static_cast<std::size_t>(blk.size * blk.size);
        m_blocks.push_back(std::move(blk));
    }
    if (offset != m_states) throw std::invalid_argument("LQG controller: the design blocks do not cover the plant");
    m_prior.x = Eigen::VectorXd::Zero(m_states);
    m_prior.cov.assign(m_covSize, 0.0);
    m_prior.steady.assign(m_blocks.size(), 0);
    for (const Block& b : m_blocks)
        std::copy_n(b.P0.data(), b.P0.size(), m_prior.cov.begin() + static_cast<std::ptrdiff_t>(b.covOffset));
    m_scratch = Eigen::VectorXd::Zero(m_states);
    m_lastApplied = Eigen::VectorXd::Zero(m_points);
    m_lastLimited = Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(m_points, false);
    const std::size_t z = static_cast<std::size_t>(m_delay);
    const std::size_t h = static_cast<std::size_t>(m_options.historyParts);
    const std::size_t m = static_cast<std::size_t>(m_points);
    m_pendingStep.assign(z, kNoStep);
    m_pendingValue.assign(z * m, 0.0);
    m_pendingHas.assign(z * m, 0);
    m_historyStep.assign(h, kNoStep);
    m_historyX.assign(h * static_cast<std::size_t>(m_states), 0.0);
    m_historyCov.assign(h * m_covSize, 0.0);
    m_historySteady.assign(h * m_blocks.size(), 0);
    m_historyValue.assign(h * m, 0.0);
    m_historyHas.assign(h * m, 0);
    m_historyApplied.assign(h * m, 0.0);
}

std::size_t LqgController::historySlot(std::int64_t step) const {
    return ringSlot(step, m_options.historyParts);
}

std::size_t LqgController::pendingSlot(std::int64_t step) const {
    return ringSlot(step, m_delay);
}

void LqgController::measurementUpdate(Estimate& e, const double* values, const std::uint8_t* has) const {
    for (std::size_t bi = 0; bi < m_blocks.size(); ++bi) {
        const Block& b = m_blocks[bi];
        auto xb = e.x.segment(b.offset, b.size);
        const Eigen::Index np = static_cast<Eigen::Index>(b.points.size());
        PointVector innovation(np);
        Eigen::Index present = 0;
        for (Eigen::Index j = 0; j < np; ++j) {
            const int p = b.points[static_cast<std::size_t>(j)];
            innovation(j) = has[p] ? values[p] - b.C.row(j).dot(xb) : 0.0;
            present += has[p] ? 1 : 0;
        }
        if (present > 0) xb.noalias() += b.L * innovation;
        if (e.steady[bi] && present == np) continue;  // stays at the steady state (time update below)
        // Joseph form with the steady-state gain restricted to the points present.
        Eigen::Map<Eigen::MatrixXd> P(e.cov.data() + b.covOffset, b.size, b.size);
        Eigen::MatrixXd Lm = b.L;
        for (Eigen::Index j = 0; j < np; ++j)
            if (!has[b.points[static_cast<std::size_t>(j)]]) Lm.col(j).setZero();
        const Eigen::MatrixXd F = Eigen::MatrixXd::Identity(b.size, b.size) - Lm * b.C;
        const Eigen::MatrixXd posterior = F * P * F.transpose() + Lm * b.V * Lm.transpose();
        P = posterior;
        e.steady[bi] = 0;
    }
}

void LqgController::timeUpdate(Estimate& e, const double* applied) {
    for (std::size_t bi = 0; bi < m_blocks.size(); ++bi) {
        const Block& b = m_blocks[bi];
        const Eigen::Index np = static_cast<Eigen::Index>(b.points.size());
        PointVector u(np);
        for (Eigen::Index j = 0; j < np; ++j)
            u(j) = applied[b.points[static_cast<std::size_t>(j)]];
        auto tmp = m_scratch.segment(b.offset, b.size);
        tmp.noalias() = b.A * e.x.segment(b.offset, b.size);
        tmp.noalias() += b.B * u;
        e.x.segment(b.offset, b.size) = tmp;
        if (e.steady[bi]) continue;
        Eigen::Map<Eigen::MatrixXd> P(e.cov.data() + b.covOffset, b.size, b.size);
        const Eigen::MatrixXd prior = b.A * P * b.A.transpose() + b.Q;
        P = 0.5 * (prior + prior.transpose());
        const double scale = b.P.cwiseAbs().maxCoeff();
        if ((P - b.P).cwiseAbs().maxCoeff() <= kSteadyTolerance * scale) {
            P = b.P;
            e.steady[bi] = 1;
        }
    }
}

Eigen::VectorXd LqgController::innovationVariance(const Estimate& e, int lead) const {
    Eigen::VectorXd s(m_points);
    for (std::size_t bi = 0; bi < m_blocks.size(); ++bi) {
        const Block& b = m_blocks[bi];
        Eigen::VectorXd sb;
        if (e.steady[bi]) {
            sb = b.steadyVariance.row(lead).transpose();
        } else {
            Eigen::MatrixXd P = Eigen::Map<const Eigen::MatrixXd>(e.cov.data() + b.covOffset, b.size, b.size);
            for (int i = 0; i < lead; ++i)
                P = (b.A * P * b.A.transpose() + b.Q).eval();
            sb = (b.C * P * b.C.transpose() + b.V).diagonal();
        }
        for (std::size_t j = 0; j < b.points.size(); ++j)
            s(b.points[j]) = sb(static_cast<Eigen::Index>(j));
    }
    return s;
}

Eigen::VectorXd LqgController::predictOutputs(const Eigen::VectorXd& x, int lead) const {
    Eigen::VectorXd y(m_points);
    for (const Block& b : m_blocks) {
        Eigen::VectorXd xb = x.segment(b.offset, b.size);
        for (int i = 0; i < lead; ++i)
            xb = (b.A * xb).eval();  // new inputs enter the delay chain and reach no output within lead < z
        const Eigen::VectorXd yb = b.C * xb;
        for (std::size_t j = 0; j < b.points.size(); ++j)
            y(b.points[j]) = yb(static_cast<Eigen::Index>(j));
    }
    return y;
}

Eigen::VectorXd LqgController::predictedDeviationMm() const {
    return predictOutputs(m_prior.x, 0);
}

Eigen::VectorXd LqgController::predictedUncorrectedDeviationMm() const {
    Eigen::VectorXd y(m_points);
    for (const Block& b : m_blocks) {
        // Block order: the points' delay chains first (z states each), then the disturbance states.
        const Eigen::Index delayStates = static_cast<Eigen::Index>(b.points.size()) * m_delay;
        const Eigen::Index rest = b.size - delayStates;
        const Eigen::VectorXd yb = b.C.rightCols(rest) * m_prior.x.segment(b.offset + delayStates, rest);
        for (std::size_t j = 0; j < b.points.size(); ++j)
            y(b.points[j]) = yb(static_cast<Eigen::Index>(j));
    }
    return y;
}

Eigen::VectorXd LqgController::predictedSigmaMm() const {
    return innovationVariance(m_prior, 0).cwiseSqrt();
}

void LqgController::storeHistory(std::size_t slot, const Estimate& e) {
    const std::size_t n = static_cast<std::size_t>(m_states);
    std::copy_n(e.x.data(), n, m_historyX.begin() + static_cast<std::ptrdiff_t>(slot * n));
    std::copy(e.cov.begin(), e.cov.end(), m_historyCov.begin() + static_cast<std::ptrdiff_t>(slot * m_covSize));
    std::copy(e.steady.begin(), e.steady.end(),
              m_historySteady.begin() + static_cast<std::ptrdiff_t>(slot * m_blocks.size()));
}

void LqgController::loadHistory(std::size_t slot, Estimate& e) const {
    const std::size_t n = static_cast<std::size_t>(m_states);
    e.x = Eigen::Map<const Eigen::VectorXd>(m_historyX.data() + slot * n, m_states);
    e.cov.assign(m_historyCov.begin() + static_cast<std::ptrdiff_t>(slot * m_covSize),
                 m_historyCov.begin() + static_cast<std::ptrdiff_t>((slot + 1) * m_covSize));
    e.steady.assign(m_historySteady.begin() + static_cast<std::ptrdiff_t>(slot * m_blocks.size()),
                    m_historySteady.begin() + static_cast<std::ptrdiff_t>((slot + 1) * m_blocks.size()));
}

MeasurementVerdict LqgController::addMeasurement(const PartMeasurement& measurement) {
    requireMeasurementSize(measurement, m_points, "LQG controller");
    const std::size_t m = static_cast<std::size_t>(m_points);
    const std::int64_t part = measurement.partNumber;
    const std::int64_t lead = part - m_nextStep;
    const bool stillKept =
        lead >= 0 || (part >= m_nextStep - m_options.historyParts && m_historyStep[historySlot(part)] == part);
    const MachinedParts machined{m_started, m_firstPart, m_lastPart, m_options.historyParts};
    if (const auto why = partRejection(machined, part, stillKept)) return rejectEveryPoint(m_points, *why);
    MeasurementVerdict verdict{std::vector<bool>(m, false), std::vector<Notice>(m)};

    // Prediction of this part's measurement and where it is stored.
    Eigen::VectorXd predicted;
    Eigen::VectorXd variance;
    double* values = nullptr;
    std::uint8_t* has = nullptr;
    if (lead >= 0) {
        const std::size_t slot = pendingSlot(part);
        if (m_pendingStep[slot] != part) {
            m_pendingStep[slot] = part;
            std::fill_n(m_pendingHas.begin() + static_cast<std::ptrdiff_t>(slot * m), m, std::uint8_t{0});
        }
        predicted = predictOutputs(m_prior.x, static_cast<int>(lead));
        variance = innovationVariance(m_prior, static_cast<int>(lead));
        values = m_pendingValue.data() + slot * m;
        has = m_pendingHas.data() + slot * m;
    } else {
        const std::size_t slot = historySlot(part);
        Estimate then;
        loadHistory(slot, then);
        predicted = predictOutputs(then.x, 0);
        variance = innovationVariance(then, 0);
        values = m_historyValue.data() + slot * m;
        has = m_historyHas.data() + slot * m;
    }

    if (lead == 0) {
        Innovation innovation{part, measurement.deviationMm - predicted, variance};
        for (Eigen::Index i = 0; i < innovation.valueMm.size(); ++i)
            if (!std::isfinite(innovation.valueMm(i))) innovation.valueMm(i) = std::numeric_limits<double>::quiet_NaN();
        m_lastInnovation = std::move(innovation);
    }
    bool anyAccepted = false;
    for (std::size_t i = 0; i < m; ++i) {
        const Eigen::Index ii = static_cast<Eigen::Index>(i);
        const double v = measurement.deviationMm(ii);
        if (const auto why = valueRejection(v, has[i] != 0, part)) {
            verdict.reasons[i] = *why;
            continue;
        }
        const double off = std::abs(v - predicted(ii)) / std::sqrt(variance(ii));
        if (off > m_options.gateSigma) {
            verdict.reasons[i] = Notice{NoticeKind::Outlier, part};
            verdict.reasons[i].value = off;
            verdict.reasons[i].limit = m_options.gateSigma;
            continue;
        }
        values[i] = v;
        has[i] = 1;
        verdict.accepted[i] = true;
        anyAccepted = true;
    }
    if (lead < 0 && anyAccepted) refilterFrom(part);
    return verdict;
}

void LqgController::refilterFrom(std::int64_t step) {
    const std::size_t m = static_cast<std::size_t>(m_points);
    Estimate e;
    loadHistory(historySlot(step), e);
    for (std::int64_t k = step; k < m_nextStep; ++k) {
        const std::size_t slot = historySlot(k);
        storeHistory(slot, e);
        measurementUpdate(e, m_historyValue.data() + slot * m, m_historyHas.data() + slot * m);
        timeUpdate(e, m_historyApplied.data() + slot * m);
    }
    m_prior = std::move(e);
}

Eigen::VectorXd LqgController::nextCorrection(std::int64_t partNumber) {
    requireNextPart(m_started, m_lastPart, partNumber, "LQG controller");
    if (!m_started) {
        m_started = true;
        m_firstPart = partNumber;
        m_lastPart = partNumber - 1;
        m_nextStep = partNumber - m_delay;
    }
    const std::int64_t k = m_nextStep;
    const std::size_t m = static_cast<std::size_t>(m_points);
    const std::size_t pslot = pendingSlot(k);
    const std::size_t hslot = historySlot(k);

    // History entry of step k: the prior, the measurement of part k (if any) and the applied u(k).
    m_historyStep[hslot] = k;
    storeHistory(hslot, m_prior);
    double* values = m_historyValue.data() + hslot * m;
    std::uint8_t* has = m_historyHas.data() + hslot * m;
    if (m_pendingStep[pslot] == k) {
        std::copy_n(m_pendingValue.data() + pslot * m, m, values);
        std::copy_n(m_pendingHas.data() + pslot * m, m, has);
    } else {
        std::fill_n(has, m, std::uint8_t{0});
    }
    m_pendingStep[pslot] = kNoStep;

    // x(k|k), u(k) = -K x(k|k), limits, then x(k+1|k) with what is really applied.
    measurementUpdate(m_prior, values, has);
    Eigen::VectorXd candidate(m_points);
    for (const Block& b : m_blocks) {
        const PointVector ub = -(b.K * m_prior.x.segment(b.offset, b.size));
        for (std::size_t j = 0; j < b.points.size(); ++j)
            candidate(b.points[j]) = ub(static_cast<Eigen::Index>(j));
    }
    const LimitedCorrection limited = applyCorrectionLimits(candidate, m_lastApplied, m_limits);
    std::copy_n(limited.correctionMm.data(), m, m_historyApplied.begin() + static_cast<std::ptrdiff_t>(hslot * m));
    timeUpdate(m_prior, limited.correctionMm.data());
    m_nextStep = k + 1;
    m_lastPart = partNumber;
    m_lastApplied = limited.correctionMm;
    m_lastLimited = limited.limited;
    return m_lastApplied;
}

void LqgController::correctionApplied(std::int64_t partNumber, const Eigen::VectorXd& appliedMm) {
    if (!m_started || partNumber != m_lastPart || appliedMm.size() != m_points || !appliedMm.allFinite()) return;
    const Eigen::VectorXd change = appliedMm - m_lastApplied;
    if (change.isZero(0.0)) return;
    for (const Block& b : m_blocks) {
        const Eigen::Index np = static_cast<Eigen::Index>(b.points.size());
        PointVector du(np);
        for (Eigen::Index j = 0; j < np; ++j)
            du(j) = change(b.points[static_cast<std::size_t>(j)]);
        m_prior.x.segment(b.offset, b.size).noalias() += b.B * du;
    }
    const std::size_t m = static_cast<std::size_t>(m_points);
    const std::size_t hslot = historySlot(m_nextStep - 1);
    std::copy_n(appliedMm.data(), m, m_historyApplied.begin() + static_cast<std::ptrdiff_t>(hslot * m));
    m_lastApplied = appliedMm;
}

std::uint16_t LqgController::fingerprint() const {
    std::vector<double> config{static_cast<double>(m_points),
                               static_cast<double>(m_delay),
                               static_cast<double>(m_states),
                               static_cast<double>(m_options.historyParts),
                               m_options.gateSigma,
                               m_limits.maxAbsMm,
                               m_limits.maxStepMm};
    for (const Block& b : m_blocks) {
        config.insert(config.end(), b.K.data(), b.K.data() + b.K.size());
        config.insert(config.end(), b.L.data(), b.L.data() + b.L.size());
        config.insert(config.end(), b.A.data(), b.A.data() + b.A.size());
        config.insert(config.end(), b.P.data(), b.P.data() + b.P.size());
    }
    return configurationFingerprint(config);
}

ControllerState LqgController::saveState() const {
    ControllerState s;
    s.kind = name();
    std::vector<double>& v = s.values;
    v = {kStateFormat,
         static_cast<double>(fingerprint()),
         m_started ? 1.0 : 0.0,
         static_cast<double>(m_firstPart),
         static_cast<double>(m_lastPart),
         static_cast<double>(m_nextStep)};
    auto pushValues = [&v](const auto& values) {
        for (const auto x : values)
            v.push_back(static_cast<double>(x));
    };
    auto pushSteps = [&v](const std::vector<std::int64_t>& steps) {
        for (std::int64_t st : steps) {
            v.push_back(st == kNoStep ? -1.0 : 0.0);
            v.push_back(st == kNoStep ? 0.0 : static_cast<double>(st));
        }
    };
    v.insert(v.end(), m_prior.x.data(), m_prior.x.data() + m_prior.x.size());
    pushValues(m_prior.cov);
    pushValues(m_prior.steady);
    v.insert(v.end(), m_lastApplied.data(), m_lastApplied.data() + m_lastApplied.size());
    for (bool l : m_lastLimited)
        v.push_back(l ? 1.0 : 0.0);
    pushSteps(m_pendingStep);
    pushValues(m_pendingValue);
    pushValues(m_pendingHas);
    pushSteps(m_historyStep);
    pushValues(m_historyX);
    pushValues(m_historyCov);
    pushValues(m_historySteady);
    pushValues(m_historyValue);
    pushValues(m_historyHas);
    pushValues(m_historyApplied);
    return s;
}

void LqgController::restoreState(const ControllerState& state) {
    if (state.kind != name())
        throw std::invalid_argument("cannot restore a '" + state.kind + "' controller state into the LQG controller");
    for (double x : state.values)
        if (!std::isfinite(x)) throw std::invalid_argument("saved LQG controller state contains a NaN or Inf");
    StateReader r(state.values);
    if (r.next() != kStateFormat) throw std::invalid_argument("saved LQG controller state has an unknown format");
    if (r.next() != static_cast<double>(fingerprint()))
        throw std::invalid_argument(
            "saved LQG controller state belongs to a different configuration (plant, weights, limits or options "
            "changed)");
    LqgController restored = *this;
    auto readValues = [&r](auto& values) {
        using T = typename std::decay_t<decltype(values)>::value_type;
        for (auto& x : values)
            x = static_cast<T>(r.next());
    };
    auto readSteps = [&r](std::vector<std::int64_t>& steps) {
        for (std::int64_t& st : steps)
            st = r.nextStep();
    };
    restored.m_started = r.next() != 0.0;
    restored.m_firstPart = static_cast<std::int64_t>(r.next());
    restored.m_lastPart = static_cast<std::int64_t>(r.next());
    restored.m_nextStep = static_cast<std::int64_t>(r.next());
    for (Eigen::Index i = 0; i < m_states; ++i)
        restored.m_prior.x(i) = r.next();
    readValues(restored.m_prior.cov);
    readValues(restored.m_prior.steady);
    for (Eigen::Index i = 0; i < m_points; ++i)
        restored.m_lastApplied(i) = r.next();
    for (Eigen::Index i = 0; i < m_points; ++i)
        restored.m_lastLimited(i) = r.next() != 0.0;
    readSteps(restored.m_pendingStep);
    readValues(restored.m_pendingValue);
    readValues(restored.m_pendingHas);
    readSteps(restored.m_historyStep);
    readValues(restored.m_historyX);
    readValues(restored.m_historyCov);
    readValues(restored.m_historySteady);
    readValues(restored.m_historyValue);
    readValues(restored.m_historyHas);
    readValues(restored.m_historyApplied);
    if (!r.atEnd()) throw std::invalid_argument("saved LQG controller state is longer than expected");
    *this = std::move(restored);
}

}  // namespace tt::core
