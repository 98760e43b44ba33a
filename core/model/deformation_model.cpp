#include "core/model/deformation_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tt::core {

namespace {

constexpr int kMaxPower = 3;
constexpr Eigen::Index kMaxRows = 1000000;
const char* const kFactorSymbol[3] = {"a", "f", "z"};
const char* const kFactorWords[3] = {"depths of cut a", "feeds f", "axial positions z"};

int powerOf(const DeformationTerm& t, int factor) {
    return factor == 0 ? t.depthPower : (factor == 1 ? t.feedPower : t.axialPower);
}

double integerPower(double x, int n) {
    double r = 1.0;
    for (int i = 0; i < n; ++i)
        r *= x;
    return r;
}

std::string number(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

void checkColumn(const Eigen::VectorXd& v, const char* what, const char* unit, double lo, double hi, bool openLow) {
    for (Eigen::Index i = 0; i < v.size(); ++i) {
        const double x = v(i);
        const bool below = openLow ? !(x > lo) : !(x >= lo);
        if (!std::isfinite(x) || below || x > hi)
            throw std::invalid_argument("row " + std::to_string(i + 1) + ": " + what + " " + number(x) + " " + unit +
                                        " is outside " + (openLow ? "(" : "[") + number(lo) + ", " + number(hi) + "] " +
                                        unit);
    }
}

int distinctLevels(const Eigen::VectorXd& v) {
    Eigen::VectorXd sorted = v;
    std::sort(sorted.data(), sorted.data() + sorted.size());
    return static_cast<int>(std::unique(sorted.data(), sorted.data() + sorted.size()) - sorted.data());
}

Eigen::MatrixXd designMatrix(const DeformationModel& shape, const DeformationSamples& s) {
    Eigen::MatrixXd x(s.size(), static_cast<Eigen::Index>(shape.terms().size()));
    for (Eigen::Index i = 0; i < s.size(); ++i)
        x.row(i) = shape.termRow(s.depthMm(i), s.feedMmPerRev(i), s.zMm(i)).transpose();
    return x;
}

/// The terms of `terms` that the levels of the data can separate; throws naming the first that cannot.
void checkLevels(const std::vector<DeformationTerm>& terms, const std::array<int, 3>& levels) {
    for (const DeformationTerm& t : terms)
        for (int factor = 0; factor < 3; ++factor)
            if (powerOf(t, factor) + 1 > levels[static_cast<std::size_t>(factor)])
                throw std::invalid_argument(
                    "the term " + t.name() + " needs at least " + std::to_string(powerOf(t, factor) + 1) +
                    " different " + kFactorWords[factor] + "; the data has " +
                    std::to_string(levels[static_cast<std::size_t>(factor)]) + " (choose fewer terms or add levels)");
}

}  // namespace

std::string DeformationTerm::name() const {
    if (degree() == 0) return "1";
    std::string out;
    for (int factor = 0; factor < 3; ++factor) {
        const int p = powerOf(*this, factor);
        if (p == 0) continue;
        if (!out.empty()) out += "*";
        out += kFactorSymbol[factor];
        if (p > 1) {
            out += '^';
            out += std::to_string(p);
        }
    }
    return out;
}

std::vector<DeformationTerm> deformationTerms(DeformationTermSet set) {
    std::vector<DeformationTerm> t = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    switch (set) {
        case DeformationTermSet::Linear:
            break;
        case DeformationTermSet::Interactions:
            t.insert(t.end(), {{1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}});
            break;
        case DeformationTermSet::Quadratic:
            t.insert(t.end(), {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}});
            break;
        case DeformationTermSet::CubicZ: {
            const std::array<std::pair<int, int>, 6> af = {{{0, 0}, {1, 0}, {0, 1}, {2, 0}, {0, 2}, {1, 1}}};
            t.clear();
            for (int k = 0; k <= 3; ++k)
                for (const auto& [i, j] : af)
                    t.push_back({i, j, k});
            break;
        }
        case DeformationTermSet::CubicFZ:
            t.clear();
            for (int k = 0; k <= 3; ++k)
                for (int j = 0; j <= 3; ++j)
                    t.push_back({0, j, k});
            break;
    }
    return t;
}

std::string deformationTermSetName(DeformationTermSet set) {
    switch (set) {
        case DeformationTermSet::Linear:
            return "linear";
        case DeformationTermSet::Interactions:
            return "interactions";
        case DeformationTermSet::Quadratic:
            return "quadratic";
        case DeformationTermSet::CubicZ:
            return "cubic-z";
        case DeformationTermSet::CubicFZ:
            break;
    }
    return "cubic-fz";
}

DeformationTermSet deformationTermSetFromName(const std::string& name) {
    for (DeformationTermSet s :
         {DeformationTermSet::Linear, DeformationTermSet::Interactions, DeformationTermSet::Quadratic,
          DeformationTermSet::CubicZ, DeformationTermSet::CubicFZ})
        if (deformationTermSetName(s) == name) return s;
    throw std::invalid_argument("unknown term set '" + name + "' (linear, interactions, quadratic, cubic-z, cubic-fz)");
}

FactorCoding FactorCoding::spanning(double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
        throw std::invalid_argument("a factor's range must be finite with its minimum below its maximum (got " +
                                    number(lo) + " .. " + number(hi) + ")");
    return {0.5 * (lo + hi), 0.5 * (hi - lo), lo, hi};
}

FactorCoding FactorCoding::at(double value) {
    if (!std::isfinite(value)) throw std::invalid_argument("a factor held at one value needs a finite value");
    return {value, 1.0, value, value};
}

DeformationModel::DeformationModel(std::array<FactorCoding, 3> coding, std::vector<DeformationTerm> terms,
                                   Eigen::VectorXd coefficients)
    : m_coding(coding), m_terms(std::move(terms)), m_coefficients(std::move(coefficients)) {
    if (m_terms.empty() || m_terms.front().degree() != 0)
        throw std::invalid_argument("the deformation model's first term must be the intercept");
    if (static_cast<Eigen::Index>(m_terms.size()) != m_coefficients.size())
        throw std::invalid_argument("the deformation model has " + std::to_string(m_terms.size()) + " terms but " +
                                    std::to_string(m_coefficients.size()) + " coefficients");
    if (!m_coefficients.allFinite())
        throw std::invalid_argument("a coefficient of the deformation model is not finite");
    for (std::size_t i = 0; i < m_terms.size(); ++i) {
        const DeformationTerm& t = m_terms[i];
        for (int factor = 0; factor < 3; ++factor)
            if (powerOf(t, factor) < 0 || powerOf(t, factor) > kMaxPower)
                throw std::invalid_argument("the term " + t.name() + " has a power outside 0 .. 3");
        if (i > 0 && t.degree() == 0) throw std::invalid_argument("the intercept appears twice in the model");
        if (std::find(m_terms.begin(), m_terms.begin() + static_cast<std::ptrdiff_t>(i), t) !=
            m_terms.begin() + static_cast<std::ptrdiff_t>(i))
            throw std::invalid_argument("the term " + t.name() + " appears twice in the model");
    }
    for (int factor = 0; factor < 3; ++factor) {
        const FactorCoding& c = m_coding[static_cast<std::size_t>(factor)];
        if (!std::isfinite(c.centre) || !std::isfinite(c.halfRange) || !(c.halfRange > 0.0) || !std::isfinite(c.min) ||
            !std::isfinite(c.max) || !(c.min <= c.max))
            throw std::invalid_argument("a factor coding of the deformation model is not valid");
        if (c.fixed())
            for (const DeformationTerm& t : m_terms)
                if (powerOf(t, factor) > 0)
                    throw std::invalid_argument(std::string("the term ") + t.name() + " uses " + kFactorSymbol[factor] +
                                                ", which the model holds at " + number(c.min) + " only");
    }
}

Eigen::VectorXd DeformationModel::termRow(double depthMm, double feedMmPerRev, double zMm) const {
    const double x[3] = {coding(DeformationFactor::Depth).coded(depthMm),
                         coding(DeformationFactor::Feed).coded(feedMmPerRev),
                         coding(DeformationFactor::Axial).coded(zMm)};
    Eigen::VectorXd row(static_cast<Eigen::Index>(m_terms.size()));
    for (std::size_t k = 0; k < m_terms.size(); ++k) {
        const DeformationTerm& t = m_terms[k];
        row(static_cast<Eigen::Index>(k)) =
            integerPower(x[0], t.depthPower) * integerPower(x[1], t.feedPower) * integerPower(x[2], t.axialPower);
    }
    return row;
}

double DeformationModel::deformationUm(double depthMm, double feedMmPerRev, double zMm) const {
    return termRow(depthMm, feedMmPerRev, zMm).dot(m_coefficients);
}

ScaledPolynomial DeformationModel::slice(DeformationFactor free, double depthMm, double feedMmPerRev,
                                         double zMm) const {
    const int freeIndex = static_cast<int>(free);
    const double x[3] = {coding(DeformationFactor::Depth).coded(depthMm),
                         coding(DeformationFactor::Feed).coded(feedMmPerRev),
                         coding(DeformationFactor::Axial).coded(zMm)};
    Eigen::VectorXd c = Eigen::VectorXd::Zero(kMaxPower + 1);
    for (std::size_t k = 0; k < m_terms.size(); ++k) {
        double factor = m_coefficients(static_cast<Eigen::Index>(k));
        for (int other = 0; other < 3; ++other)
            if (other != freeIndex) factor *= integerPower(x[other], powerOf(m_terms[k], other));
        c(powerOf(m_terms[k], freeIndex)) += factor;
    }
    const FactorCoding& coding = m_coding[static_cast<std::size_t>(freeIndex)];
    return ScaledPolynomial(c, coding.centre, coding.halfRange);
}

ScaledPolynomial DeformationModel::alongAxis(double depthMm, double feedMmPerRev) const {
    return slice(DeformationFactor::Axial, depthMm, feedMmPerRev, 0.0);
}

ScaledPolynomial DeformationModel::againstFeed(double depthMm, double zMm) const {
    return slice(DeformationFactor::Feed, depthMm, 0.0, zMm);
}

Eigen::Index DeformationSamples::size() const {
    const Eigen::Index n = depthMm.size();
    if (feedMmPerRev.size() != n || zMm.size() != n || deformationUm.size() != n)
        throw std::invalid_argument("the deformation samples have columns of different lengths");
    return n;
}

namespace {

/// Checks the columns' values and returns, per factor, the number of different levels.
std::array<int, 3> checkedLevels(const DeformationSamples& samples) {
    const Eigen::Index n = samples.size();
    if (n > kMaxRows)
        throw std::invalid_argument("at most " + std::to_string(kMaxRows) + " measurements can be fitted (got " +
                                    std::to_string(n) + ")");
    checkColumn(samples.depthMm, "the depth of cut", "mm", 0.0, 20.0, true);
    checkColumn(samples.feedMmPerRev, "the feed", "mm/rev", 0.0, 5.0, true);
    checkColumn(samples.zMm, "the axial position", "mm", -10000.0, 10000.0, false);
    checkColumn(samples.deformationUm, "the deformation", "µm", -1e6, 1e6, false);
    const std::array<const Eigen::VectorXd*, 3> columns = {&samples.depthMm, &samples.feedMmPerRev, &samples.zMm};
    std::array<int, 3> levels{};
    for (std::size_t f = 0; f < 3; ++f)
        levels[f] = columns[f]->size() > 0 ? distinctLevels(*columns[f]) : 0;
    return levels;
}

/// Whether some term of `terms` has a power of `factor`.
bool usesFactor(const std::vector<DeformationTerm>& terms, int factor) {
    return std::any_of(terms.begin(), terms.end(),
                       [factor](const DeformationTerm& t) { return powerOf(t, factor) > 0; });
}

/// The least-squares fit (with the stepwise elimination) on the given coding.
DeformationFit fitCoded(const DeformationSamples& samples, DeformationTermSet set, bool stepwise,
                        const std::array<FactorCoding, 3>& coding, std::vector<DeformationTerm> terms) {
    std::vector<RemovedTerm> removed;
    for (;;) {
        const DeformationModel shape(coding, terms, Eigen::VectorXd::Zero(static_cast<Eigen::Index>(terms.size())));
        LinearRegression regression = fitLinearRegression(designMatrix(shape, samples), samples.deformationUm);
        Eigen::Index weakest = 0;
        if (stepwise && terms.size() > 2) {
            double smallest = regression.tCritical95;
            for (Eigen::Index k = 1; k < regression.tValues.size(); ++k)
                if (std::abs(regression.tValues(k)) < smallest) {
                    smallest = std::abs(regression.tValues(k));
                    weakest = k;
                }
        }
        if (weakest == 0) {
            DeformationModel model(coding, terms, regression.coefficients);
            return {std::move(model), std::move(regression), set, stepwise, std::move(removed)};
        }
        removed.push_back({terms[static_cast<std::size_t>(weakest)], std::abs(regression.tValues(weakest))});
        terms.erase(terms.begin() + weakest);
    }
}

void requireLevels(const std::vector<DeformationTerm>& terms, const std::array<int, 3>& levels) {
    for (int f = 0; f < 3; ++f)
        if (levels[static_cast<std::size_t>(f)] < 2 && usesFactor(terms, f))
            throw std::invalid_argument(std::string("the experiment needs at least 2 different ") + kFactorWords[f] +
                                        "; the data has " + std::to_string(levels[static_cast<std::size_t>(f)]));
    checkLevels(terms, levels);
}

}  // namespace

DeformationFit fitDeformationModel(const DeformationSamples& samples, DeformationTermSet set, bool stepwise) {
    const std::array<int, 3> levels = checkedLevels(samples);
    const std::vector<DeformationTerm> terms = deformationTerms(set);
    requireLevels(terms, levels);
    const std::array<const Eigen::VectorXd*, 3> columns = {&samples.depthMm, &samples.feedMmPerRev, &samples.zMm};
    std::array<FactorCoding, 3> coding;
    for (std::size_t f = 0; f < 3; ++f)
        coding[f] = levels[f] < 2 ? FactorCoding::at(columns[f]->minCoeff())
                                  : FactorCoding::spanning(columns[f]->minCoeff(), columns[f]->maxCoeff());
    return fitCoded(samples, set, stepwise, coding, terms);
}

DeformationFit fitDeformationModel(const DeformationSamples& samples, DeformationTermSet set, bool stepwise,
                                   const std::array<FactorCoding, 3>& region) {
    const std::array<int, 3> levels = checkedLevels(samples);
    const std::vector<DeformationTerm> terms = deformationTerms(set);
    requireLevels(terms, levels);
    const std::array<const Eigen::VectorXd*, 3> columns = {&samples.depthMm, &samples.feedMmPerRev, &samples.zMm};
    for (std::size_t f = 0; f < 3; ++f) {
        const FactorCoding& c = region[f];
        for (Eigen::Index i = 0; i < columns[f]->size(); ++i) {
            const double v = (*columns[f])(i);
            if (v < c.min || v > c.max)
                throw std::invalid_argument("row " + std::to_string(i + 1) + ": " + kFactorSymbol[f] + " = " +
                                            number(v) + " is outside the region " + number(c.min) + " .. " +
                                            number(c.max) + " the model is fitted for");
        }
    }
    return fitCoded(samples, set, stepwise, region, terms);
}

}  // namespace tt::core
