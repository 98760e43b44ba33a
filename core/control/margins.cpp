#include "core/control/margins.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace tt::core {

namespace {

using Eigen::Index;
using Eigen::MatrixXcd;
using Eigen::MatrixXd;
using Complex = std::complex<double>;

constexpr double kPi = std::numbers::pi;
constexpr int kBisectionSteps = 48;
constexpr int kGoldenSteps = 40;

void checkFinite(const MatrixXd& m, const char* name) {
    if (!m.allFinite())
        throw std::invalid_argument(std::string("margins: the controller matrix ") + name + " is not finite");
}

void validate(const Eigen::VectorXd& gain, int delay, const LoopController& c, int maxDelay = kMaxDelay) {
    const Index m = gain.size();
    if (m < 1 || m > kMaxControlPoints)
        throw std::invalid_argument("margins: 1 to " + std::to_string(kMaxControlPoints) + " control points, got " +
                                    std::to_string(m));
    if (delay < 1 || delay > maxDelay)
        throw std::invalid_argument("margins: the delay must be 1 to " + std::to_string(maxDelay) + " parts, got " +
                                    std::to_string(delay));
    if (!gain.allFinite() || (gain.array() <= 0.0).any())
        throw std::invalid_argument("margins: every plant gain k_i must be finite and positive");
    const Index n = c.Ac.rows();
    if (c.Ac.cols() != n || c.Bc.rows() != n || c.Bc.cols() != m || c.Cc.rows() != m || c.Cc.cols() != n ||
        c.Dc.rows() != m || c.Dc.cols() != m)
        throw std::invalid_argument("margins: the controller's matrices do not match " + std::to_string(m) +
                                    " control points");
    checkFinite(c.Ac, "Ac");
    checkFinite(c.Bc, "Bc");
    checkFinite(c.Cc, "Cc");
    checkFinite(c.Dc, "Dc");
}

/// Evaluates the loop-at-a-time transfers L_i(e^jw) of the loop u = K(z) y, y = diag(gain) z^-d u.
class LoopEvaluator {
public:
    LoopEvaluator(const Eigen::VectorXd& gain, int delay, const LoopController& c)
        : m_gain(gain), m_delay(delay), m_c(c) {}

    Index channels() const { return m_gain.size(); }

    /// L_i(e^jw) of channel i, negative-feedback convention (the loop is stable with 1 + L != 0 encircling
    /// correctly; L = -K k z^-d for one channel).
    Complex loop(double w, Index i) const {
        const MatrixXcd T = returnRatio(w);
        const Index m = T.rows();
        if (m == 1) return -T(0, 0);
        // Break channel i, close the others: L_i = -(T_ii + T_ir (I - T_rr)^-1 T_ri).
        std::vector<Index> rest;
        for (Index j = 0; j < m; ++j)
            if (j != i) rest.push_back(j);
        const Index r = static_cast<Index>(rest.size());
        MatrixXcd Trr(r, r), Tri(r, 1), Tir(1, r);
        for (Index a = 0; a < r; ++a) {
            Tri(a, 0) = T(rest[static_cast<std::size_t>(a)], i);
            Tir(0, a) = T(i, rest[static_cast<std::size_t>(a)]);
            for (Index b = 0; b < r; ++b)
                Trr(a, b) = T(rest[static_cast<std::size_t>(a)], rest[static_cast<std::size_t>(b)]);
        }
        const MatrixXcd closed = (MatrixXcd::Identity(r, r) - Trr).partialPivLu().solve(Tri);
        return -(T(i, i) + (Tir * closed)(0, 0));
    }

private:
    /// T = K(e^jw) diag(gain) e^-jwd: the signal returned to the corrections (positive feedback).
    MatrixXcd returnRatio(double w) const {
        const Complex zeta = std::polar(1.0, w);
        const Index n = m_c.Ac.rows();
        MatrixXcd K = m_c.Dc.cast<Complex>();
        if (n > 0) {
            const MatrixXcd zI_A = zeta * MatrixXcd::Identity(n, n) - m_c.Ac.cast<Complex>();
            K += m_c.Cc.cast<Complex>() * zI_A.partialPivLu().solve(m_c.Bc.cast<Complex>());
        }
        const Complex delay = std::polar(1.0, -w * m_delay);
        return K * (m_gain.cast<Complex>() * delay).asDiagonal();
    }

    const Eigen::VectorXd& m_gain;
    int m_delay;
    const LoopController& m_c;
};

}  // namespace

bool closedLoopStable(const Eigen::VectorXd& gain, int delay, const LoopController& c) {
    validate(gain, delay, c, 2 * kMaxDelay);
    const Index m = gain.size();
    const Index n = c.Ac.rows();
    const Index q = m * delay;
    MatrixXd phi = MatrixXd::Zero(n + q, n + q);
    const MatrixXd G = gain.asDiagonal();
    const Index last = n + (delay - 1) * m;  // u(k-d) block
    phi.block(0, 0, n, n) = c.Ac;
    phi.block(0, last, n, m) = c.Bc * G;
    phi.block(n, 0, m, n) = c.Cc;
    phi.block(n, last, m, m) += c.Dc * G;
    for (int j = 1; j < delay; ++j)
        phi.block(n + j * m, n + (j - 1) * m, m, m) = MatrixXd::Identity(m, m);
    const Eigen::VectorXcd eig = phi.eigenvalues();
    return eig.cwiseAbs().maxCoeff() < 1.0 - 1e-9;
}

namespace {

std::vector<double> frequencyGrid() {
    std::vector<double> w;
    w.reserve(kMarginUniformGrid + kMarginLogGrid + 1);
    for (int k = 0; k <= kMarginUniformGrid; ++k)
        w.push_back(kPi * k / kMarginUniformGrid);
    const double lo = std::log(1e-4), hi = std::log(0.05);
    for (int k = 0; k < kMarginLogGrid; ++k)
        w.push_back(std::exp(lo + (hi - lo) * k / (kMarginLogGrid - 1)));
    std::sort(w.begin(), w.end());
    w.erase(std::unique(w.begin(), w.end()), w.end());
    return w;
}

/// Root of f on [a, b] where f(a), f(b) differ in sign.
template <typename F>
double bisect(F f, double a, double b) {
    double fa = f(a);
    for (int k = 0; k < kBisectionSteps; ++k) {
        const double mid = 0.5 * (a + b);
        const double fm = f(mid);
        if ((fm < 0.0) == (fa < 0.0)) {
            a = mid;
            fa = fm;
        } else {
            b = mid;
        }
    }
    return 0.5 * (a + b);
}

/// Maximum of f on [a, b] (golden section), returns {argmax, max}.
template <typename F>
std::pair<double, double> goldenMax(F f, double a, double b) {
    const double r = (std::sqrt(5.0) - 1.0) / 2.0;
    double c = b - r * (b - a), d = a + r * (b - a);
    double fc = f(c), fd = f(d);
    for (int k = 0; k < kGoldenSteps; ++k) {
        if (fc > fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - r * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + r * (b - a);
            fd = f(d);
        }
    }
    return fc > fd ? std::pair{c, fc} : std::pair{d, fd};
}

/// Phase of L + 180 degrees wrapped to (-180, 180]: the phase margin at a gain crossover, radians.
double phaseMarginRad(Complex L) {
    double pm = std::arg(L) + kPi;
    while (pm > kPi)
        pm -= 2.0 * kPi;
    while (pm <= -kPi)
        pm += 2.0 * kPi;
    return pm;
}

void gainMargins(const LoopEvaluator& ev, Index i, const std::vector<double>& w, const std::vector<Complex>& L,
                 ChannelMargins& out) {
    auto consider = [&](Complex at) {
        if (at.real() >= 0.0 || std::abs(at) <= 0.0) return;
        const double k = 1.0 / std::abs(at);
        if (k > 1.0) {
            if (!out.gain || k < *out.gain) out.gain = k;
        } else if (!out.gainLower || k > *out.gainLower) {
            out.gainLower = k;
        }
    };
    // L is real at w = 0 and w = pi.
    if (std::abs(L.front().imag()) <= 1e-9 * std::abs(L.front())) consider(Complex(L.front().real(), 0.0));
    consider(Complex(L.back().real(), 0.0));
    for (std::size_t k = 1; k < w.size(); ++k) {
        const double a = L[k - 1].imag(), b = L[k].imag();
        if (k + 1 == w.size() && b == 0.0) continue;  // w = pi handled above
        if (a == 0.0 || (a < 0.0) == (b < 0.0)) continue;
        const double wc = bisect([&](double x) { return ev.loop(x, i).imag(); }, w[k - 1], w[k]);
        consider(ev.loop(wc, i));
    }
}

void phaseMargins(const LoopEvaluator& ev, Index i, const std::vector<double>& w, const std::vector<Complex>& L,
                  ChannelMargins& out) {
    for (std::size_t k = 1; k < w.size(); ++k) {
        const double a = std::abs(L[k - 1]) - 1.0, b = std::abs(L[k]) - 1.0;
        if ((a < 0.0) == (b < 0.0)) continue;
        const double wc = bisect([&](double x) { return std::abs(ev.loop(x, i)) - 1.0; }, w[k - 1], w[k]);
        const double pm = phaseMarginRad(ev.loop(wc, i));
        if (!out.phaseDeg || std::abs(pm) * 180.0 / kPi < *out.phaseDeg) out.phaseDeg = std::abs(pm) * 180.0 / kPi;
        if (wc <= 0.0) continue;
        double positive = std::fmod(pm, 2.0 * kPi);
        if (positive < 0.0) positive += 2.0 * kPi;
        const double dm = positive / wc;
        if (!out.delayParts || dm < *out.delayParts) {
            out.delayParts = dm;
            out.crossoverRadPerPart = wc;
        }
    }
}

void peaks(const LoopEvaluator& ev, Index i, const std::vector<double>& w, const std::vector<Complex>& L,
           ChannelMargins& out) {
    auto sens = [&](double x) { return std::abs(1.0 / (1.0 + ev.loop(x, i))); };
    auto disk = [&](double x) { return std::abs(1.0 / (1.0 + ev.loop(x, i)) - 0.5); };
    std::size_t bestS = 0, bestD = 0;
    double maxS = -1.0, maxD = -1.0;
    for (std::size_t k = 0; k < w.size(); ++k) {
        const Complex s = 1.0 / (1.0 + L[k]);
        if (std::abs(s) > maxS) maxS = std::abs(s), bestS = k;
        if (std::abs(s - 0.5) > maxD) maxD = std::abs(s - 0.5), bestD = k;
    }
    auto refine = [&](auto f, std::size_t k, double gridMax) {
        const double a = w[k == 0 ? 0 : k - 1], b = w[std::min(k + 1, w.size() - 1)];
        const auto [x, v] = goldenMax(f, a, b);
        return v > gridMax ? std::pair{x, v} : std::pair{w[k], gridMax};
    };
    const auto [ws, s] = refine(sens, bestS, maxS);
    out.sensitivityPeak = s;
    out.sensitivityPeakRadPerPart = ws;
    const double d = refine(disk, bestD, maxD).second;
    out.disk = 1.0 / d;
    out.diskGainUpper = out.disk < 2.0 ? (2.0 + out.disk) / (2.0 - out.disk) : 0.0;
    out.diskPhaseDeg = 2.0 * std::atan(out.disk / 2.0) * 180.0 / kPi;
}

/// Whole extra parts of delay the (whole) loop stays stable with, 0 .. kMaxDelay.
int extraPartsTolerated(const Eigen::VectorXd& gain, int delay, const LoopController& c) {
    for (int extra = 1; extra <= kMaxDelay; ++extra)
        if (!closedLoopStable(gain, delay + extra, c)) return extra - 1;
    return kMaxDelay;
}

/// L evaluated where it is finite: an integrating controller is infinite at w = 0, so take it just beside.
Complex finiteLoop(const LoopEvaluator& ev, double w, Index i) {
    Complex L = ev.loop(w, i);
    if (std::isfinite(L.real()) && std::isfinite(L.imag())) return L;
    return ev.loop(w < 1.0 ? w + 1e-7 : w - 1e-7, i);
}

}  // namespace

LoopMargins computeLoopMargins(const Eigen::VectorXd& gain, int delay, const LoopController& controller) {
    validate(gain, delay, controller);
    LoopMargins out;
    out.closedLoopStable = closedLoopStable(gain, delay, controller);
    const LoopEvaluator ev(gain, delay, controller);
    const std::vector<double> w = frequencyGrid();
    for (Index i = 0; i < ev.channels(); ++i) {
        ChannelMargins ch;
        std::vector<Complex> L(w.size());
        for (std::size_t k = 0; k < w.size(); ++k)
            L[k] = finiteLoop(ev, w[k], i);
        peaks(ev, i, w, L, ch);
        if (out.closedLoopStable) {
            gainMargins(ev, i, w, L, ch);
            phaseMargins(ev, i, w, L, ch);
        } else {
            ch.delayParts = 0.0;  // already unstable: no margin of any kind
            ch.disk = 0.0;
            ch.diskGainUpper = 0.0;
            ch.diskPhaseDeg = 0.0;
        }
        out.channels.push_back(ch);
    }
    const int tolerated = out.closedLoopStable ? extraPartsTolerated(gain, delay, controller) : 0;
    for (ChannelMargins& ch : out.channels) {
        ch.extraPartsTolerated = tolerated;
        if ((ch.delayParts && *ch.delayParts < 1.0) || tolerated < 1) out.delayMarginBelowOnePart = true;
    }
    if (!out.closedLoopStable) out.delayMarginBelowOnePart = true;
    return out;
}

LoopController lqgBlockController(const LqgBlock& block) {
    const Index n = block.A.rows();
    const MatrixXd AminusBK = block.A - block.B * block.K;
    const MatrixXd IminusLC = MatrixXd::Identity(n, n) - block.L * block.C;
    return {AminusBK * IminusLC, AminusBK * block.L, -block.K * IminusLC, -block.K * block.L};
}

namespace {

Eigen::VectorXd blockGain(const RunToRunPlant& plant, const LqgBlock& block) {
    Eigen::VectorXd g(static_cast<Index>(block.points.size()));
    for (std::size_t j = 0; j < block.points.size(); ++j)
        g(static_cast<Index>(j)) = plant.gain(block.points[j]);
    return g;
}

}  // namespace

LoopMargins lqgMargins(const RunToRunPlant& plant, const LqgDesign& design) {
    if (design.blocks.empty()) throw std::invalid_argument("margins: the LQG design has no blocks");
    LoopMargins out;
    out.channels.resize(static_cast<std::size_t>(plant.pointCount()));
    out.closedLoopStable = true;
    for (const LqgBlock& block : design.blocks) {
        const LoopMargins part = computeLoopMargins(blockGain(plant, block), plant.delay, lqgBlockController(block));
        for (std::size_t j = 0; j < block.points.size(); ++j)
            out.channels[static_cast<std::size_t>(block.points[j])] = part.channels[j];
        out.closedLoopStable = out.closedLoopStable && part.closedLoopStable;
        out.delayMarginBelowOnePart = out.delayMarginBelowOnePart || part.delayMarginBelowOnePart;
    }
    return out;
}

std::vector<double> sensitivityMagnitude(const Eigen::VectorXd& gain, int delay, const LoopController& controller,
                                         int channel, const std::vector<double>& wRadPerPart) {
    validate(gain, delay, controller);
    if (channel < 0 || channel >= gain.size())
        throw std::invalid_argument("margins: no control point " + std::to_string(channel + 1));
    const LoopEvaluator ev(gain, delay, controller);
    std::vector<double> out;
    out.reserve(wRadPerPart.size());
    for (double w : wRadPerPart)
        out.push_back(std::abs(1.0 / (1.0 + ev.loop(w, channel))));
    return out;
}

std::vector<double> lqgSensitivityMagnitude(const RunToRunPlant& plant, const LqgDesign& design, int point,
                                            const std::vector<double>& wRadPerPart) {
    for (const LqgBlock& block : design.blocks)
        for (std::size_t j = 0; j < block.points.size(); ++j)
            if (block.points[j] == point)
                return sensitivityMagnitude(blockGain(plant, block), plant.delay, lqgBlockController(block),
                                            static_cast<int>(j), wRadPerPart);
    throw std::invalid_argument("margins: no control point " + std::to_string(point + 1) + " in the design");
}

}  // namespace tt::core

namespace tt::core {

LoopController ewmaLoopController(const Eigen::VectorXd& gain, int delay, double weight) {
    if (!(weight > 0.0 && weight <= 1.0)) throw std::invalid_argument("the EWMA weight must be in (0, 1]");
    if (delay < 1 || delay > 2 * kMaxDelay)
        throw std::invalid_argument("the EWMA's delay must be 1 .. " + std::to_string(2 * kMaxDelay) + " parts");
    if (gain.size() < 1 || !gain.allFinite() || (gain.array() <= 0.0).any())
        throw std::invalid_argument("the EWMA needs a positive gain at every point");
    using Eigen::Index;
    using Eigen::MatrixXd;
    const Index m = gain.size();
    const Index z = delay;
    const Index nc = m * (1 + z);
    const MatrixXd I = MatrixXd::Identity(m, m);
    const MatrixXd G = gain.asDiagonal();
    const MatrixXd Ginv = gain.cwiseInverse().asDiagonal();
    LoopController c;
    // u(k) = -G^-1 ((1 - lambda) offset(k-1) - lambda G u(k-z) + lambda y(k))
    c.Cc = MatrixXd::Zero(m, nc);
    c.Cc.block(0, 0, m, m) = -(1.0 - weight) * Ginv;
    c.Cc.block(0, z * m, m, m) = weight * I;
    c.Dc = -weight * Ginv;
    c.Ac = MatrixXd::Zero(nc, nc);
    c.Bc = MatrixXd::Zero(nc, m);
    // offset(k) = (1 - lambda) offset(k-1) - lambda G u(k-z) + lambda y(k)
    c.Ac.block(0, 0, m, m) = (1.0 - weight) * I;
    c.Ac.block(0, z * m, m, m) = -weight * G;
    c.Bc.block(0, 0, m, m) = weight * I;
    // u(k) becomes the newest delayed input; the others shift by one.
    c.Ac.block(m, 0, m, nc) = c.Cc;
    c.Bc.block(m, 0, m, m) = c.Dc;
    for (Index j = 2; j <= z; ++j)
        c.Ac.block(j * m, (j - 1) * m, m, m) = I;
    return c;
}

}  // namespace tt::core
