#include "core/calibration/kp_calibration.h"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace tt::core {

KpFit fitKp(const std::vector<KpPoint>& points) {
    if (points.size() < static_cast<std::size_t>(kMinKpLoads))
        throw KpFitRefused(KpFitProblem::TooFewLoads,
                           "k_p needs at least 3 known loads, got " + std::to_string(points.size()),
                           static_cast<int>(points.size()));
    std::set<double> loads;
    double sx = 0.0, sy = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const KpPoint& p = points[i];
        if (!std::isfinite(p.loadN) || !std::isfinite(p.currentDifferenceA))
            throw KpFitRefused(KpFitProblem::NotANumber, "point " + std::to_string(i + 1) + ": not a number",
                               static_cast<int>(i + 1));
        loads.insert(p.loadN);
        sx += p.currentDifferenceA;
        sy += p.loadN;
    }
    if (loads.size() < 2)
        throw KpFitRefused(KpFitProblem::TooFewDifferentLoads, "k_p needs at least 2 different loads",
                           static_cast<int>(loads.size()));
    const double n = static_cast<double>(points.size());
    const double mx = sx / n;
    const double my = sy / n;
    double sxx = 0.0, sxy = 0.0, syy = 0.0;
    for (const KpPoint& p : points) {
        sxx += (p.currentDifferenceA - mx) * (p.currentDifferenceA - mx);
        sxy += (p.currentDifferenceA - mx) * (p.loadN - my);
        syy += (p.loadN - my) * (p.loadN - my);
    }
    if (sxx <= 0.0)
        throw KpFitRefused(KpFitProblem::ConstantCurrent,
                           "the current difference is the same at every load: the drive current is not read");
    KpFit fit;
    fit.kpNPerA = sxy / sxx;
    if (!(fit.kpNPerA > 0.0)) {
        std::ostringstream s;
        s << "the current difference falls as the load grows (slope " << fit.kpNPerA
          << " N/A): the load acts the other way or the current sign is reversed";
        throw KpFitRefused(KpFitProblem::FallsWithLoad, s.str(), 0, fit.kpNPerA);
    }
    fit.offsetN = my - fit.kpNPerA * mx;
    double sse = 0.0;
    for (const KpPoint& p : points) {
        const double r = p.loadN - (fit.kpNPerA * p.currentDifferenceA + fit.offsetN);
        fit.residualsN.push_back(r);
        sse += r * r;
    }
    fit.r2 = syy > 0.0 ? 1.0 - sse / syy : 1.0;
    fit.rmsResidualN = std::sqrt(sse / n);
    return fit;
}

}  // namespace tt::core
