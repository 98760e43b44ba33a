#include "core/control/plant_identification.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Cholesky>

#include "core/common/text_format.h"
#include "core/control/run_to_run_plant.h"

namespace tt::core {

namespace {

/// The first prediction errors of every model are left out of the criteria (the conditional start: e = 0
/// before the first value), the same number for every model compared.
constexpr int kSkippedErrors = 10;
/// Most parts a refusal asks for (beyond that it says "many").
constexpr std::int64_t kMaxPartsNeeded = 1'000'000;
/// The relaxation: rounds of gain-then-noise at fixed orders, searches of the orders, and when the gain has settled.
constexpr int kMaxRelaxationRounds = 200;
constexpr int kMaxOrderSearches = 5;
constexpr double kRelaxationTolerance = 1e-5;
/// Criteria closer than this are a tie (about a likelihood ratio of e): the candidate nearer the loop's model wins.
constexpr double kCriterionTie = 2.0;
/// The disturbance the loop had is replaced only when a re-identified one beats it by this much in the criterion
/// ("very strong" evidence on Kass and Raftery's scale for the BIC): in closed loop, a re-identified disturbance
/// with another gain can fit about as well without being the plant.
constexpr double kReplaceDisturbanceEvidence = 10.0;

/// The longest stretch [first, last] of record indices with a finite deviation at `point`, starting at
/// `earliest` or later.
std::pair<std::size_t, std::size_t> longestStretch(const LoopHistory& h, int point, std::size_t earliest) {
    std::size_t bestFirst = 0, bestLength = 0, first = earliest, length = 0;
    for (std::size_t t = earliest; t < h.size(); ++t) {
        if (std::isfinite(h.deviationMm[t](point))) {
            if (length == 0) first = t;
            if (++length > bestLength) {
                bestLength = length;
                bestFirst = first;
            }
        } else {
            length = 0;
        }
    }
    return {bestFirst, bestFirst + bestLength};  // [first, end)
}

std::int64_t partsFor(double have, double factor) {
    const double more = std::ceil(have * factor - have);
    return more >= static_cast<double>(kMaxPartsNeeded) ? kMaxPartsNeeded
                                                        : std::max<std::int64_t>(1, static_cast<std::int64_t>(more));
}

std::string pointName(int point) {
    return "point " + std::to_string(point + 1);
}

struct PointData {
    std::vector<double> y;               ///< deviations of the stretch
    std::vector<std::vector<double>> u;  ///< per lag: the correction acting on each part of it
    std::int64_t firstPart = 0, lastPart = 0;
};

PointData pointData(const LoopHistory& h, int point, int maxLag, const PlantIdentificationOptions& o) {
    const auto [first, end] = longestStretch(h, point, static_cast<std::size_t>(maxLag));
    const std::size_t length = end - first;
    if (length < o.minParts)
        throw IdentificationRefused(pointName(point) + ": " + std::to_string(length) +
                                        " consecutive measured parts, the identification needs " +
                                        std::to_string(o.minParts) + "; about " + std::to_string(o.minParts - length) +
                                        " parts more",
                                    static_cast<std::int64_t>(o.minParts - length));
    PointData d;
    d.firstPart = h.firstPart + static_cast<std::int64_t>(first);
    d.lastPart = h.firstPart + static_cast<std::int64_t>(end) - 1;
    d.u.assign(static_cast<std::size_t>(maxLag) + 1, {});
    for (std::size_t t = first; t < end; ++t) {
        d.y.push_back(h.deviationMm[t](point));
        for (int lag = 0; lag <= maxLag; ++lag)
            d.u[static_cast<std::size_t>(lag)].push_back(h.appliedMm[t - static_cast<std::size_t>(lag)](point));
    }
    const auto [lo, hi] = std::minmax_element(d.u[0].begin(), d.u[0].end());
    if (*hi - *lo < 1e-9)
        throw IdentificationRefused(pointName(point) + ": the corrections did not change over parts " +
                                        std::to_string(d.firstPart) + " .. " + std::to_string(d.lastPart) +
                                        ", so the plant's gain cannot be told; switch on the dither",
                                    0);
    return d;
}

double criterionValue(const InputArmaFit& fit, InformationCriterion c) {
    const double n = static_cast<double>(fit.residuals.size() - kSkippedErrors);
    const double k = fit.parameters;
    return fit.logLikelihoodTerm + (c == InformationCriterion::Aic ? 2.0 * k : k * std::log(n));
}

/// The gain and the mean by least squares on the series filtered by the noise model's inverse A(q) / C(q) (the
/// prediction errors are then linear in them).
std::pair<double, double> filteredGain(const std::vector<double>& y, const std::vector<double>& u,
                                       const std::vector<double>& ar, const std::vector<double>& ma) {
    const std::size_t n = y.size();
    auto filter = [&](auto value) {
        std::vector<double> raw(n), out(n);
        for (std::size_t t = 0; t < n; ++t) {
            raw[t] = value(t);
            double v = raw[t];
            for (std::size_t i = 1; i <= ar.size() && i <= t; ++i)
                v -= ar[i - 1] * raw[t - i];
            for (std::size_t j = 1; j <= ma.size() && j <= t; ++j)
                v -= ma[j - 1] * out[t - j];
            out[t] = v;
        }
        return out;
    };
    const std::vector<double> yf = filter([&](std::size_t t) { return y[t]; });
    const std::vector<double> uf = filter([&](std::size_t t) { return u[t]; });
    const std::vector<double> one = filter([](std::size_t) { return 1.0; });
    Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    for (std::size_t t = kSkippedErrors; t < n; ++t) {
        const Eigen::Vector2d x(uf[t], one[t]);
        M += x * x.transpose();
        b += x * yf[t];
    }
    const Eigen::Vector2d theta = M.ldlt().solve(b);
    return {theta(0), theta(1)};
}

/// The point's model at fixed orders for the gain `gain`: the ARMA of y - gain u.
std::optional<PointPlantFit> atGain(const PointData& d, int lag, double gain, ArmaOrders orders,
                                    const PlantIdentificationOptions& o) {
    const std::vector<double>& u = d.u[static_cast<std::size_t>(lag)];
    std::vector<double> w(d.y.size());
    for (std::size_t t = 0; t < w.size(); ++t)
        w[t] = d.y[t] - gain * u[t];
    try {
        const ArmaFit noise = fitArma(w, orders);
        PointPlantFit p;
        p.fit = evaluateInputArma(d.y, u, gain, noise.meanMm, noise.ar, noise.ma, kSkippedErrors);
        p.orders = orders;
        p.criterion = criterionValue(p.fit, o.criterion);
        return p;
    } catch (const std::invalid_argument&) {
        return std::nullopt;  // a constant series: this order cannot be fitted
    }
}

/// The orders the criterion prefers at the gain `gain`.
PointPlantFit bestOrdersAt(const PointData& d, int lag, double gain, const PlantIdentificationOptions& o) {
    PointPlantFit best;
    best.criterion = std::numeric_limits<double>::infinity();
    for (int p = 0; p <= o.maxArmaOrder; ++p)
        for (int q = 0; q <= o.maxArmaOrder; ++q)
            if (std::optional<PointPlantFit> f = atGain(d, lag, gain, {p, q}, o); f && f->criterion < best.criterion)
                best = std::move(*f);
    return best;
}

/// The point's model with the disturbance the loop had (ARMA `ar`, `ma`): the gain and the mean by least squares on
/// the series filtered by its inverse, the noise variance from the residuals; none when that ARMA is not admissible.
std::optional<PointPlantFit> keptDisturbance(const PointData& d, int lag, const std::vector<double>& ar,
                                             const std::vector<double>& ma, const PlantIdentificationOptions& o) {
    const int p = static_cast<int>(ar.size());
    const int q = static_cast<int>(ma.size());
    if (p > kMaxArmaOrder || q > kMaxArmaOrder) return std::nullopt;
    Eigen::VectorXd theta(p + q);
    for (int i = 0; i < p; ++i)
        theta(i) = ar[static_cast<std::size_t>(i)];
    for (int j = 0; j < q; ++j)
        theta(p + j) = ma[static_cast<std::size_t>(j)];
    if (!armaAdmissible(theta, p, q)) return std::nullopt;
    const std::vector<double>& u = d.u[static_cast<std::size_t>(lag)];
    const auto [gain, mean] = filteredGain(d.y, u, ar, ma);
    PointPlantFit f;
    f.fit = evaluateInputArma(d.y, u, gain, mean, ar, ma, kSkippedErrors, true);
    f.orders = {p, q};
    f.criterion = criterionValue(f.fit, o.criterion);
    f.disturbanceKept = true;
    return f;
}

/// The prediction-error fit of one point at one lag by relaxation from the model the loop uses (gain `prior`,
/// noise `priorAr` / `priorMa`): the gain by least squares on the series filtered by the noise model's inverse,
/// then the noise for that gain (the orders by the criterion), until neither changes. The fixed point is a
/// stationary point of the joint prediction-error criterion; where closed-loop data cannot tell a gain change from a
/// noise change (a flat valley of the criterion), it stays near the model the loop had, and the standard error of
/// the gain (from the joint J'J) says how little the data tell. The disturbance the loop had is a candidate too
/// (keptDisturbance), chosen when the criterion prefers it.
PointPlantFit relaxFrom(const PointData& d, int lag, double start, const std::vector<double>& startAr,
                        const std::vector<double>& startMa, const PlantIdentificationOptions& o) {
    const double prior = start;
    const std::vector<double>& priorAr = startAr;
    const std::vector<double>& priorMa = startMa;
    const std::vector<double>& u = d.u[static_cast<std::size_t>(lag)];
    double gain = std::isfinite(prior) ? prior : 0.0;
    std::vector<double> ar = priorAr, ma = priorMa;
    ArmaOrders orders{static_cast<int>(ar.size()), static_cast<int>(ma.size())};
    if (orders.ar > o.maxArmaOrder || orders.ma > o.maxArmaOrder) {
        ar.clear();
        ma.clear();
        orders = {0, 0};
    }
    PointPlantFit fit;
    for (int search = 0; search < kMaxOrderSearches; ++search) {
        for (int round = 0; round < kMaxRelaxationRounds; ++round) {
            const double previous = gain;
            gain = filteredGain(d.y, u, ar, ma).first;
            const std::optional<PointPlantFit> f = atGain(d, lag, gain, orders, o);
            if (!f) break;
            ar = f->fit.noise.ar;
            ma = f->fit.noise.ma;
            if (std::abs(gain - previous) <= kRelaxationTolerance * (std::abs(gain) + 1e-12)) break;
        }
        fit = bestOrdersAt(d, lag, gain, o);
        const bool same = fit.orders.ar == orders.ar && fit.orders.ma == orders.ma;
        orders = fit.orders;
        ar = fit.fit.noise.ar;
        ma = fit.fit.noise.ma;
        if (same) break;
    }
    return fit;
}

/// The best of the candidates of one point at one lag: relaxed from the model the loop had, relaxed from a joint
/// Gauss-Newton fit, and the model the loop had with only its gain re-estimated (ties go to the model the loop had).
PointPlantFit relax(const PointData& d, int point, int lag, double prior, const std::vector<double>& priorAr,
                    const std::vector<double>& priorMa, const PlantIdentificationOptions& o) {
    const bool havePrior = std::isfinite(prior);
    PointPlantFit fit = relaxFrom(d, lag, havePrior ? prior : 0.0, priorAr, priorMa, o);
    try {
        const InputArmaFit joint = fitInputArma(
            d.y, d.u[static_cast<std::size_t>(lag)], {std::min(1, o.maxArmaOrder), std::min(1, o.maxArmaOrder)},
            havePrior ? std::optional<double>(prior) : std::nullopt, kSkippedErrors);
        PointPlantFit other = relaxFrom(d, lag, joint.gain, joint.noise.ar, joint.noise.ma, o);
        if (other.criterion < fit.criterion - kCriterionTie) fit = std::move(other);
    } catch (const std::invalid_argument&) {
        // the joint fit cannot start (a constant series): the relaxation from the model stands
    }
    // The disturbance model the loop had, with only the gain, the mean and the noise variance re-estimated: a
    // candidate with 2 parameters that the criterion weighs against the re-identified ones.
    if (havePrior) {
        if (std::optional<PointPlantFit> kept = keptDisturbance(d, lag, priorAr, priorMa, o);
            kept && kept->criterion < fit.criterion + kReplaceDisturbanceEvidence)
            fit = std::move(*kept);
    }
    fit.point = point;
    fit.firstPart = d.firstPart;
    fit.lastPart = d.lastPart;
    return fit;
}

void checkGains(const PlantIdentification& id, const PlantIdentificationOptions& o) {
    std::int64_t needed = 0;
    std::string worst;
    double worstShare = 0.0;
    for (const PointPlantFit& p : id.points) {
        const double g = p.fit.gain;
        if (!(g > 0.0))
            throw IdentificationRefused(pointName(p.point) + ": the identified gain is " + formatSignificant(g, 3) +
                                            " ± " + formatSignificant(p.fit.gainStdErr, 2) +
                                            ", not positive: the corrections do not explain the measurements yet",
                                        partsFor(static_cast<double>(p.fit.residuals.size()), 2.0));
        const double share = p.fit.gainStdErr / g;
        if (share > o.maxGainRelativeStdErr && share > worstShare) {
            worstShare = share;
            const double n = static_cast<double>(p.fit.residuals.size());
            needed = partsFor(n, (share / o.maxGainRelativeStdErr) * (share / o.maxGainRelativeStdErr));
            worst = pointName(p.point) + ": the gain is " + formatSignificant(g, 3) + " ± " +
                    formatSignificant(p.fit.gainStdErr, 2) + " (" + formatFixed(100.0 * share, 1) +
                    " % standard error, at most " + formatFixed(100.0 * o.maxGainRelativeStdErr, 1) +
                    " % is needed); about " + std::to_string(needed) + " parts more";
        }
    }
    if (!worst.empty()) throw IdentificationRefused(worst, needed);
}

Eigen::MatrixXd predictionErrorCorrelation(const std::vector<PointPlantFit>& points) {
    const auto m = static_cast<Eigen::Index>(points.size());
    std::int64_t first = std::numeric_limits<std::int64_t>::min(), last = std::numeric_limits<std::int64_t>::max();
    for (const PointPlantFit& p : points) {
        first = std::max(first, p.firstPart + kSkippedErrors);
        last = std::min(last, p.lastPart);
    }
    if (last - first < 20) return Eigen::MatrixXd::Identity(m, m);
    Eigen::MatrixXd E(last - first + 1, m);
    for (Eigen::Index i = 0; i < m; ++i) {
        const PointPlantFit& p = points[static_cast<std::size_t>(i)];
        for (std::int64_t k = first; k <= last; ++k)
            E(k - first, i) = p.fit.residuals[static_cast<std::size_t>(k - p.firstPart)];
    }
    const Eigen::MatrixXd centred = E.rowwise() - E.colwise().mean();
    const Eigen::MatrixXd cov = centred.transpose() * centred;
    const Eigen::VectorXd scale = cov.diagonal().cwiseSqrt().cwiseInverse();
    Eigen::MatrixXd r = scale.asDiagonal() * cov * scale.asDiagonal();
    r.diagonal().setOnes();
    return r.allFinite() ? r : Eigen::MatrixXd::Identity(m, m);
}

}  // namespace

const char* informationCriterionName(InformationCriterion criterion) {
    return criterion == InformationCriterion::Aic ? "aic" : "bic";
}

InformationCriterion informationCriterionFromName(const std::string& name) {
    if (name == "aic") return InformationCriterion::Aic;
    if (name == "bic") return InformationCriterion::Bic;
    throw std::invalid_argument("unknown information criterion '" + name + "' (aic, bic)");
}

void PlantIdentificationOptions::validate(std::size_t points) const {
    if (loopDelay < 1 || loopDelay > kMaxDelay)
        throw std::invalid_argument("the loop's delay must be 1 .. " + std::to_string(kMaxDelay) + " parts, got " +
                                    std::to_string(loopDelay));
    if (maxExtraLag < 0 || maxExtraLag > 4)
        throw std::invalid_argument("the extra plant delay tried must be 0 .. 4 parts, got " +
                                    std::to_string(maxExtraLag));
    if (maxArmaOrder < 0 || maxArmaOrder > kMaxArmaOrder)
        throw std::invalid_argument("the largest ARMA order must be 0 .. " + std::to_string(kMaxArmaOrder) + ", got " +
                                    std::to_string(maxArmaOrder));
    if (!priorGain.empty() && priorGain.size() != points)
        throw std::invalid_argument("one prior gain per control point is needed: " + std::to_string(points) + ", got " +
                                    std::to_string(priorGain.size()));
    if ((!priorAr.empty() && priorAr.size() != points) || (!priorMa.empty() && priorMa.size() != points))
        throw std::invalid_argument("one prior disturbance per control point is needed: " + std::to_string(points));
    if (!(maxGainRelativeStdErr > 0.0 && maxGainRelativeStdErr <= 1.0))
        throw std::invalid_argument("the largest standard error of a gain must be in (0, 1] of the gain");
    if (!(minDelayEvidence >= 0.0 && std::isfinite(minDelayEvidence)))
        throw std::invalid_argument("the evidence asked for the delay must be >= 0");
    if (minParts < kMinInputArmaValues + kSkippedErrors || minParts > 1'000'000)
        throw std::invalid_argument("the identification needs at least " +
                                    std::to_string(kMinInputArmaValues + kSkippedErrors) + " parts, got " +
                                    std::to_string(minParts));
}

PlantIdentification identifyPlant(const LoopHistory& h, const PlantIdentificationOptions& o) {
    if (h.appliedMm.size() != h.deviationMm.size())
        throw std::invalid_argument("the record has " + std::to_string(h.appliedMm.size()) + " corrections and " +
                                    std::to_string(h.deviationMm.size()) + " measurements");
    if (h.appliedMm.empty())
        throw IdentificationRefused("no part was recorded yet; the identification needs " + std::to_string(o.minParts),
                                    static_cast<std::int64_t>(o.minParts));
    const auto m = static_cast<std::size_t>(h.appliedMm.front().size());
    for (std::size_t t = 0; t < h.size(); ++t)
        if (static_cast<std::size_t>(h.appliedMm[t].size()) != m ||
            static_cast<std::size_t>(h.deviationMm[t].size()) != m)
            throw std::invalid_argument("part " + std::to_string(h.firstPart + static_cast<std::int64_t>(t)) +
                                        " of the record has another number of control points");
    o.validate(m);
    const int maxLag = std::min(o.maxExtraLag, kMaxDelay - o.loopDelay);
    std::vector<PointData> data;
    for (std::size_t i = 0; i < m; ++i)
        data.push_back(pointData(h, static_cast<int>(i), maxLag, o));

    PlantIdentification id;
    id.loopDelay = o.loopDelay;
    id.criterion = o.criterion;
    id.parts = h.size();
    std::vector<std::vector<PointPlantFit>> byLag(static_cast<std::size_t>(maxLag) + 1);
    for (int lag = 0; lag <= maxLag; ++lag) {
        double score = 0.0;
        for (std::size_t i = 0; i < m; ++i) {
            const double prior = o.priorGain.empty() ? std::numeric_limits<double>::quiet_NaN() : o.priorGain[i];
            const std::vector<double> noAr, noMa;
            byLag[static_cast<std::size_t>(lag)].push_back(relax(data[i], static_cast<int>(i), lag, prior,
                                                                 o.priorAr.empty() ? noAr : o.priorAr[i],
                                                                 o.priorMa.empty() ? noMa : o.priorMa[i], o));
            score += byLag[static_cast<std::size_t>(lag)].back().criterion;
        }
        id.lagScores.push_back(score);
    }
    // The model's lag stays unless the data clearly prefer another one (in closed loop near minimum variance a lag can
    // fit about as well as another without being the plant's).
    const int prior = std::clamp(o.priorLag, 0, maxLag);
    const auto best = std::min_element(id.lagScores.begin(), id.lagScores.end());
    const int bestLag = static_cast<int>(best - id.lagScores.begin());
    id.lagParts = id.lagScores[static_cast<std::size_t>(prior)] - *best < o.minDelayEvidence ? prior : bestLag;
    const double chosen = id.lagScores[static_cast<std::size_t>(id.lagParts)];
    id.delayEvidence = std::numeric_limits<double>::infinity();
    for (std::size_t lag = 0; lag < id.lagScores.size(); ++lag)
        if (static_cast<int>(lag) != id.lagParts)
            id.delayEvidence = std::min(id.delayEvidence, id.lagScores[lag] - chosen);
    id.points = std::move(byLag[static_cast<std::size_t>(id.lagParts)]);
    if (id.lagParts != prior && id.delayEvidence < o.minDelayEvidence) {
        const double n = static_cast<double>(data.front().y.size());
        const std::int64_t needed = partsFor(n, o.minDelayEvidence / std::max(id.delayEvidence, 0.5));
        throw IdentificationRefused("the plant delay is not clear yet: " + std::to_string(id.delayParts()) +
                                        " parts fits better than the next delay by " +
                                        formatSignificant(id.delayEvidence, 3) + " in the criterion, " +
                                        formatSignificant(o.minDelayEvidence, 3) + " is needed; about " +
                                        std::to_string(needed) + " parts more",
                                    needed);
    }
    checkGains(id, o);
    id.innovationCorrelation = predictionErrorCorrelation(id.points);
    return id;
}

DisturbanceModel identifiedDisturbance(const PointPlantFit& point) {
    return point.fit.noise.disturbanceModel();
}

}  // namespace tt::core
