#include "devices/parsers/parametric_gcode.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tt::devices {

namespace {

constexpr double kMmPerInch = 25.4;

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    std::string s(text);
    if (s.find_first_not_of("-0.") == std::string::npos) s = s.substr(s[0] == '-' ? 1 : 0);  // no "-0.000"
    return s;
}

/// A comment's text: upper case, printable ASCII, no parentheses.
std::string commentText(const std::string& text) {
    std::string out;
    for (const unsigned char c : text) {
        if (c == '(' || c == '[')
            out += '<';
        else if (c == ')' || c == ']')
            out += '>';
        else if (c >= 0x20 && c < 0x7f)
            out += static_cast<char>(std::toupper(c));
    }
    return out;
}

/// "O<label>": an O-word (built by appending: GCC 12 warns falsely on a short literal plus a temporary string).
std::string oword(int label) {
    std::string word(1, 'O');
    word += std::to_string(label);
    return word;
}

std::string slopeName(std::size_t k) {
    return "#<_tt_d" + std::to_string(k) + ">";
}

std::string secantName(std::size_t k) {
    return "#<_tt_s" + std::to_string(k) + ">";
}

/// `[[#a GT 0]-[#a LT 0]]`: the sign of a parameter as the approximation unit takes it.
std::string signOf(const std::string& p) {
    return "[[" + p + " GT 0]-[" + p + " LT 0]]";
}

void checkPoints(const ParametricProgramJob& job) {
    const std::size_t n = job.pointZMm.size();
    if (n == 0) throw std::invalid_argument("G-code: the program needs at least one control point");
    if (job.pathZMm.size() < 2) throw std::invalid_argument("G-code: the cutter path needs at least two samples");
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(job.pointZMm[i]) || (i > 0 && !(job.pointZMm[i] > job.pointZMm[i - 1])))
            throw std::invalid_argument("G-code: the control points must be finite and strictly increasing");
    }
    for (std::size_t i = 0; i < job.pathZMm.size(); ++i)
        if (!std::isfinite(job.pathZMm[i]) || (i > 0 && !(job.pathZMm[i] > job.pathZMm[i - 1])))
            throw std::invalid_argument("G-code: the path samples must be finite and strictly increasing");
    if (!job.feedForwardMm.empty() && job.feedForwardMm.size() != job.pathZMm.size())
        throw std::invalid_argument("G-code: the feed-forward needs one value per path sample");
    for (const double f : job.feedForwardMm)
        if (!std::isfinite(f) || std::fabs(f) > 10.0)
            throw std::invalid_argument("G-code: a feed-forward value is not a number within 10 mm");
    if (job.slopes == ParametricSlopes::Weights) {
        if (job.slopeWeights.size() != n)
            throw std::invalid_argument("G-code: the slope weights need one row per control point");
        for (const auto& row : job.slopeWeights)
            if (row.size() != n) throw std::invalid_argument("G-code: the slope weights need one column per point");
    }
}

void checkJob(const ParametricProgramJob& job) {
    checkPoints(job);
    if (!(job.nominalDiameterMm > 0.0 && job.nominalDiameterMm < 10000.0))
        throw std::invalid_argument("G-code: the nominal diameter must be between 0 and 10000 mm");
    if (job.firstParameter != 0 &&
        (job.firstParameter < linuxcnc::kFirstFreeParameter ||
         job.firstParameter + static_cast<long>(job.pointZMm.size()) > linuxcnc::kLastFreeParameter))
        throw std::invalid_argument("G-code: the parameters #" + std::to_string(job.firstParameter) + " .. #" +
                                    std::to_string(job.firstParameter + job.pointZMm.size()) +
                                    " are not all within #31 .. #5000");
    if (!(job.feed > 0.0 && std::isfinite(job.feed)) || (!job.feedPerMinute && job.feed > 5.0) || job.feed > 100000.0)
        throw std::invalid_argument("G-code: the feed must be in (0, 5] per revolution or (0, 100000] per minute");
    if (job.spindleRpm < 0 || job.spindleRpm > 10000)
        throw std::invalid_argument("G-code: the spindle speed must be 0 to 10000 rpm");
    if (job.toolNumber < 1 || (job.wearTool && *job.wearTool < 1))
        throw std::invalid_argument("G-code: tool numbers start at 1");
    if (job.zDirection != 1 && job.zDirection != -1) throw std::invalid_argument("G-code: the Z direction is +1 or -1");
    if (!(job.clearanceMm > 0.0 && job.clearanceMm <= 100.0) || !std::isfinite(job.zOriginMm))
        throw std::invalid_argument("G-code: the clearance must be in (0, 100] mm and the Z origin finite");
    if (!(job.largestTotalMm > 0.0 && job.largestTotalMm <= 5.0))
        throw std::invalid_argument("G-code: the largest correction must be in (0, 5] mm");
    if (!(job.blendToleranceMm > 0.0 && job.blendToleranceMm <= 0.1))
        throw std::invalid_argument("G-code: the blending tolerance must be in (0, 0.1] mm");
    if (job.programNumber < 1 || job.programNumber > 99999)
        throw std::invalid_argument("G-code: the program number must be 1 to 99999");
}

/// The numbers of the program in its own units and X mode.
class Units {
public:
    explicit Units(const ParametricProgramJob& job) : m_job(job), m_unit(job.conventions.inch ? kMmPerInch : 1.0) {}
    /// A length in program units.
    double length(double mm) const { return mm / m_unit; }
    /// The X word of a radial correction `radialMm` from the nominal.
    double x(double radialMm) const {
        const double r = 0.5 * m_job.nominalDiameterMm + radialMm;
        return (m_job.conventions.diameterMode ? 2.0 * r : r) / m_unit;
    }
    /// A radial correction as the X word counts it (doubled in diameter mode).
    double correction(double radialMm) const {
        return (m_job.conventions.diameterMode ? 2.0 * radialMm : radialMm) / m_unit;
    }
    /// The Z word of a position z along the part.
    std::string z(double zMm) const { return fixed((m_job.zOriginMm + m_job.zDirection * zMm) / m_unit, 6); }
    int decimals() const { return m_job.conventions.inch ? 7 : 6; }

private:
    const ParametricProgramJob& m_job;
    double m_unit;
};

void header(std::string& out, const ParametricProgramJob& job, const Units& u) {
    auto comment = [&](const std::string& text) {
        out += '(';
        out += commentText(text);
        out += ")\n";
    };
    const bool inch = job.conventions.inch;
    const std::size_t n = job.pointZMm.size();
    comment("PROGRAM " + std::to_string(job.programNumber) + " TRUETURN FINISHING PASS, LINUXCNC");
    for (const std::string& note : job.notes)
        comment(note);
    comment(std::string(inch ? "INCH: G20" : "MILLIMETRES: G21") + ", X WORDS ARE " +
            (job.conventions.diameterMode ? "DIAMETERS: G7" : "RADII: G8"));
    comment("NOMINAL DIAMETER " + fixed(job.nominalDiameterMm, 4) + " MM, MACHINE Z = " + fixed(job.zOriginMm, 3) +
            (job.zDirection > 0 ? " + " : " - ") + "PART Z");
    if (job.firstParameter == 0) {
        comment("NOMINAL PATH" + std::string(job.feedForwardMm.empty() ? "" : " WITH THE FEED-FORWARD") +
                "; THE CORRECTION IS THE X WEAR OF TOOL " + std::to_string(job.wearTool.value_or(0)) +
                ", APPLIED BY G43.2");
        return;
    }
    comment("CORRECTIONS SET BY TRUETURN BETWEEN PARTS, " + std::string(inch ? "INCH" : "MM") + ", " +
            (job.conventions.diameterMode ? "ON DIAMETER" : "RADIAL") + ", NEGATIVE = TOWARDS THE AXIS:");
    for (std::size_t i = 0; i < n; ++i)
        comment("  " + linuxcnc::parameterName(job.firstParameter + static_cast<int>(i)) + " AT PART Z " +
                fixed(job.pointZMm[i], 3) + " MM");
    comment("  " + linuxcnc::parameterName(job.firstParameter + static_cast<int>(n)) +
            " THE PART NUMBER THEY ARE FOR; THE PROGRAM CLEARS IT AND REFUSES TO CUT WITHOUT IT");
    comment(std::string("BETWEEN THE POINTS: ") + (job.slopes == ParametricSlopes::Pchip ? "PCHIP" : "CUBIC SPLINE") +
            " THROUGH THE CORRECTIONS, HELD AT THE END VALUES OUTSIDE THEM; LARGEST CORRECTION " +
            fixed(u.correction(job.largestTotalMm), u.decimals()));
}

void guards(std::string& out, const ParametricProgramJob& job, const Units& u, int& label) {
    const std::size_t n = job.pointZMm.size();
    const std::string token = linuxcnc::parameterName(job.firstParameter + static_cast<int>(n));
    out += oword(label) + " if [" + token + " LT 1]\n";
    out += "(ABORT, TRUETURN: NO CORRECTIONS WERE WRITTEN FOR THIS PART - " + token + " IS NOT SET)\n";
    out += oword(label++) + " endif\n";
    const std::string limit = fixed(u.correction(job.largestTotalMm) * (1.0 + 1e-9), u.decimals() + 2);
    for (std::size_t i = 0; i < n; ++i) {
        const std::string p = linuxcnc::parameterName(job.firstParameter + static_cast<int>(i));
        out += oword(label) + " if [ABS[" + p + "] GT " + limit + "]\n";
        out += "(ABORT, TRUETURN: THE CORRECTION " + p + " IS BEYOND THE LARGEST CORRECTION)\n";
        out += oword(label++) + " endif\n";
    }
    out += token + "=0\n";
}

/// PCHIP slopes (Fritsch-Carlson with Brodlie's weights, MATLAB's end conditions), as
/// core/control/profile_interpolation.cpp computes them.
void pchipSlopes(std::string& out, const ParametricProgramJob& job, const Units& u, int& label) {
    const std::size_t n = job.pointZMm.size();
    std::vector<double> h(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        h[k] = u.length(job.pointZMm[k + 1] - job.pointZMm[k]);
        const std::string p0 = linuxcnc::parameterName(job.firstParameter + static_cast<int>(k));
        const std::string p1 = linuxcnc::parameterName(job.firstParameter + static_cast<int>(k) + 1);
        out += secantName(k) + "=[[" + p1 + "-" + p0 + "]/" + fixed(h[k], 9) + "]\n";
    }
    if (n == 2) {
        out += slopeName(0) + "=" + secantName(0) + "\n" + slopeName(1) + "=" + secantName(0) + "\n";
        return;
    }
    for (std::size_t k = 1; k + 1 < n; ++k) {
        const std::string a = secantName(k - 1), b = secantName(k);
        const std::string w1 = fixed(2.0 * h[k] + h[k - 1], 9), w2 = fixed(h[k] + 2.0 * h[k - 1], 9);
        out += slopeName(k) + "=0\n";
        out +=
            oword(label) + " if [[[" + a + " GT 0] AND [" + b + " GT 0]] OR [[" + a + " LT 0] AND [" + b + " LT 0]]]\n";
        out += slopeName(k) + "=[[" + w1 + "+" + w2 + "]/[" + w1 + "/" + a + "+" + w2 + "/" + b + "]]\n";
        out += oword(label++) + " endif\n";
    }
    // The end slopes: one-sided three-point formula, kept shape-preserving.
    const auto end = [&](std::size_t slope, double h1, double h2, std::size_t s1, std::size_t s2) {
        const std::string d = slopeName(slope), del1 = secantName(s1), del2 = secantName(s2);
        out += d + "=[[[" + fixed(2.0 * h1 + h2, 9) + "*" + del1 + "]-[" + fixed(h1, 9) + "*" + del2 + "]]/" +
               fixed(h1 + h2, 9) + "]\n";
        out += oword(label) + " if [" + signOf(d) + " NE " + signOf(del1) + "]\n" + d + "=0\n";
        out += oword(label) + " elseif [[" + signOf(del1) + " NE " + signOf(del2) + "] AND [ABS[" + d + "] GT ABS[3*" +
               del1 + "]]]\n" + d + "=[3*" + del1 + "]\n";
        out += oword(label++) + " endif\n";
    };
    end(0, h[0], h[1], 0, 1);
    end(n - 1, h[n - 2], h[n - 3], n - 2, n - 3);
}

/// Slopes as fixed combinations of the parameters (natural spline), per program length unit.
void weightSlopes(std::string& out, const ParametricProgramJob& job, const Units& u) {
    const std::size_t n = job.pointZMm.size();
    const double perUnit = job.conventions.inch ? kMmPerInch : 1.0;
    for (std::size_t k = 0; k < n; ++k) {
        std::string sum;
        for (std::size_t j = 0; j < n; ++j) {
            const double w = job.slopeWeights[k][j] * perUnit;
            if (w == 0.0) continue;
            if (!sum.empty()) sum += '+';
            sum += '[';
            sum += fixed(w, 12);
            sum += '*';
            sum += linuxcnc::parameterName(job.firstParameter + static_cast<int>(j));
            sum += ']';
        }
        out += slopeName(k) + "=[" + (sum.empty() ? "0" : sum) + "]\n";
    }
    (void)u;
}

}  // namespace

namespace {

/// The X word at path sample `i`: the nominal plus the feed-forward plus the Hermite cubic through the parameters.
std::string xWord(const ParametricProgramJob& job, const Units& u, std::size_t i) {
    const double z = job.pathZMm[i];
    const double ff = job.feedForwardMm.empty() ? 0.0 : job.feedForwardMm[i];
    const std::string base = fixed(u.x(ff), u.decimals() + 1);
    if (job.firstParameter == 0) return base;
    const std::vector<double>& zs = job.pointZMm;
    const std::size_t n = zs.size();
    auto p = [&](std::size_t k) { return linuxcnc::parameterName(job.firstParameter + static_cast<int>(k)); };
    if (n == 1 || z <= zs.front()) return "[" + base + "+" + p(0) + "]";
    if (z >= zs.back()) return "[" + base + "+" + p(n - 1) + "]";
    std::size_t k = 0;
    while (k + 2 < n && z >= zs[k + 1])
        ++k;
    const double h = zs[k + 1] - zs[k], t = (z - zs[k]) / h, hp = u.length(h);
    const double a = 2 * t * t * t - 3 * t * t + 1, b = (t * t * t - 2 * t * t + t) * hp;
    const double c = -2 * t * t * t + 3 * t * t, d = (t * t * t - t * t) * hp;
    std::string s = "[" + base;
    const auto term = [&](double coefficient, const std::string& name) {
        const std::string v = fixed(coefficient, 9);
        if (v == "0.000000000") return;
        s += (coefficient < 0 ? "" : "+") + v + "*" + name;
    };
    term(a, p(k));
    term(b, slopeName(k));
    term(c, p(k + 1));
    term(d, slopeName(k + 1));
    return s + "]";
}

void pass(std::string& out, const ParametricProgramJob& job, const Units& u) {
    const double safe = u.x(job.largestTotalMm + job.clearanceMm);
    const std::string approachZ = u.z(job.pathZMm.front() - job.clearanceMm);
    if (job.spindleRpm > 0) out += "G97 S" + std::to_string(job.spindleRpm) + " M3\n";
    out += "G0 X" + fixed(safe, u.decimals()) + " Z" + approachZ + "\n";
    out += "G0 X" + xWord(job, u, 0) + "\n";
    // Onto the part's start at the path's first X, with a dwell in the air half the clearance before it (where the
    // path starts is then surely seen by whoever watches the tool's position).
    out += "G1 Z" + u.z(job.pathZMm.front() - 0.5 * job.clearanceMm) + " F" +
           fixed(u.length(job.feed), job.feedPerMinute ? 3 : 6) + "\n";
    out += "G4 P0.05\n";
    out += "G1 Z" + u.z(job.pathZMm.front()) + "\n";
    for (std::size_t i = 1; i < job.pathZMm.size(); ++i)
        out += "G1 X" + xWord(job, u, i) + " Z" + u.z(job.pathZMm[i]) + "\n";
    // The tool stops at the end of the cut before it leaves the part (no spiral mark on the shoulder).
    out += "G4 P0.05\n";
    out += "G0 X" + fixed(safe, u.decimals()) + "\n";
    out += "G0 Z" + approachZ + "\n";
    if (job.spindleRpm > 0) out += "M5\n";
}

}  // namespace

std::string writeParametricProgram(const ParametricProgramJob& job) {
    checkJob(job);
    const Units u(job);
    std::string out = "%\n";
    header(out, job, u);
    const std::string tolerance = fixed(u.length(job.blendToleranceMm), u.decimals() + 2);
    out += std::string("G18 G40 G90 ") + (job.conventions.inch ? "G20" : "G21") +
           (job.conventions.diameterMode ? " G7" : " G8") + (job.feedPerMinute ? " G94" : " G95") + " G64 P" +
           tolerance + " Q" + tolerance + "\n";
    out += 'T';
    out += std::to_string(job.toolNumber);
    out += " M6 G43\n";
    if (job.wearTool) out += "G43.2 H" + std::to_string(*job.wearTool) + "\n";
    int label = 100;
    if (job.firstParameter != 0) {
        guards(out, job, u, label);
        if (job.pointZMm.size() > 1) {
            if (job.slopes == ParametricSlopes::Pchip)
                pchipSlopes(out, job, u, label);
            else
                weightSlopes(out, job, u);
        }
    }
    pass(out, job, u);
    out += "M2\n%\n";
    return out;
}

}  // namespace tt::devices
