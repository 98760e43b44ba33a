#include "core/sim/hydraulic/ode_integrator.h"

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tt::core {

namespace odeint = boost::numeric::odeint;

std::vector<double> integrateDormandPrince(const OdeRightHandSide& f, std::vector<double> x0,
                                           const std::vector<double>& times, const OdeObserver& observe,
                                           const std::vector<double>& scale, OdeTolerances tolerances) {
    const std::size_t n = x0.size();
    if (n == 0 || scale.size() != n)
        throw std::invalid_argument("ODE: the state and its scales must have the same, non-zero size");
    if (times.empty() || !std::is_sorted(times.begin(), times.end()))
        throw std::invalid_argument("ODE: the output times must be given in ascending order");
    for (double s : scale)
        if (!(s > 0.0) || !std::isfinite(s)) throw std::invalid_argument("ODE: every state scale must be > 0");
    if (!(tolerances.absolute > 0.0) || !(tolerances.relative > 0.0))
        throw std::invalid_argument("ODE: tolerances must be > 0");

    std::vector<double> z(n);
    for (std::size_t k = 0; k < n; ++k)
        z[k] = x0[k] / scale[k];
    std::vector<double> x(n);
    std::vector<double> dxdt(n);
    auto system = [&](const std::vector<double>& zs, std::vector<double>& dzdt, double t) {
        for (std::size_t k = 0; k < n; ++k)
            x[k] = zs[k] * scale[k];
        f(t, x, dxdt);
        dzdt.resize(n);
        for (std::size_t k = 0; k < n; ++k)
            dzdt[k] = dxdt[k] / scale[k];
    };
    std::vector<double> out(n);
    auto observer = [&](const std::vector<double>& zs, double t) {
        for (std::size_t k = 0; k < n; ++k) {
            out[k] = zs[k] * scale[k];
            if (!std::isfinite(out[k]))
                throw std::runtime_error("ODE: the solution is no longer finite at t = " + std::to_string(t) + " s");
        }
        observe(t, out);
    };
    if (times.size() == 1) {
        observer(z, times.front());
        return out;
    }
    const double span = times.back() - times.front();
    double firstStep = span / 1000.0;
    for (std::size_t k = 1; k < times.size(); ++k)
        if (times[k] > times[k - 1]) firstStep = std::min(firstStep, (times[k] - times[k - 1]) / 10.0);
    auto stepper = odeint::make_dense_output(tolerances.absolute, tolerances.relative,
                                             odeint::runge_kutta_dopri5<std::vector<double>>());
    try {
        // At most 100000 steps between two output times: a stiff or runaway solution stops with a reason.
        odeint::integrate_times(stepper, system, z, times.begin(), times.end(), firstStep, observer,
                                odeint::max_step_checker(100000));
    } catch (const odeint::step_adjustment_error& e) {
        throw std::runtime_error(std::string("ODE: the stepper cannot meet the tolerances: ") + e.what());
    } catch (const odeint::no_progress_error& e) {
        throw std::runtime_error(std::string("ODE: no progress: ") + e.what());
    }
    return out;
}

}  // namespace tt::core
