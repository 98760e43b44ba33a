#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/model/shaping_filter.h"

namespace tt::core {

/// One source of random diameter error at a control point, in mm of diameter (paper 000, "возмущающие
/// воздействия"): a rational shaping filter, a first-order autoregression, a random walk or white noise.
class DisturbanceComponent {
public:
    /// The kind of process.
    enum class Kind { ShapingFilter, Ar1, RandomWalk, White };

    /// Shaping filter driven by white noise of variance `inputVarianceMm2`.
    static DisturbanceComponent shapingFilter(const ShapingFilter& filter, double inputVarianceMm2);
    /// Shaping filter scaled so that its stationary output variance is `varianceMm2`.
    static DisturbanceComponent shapingFilterWithVariance(const ShapingFilter& filter, double varianceMm2);
    /// AR(1) `d(k+1) = pole d(k) + e(k)` with stationary variance `varianceMm2` (|pole| < 1).
    static DisturbanceComponent ar1(double pole, double varianceMm2);
    /// Random walk `d(k+1) = d(k) + e(k)`, var(e) = `stepVarianceMm2` (tool wear, warm-up drift).
    static DisturbanceComponent randomWalk(double stepVarianceMm2);
    /// White noise of variance `varianceMm2` (part-to-part scatter no controller can predict).
    static DisturbanceComponent white(double varianceMm2);

    /// The kind of process.
    Kind kind() const { return m_kind; }
    /// The filter of a ShapingFilter component (empty otherwise).
    const std::optional<ShapingFilter>& filter() const { return m_filter; }
    /// AR(1) pole (0 for the other kinds).
    double pole() const { return m_pole; }
    /// Variance of the driving white noise, mm^2.
    double inputVarianceMm2() const { return m_inputVariance; }
    /// False for a random walk (its variance grows without bound).
    bool isStationary() const { return m_kind != Kind::RandomWalk; }
    /// Stationary variance, mm^2 (+infinity for a random walk).
    double stationaryVarianceMm2() const;

    /// State-space realisation. White noise is realised as a one-step-delayed state (s(k+1) = e(k),
    /// d = s), which is the same white process and keeps the plant in the form x+ = Ax + Bu + Gw.
    DisturbanceRealisation realise() const;

    /// Short description for tables and logs ("AR(1) pole 0.92, 0.0013 mm^2").
    std::string describe() const;

private:
    DisturbanceComponent(Kind kind, std::optional<ShapingFilter> filter, double pole, double inputVariance);

    Kind m_kind;
    std::optional<ShapingFilter> m_filter;
    double m_pole = 0.0;
    double m_inputVariance = 0.0;
};

/// Realisations stacked block-diagonally: the states and noise inputs of part k follow those of part
/// k - 1, and C has one row per part (part k's output alone). The controller's plant and the lathe
/// simulator stack the control points' models this way; a model stacks its components (and sums C).
DisturbanceRealisation stackRealisations(const std::vector<DisturbanceRealisation>& parts);

/// The disturbance at one control point: a sum of independent components.
class DisturbanceModel {
public:
    /// Throws std::invalid_argument when `components` is empty.
    explicit DisturbanceModel(std::vector<DisturbanceComponent> components);

    /// The components, summed.
    const std::vector<DisturbanceComponent>& components() const { return m_components; }
    /// No random walk among the components (the variance is bounded).
    bool isStationary() const;
    /// Sum of the components' stationary variances, mm^2 (+infinity with a random walk).
    double stationaryVarianceMm2() const;
    /// Block-diagonal realisation of the sum: one white input per component.
    DisturbanceRealisation realise() const;
    /// The components' descriptions joined with " + ".
    std::string describe() const;
    /// Covariance of the realisation's state before anything is known: the stationary covariance of
    /// each stationary component, `randomWalkPriorMm2` for a random-walk state (it has none).
    Eigen::MatrixXd priorCovariance(double randomWalkPriorMm2) const;

private:
    std::vector<DisturbanceComponent> m_components;
};

}  // namespace tt::core
