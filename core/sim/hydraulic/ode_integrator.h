#pragma once

#include <functional>
#include <vector>

namespace tt::core {

/// dx/dt = f(t, x): writes the derivative of `x` at time `t` into `dxdt` (same size).
using OdeRightHandSide = std::function<void(double t, const std::vector<double>& x, std::vector<double>& dxdt)>;
/// Called with the state at each requested time.
using OdeObserver = std::function<void(double t, const std::vector<double>& x)>;

/// Error control of the adaptive stepper, on the states divided by their scales.
struct OdeTolerances {
    double absolute = 1e-9;
    double relative = 1e-8;
};

/// Integrates dx/dt = f(t, x) from times.front() with the adaptive Runge-Kutta-Dormand-Prince 5(4)
/// stepper of Boost.Odeint (error control and dense output), and calls `observe` with the state at
/// every time of `times` (ascending; the first is the start, where x = x0). Each state is divided by
/// its entry of `scale` (> 0) for the error control, so currents in A and positions in µm are held
/// to the same relative accuracy. Returns the state at times.back(). Throws std::invalid_argument for
/// sizes or times that do not fit, std::runtime_error when the solution stops being finite or the
/// stepper cannot keep the error within the tolerances; exceptions thrown by `observe` pass through.
std::vector<double> integrateDormandPrince(const OdeRightHandSide& f, std::vector<double> x0,
                                           const std::vector<double>& times, const OdeObserver& observe,
                                           const std::vector<double>& scale, OdeTolerances tolerances = {});

}  // namespace tt::core
