#pragma once

#include <algorithm>
#include <vector>

#include "plot/chart.h"

namespace tt::ui {

/// Sets both axes of `chart` to the data of `xs`, `ys` with a 6 % margin on every side, so
/// points at the ends are never cut by the frame; `includeZeroY` keeps y = 0 in view. `topShare`
/// leaves room above the data for the legend (top right) of a rising curve.
inline void showAllWithMargin(plot::Chart& chart, const std::vector<double>& xs, const std::vector<double>& ys,
                              bool includeZeroY, double topShare = 0.06) {
    if (xs.empty() || ys.empty()) return;
    auto [xlo, xhi] = std::minmax_element(xs.begin(), xs.end());
    double ylo = *std::min_element(ys.begin(), ys.end());
    double yhi = *std::max_element(ys.begin(), ys.end());
    if (includeZeroY) {
        ylo = std::min(ylo, 0.0);
        yhi = std::max(yhi, 0.0);
    }
    const double dx = std::max(*xhi - *xlo, 1e-9) * 0.06;
    const double dy = std::max(yhi - ylo, 1e-9) * 0.06;
    chart.setXRange(*xlo - dx, *xhi + dx);
    chart.setYRange(ylo - dy, yhi + std::max(yhi - ylo, 1e-9) * topShare);
}

}  // namespace tt::ui
