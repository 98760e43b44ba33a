#include "core/control/adaptive_design.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The one-point EWMA loop of weight `weight` designed for delay `delay` stays stable for every gain factor of the
/// grid with the plant's delay `plantDelay`.
bool coversGainRange(double weight, int delay, int plantDelay) {
    const LoopController c = ewmaLoopController(Eigen::VectorXd::Ones(1), delay, weight);
    const int steps =
        static_cast<int>(std::lround((kFallbackMaxGainFactor - kFallbackMinGainFactor) / kFallbackGainStep));
    for (int i = 0; i <= steps; ++i) {
        const double factor = kFallbackMinGainFactor + i * kFallbackGainStep;
        if (!closedLoopStable(Eigen::VectorXd::Constant(1, factor), plantDelay, c)) return false;
    }
    return true;
}

double minOf(double a, double b) {
    return std::isnan(a) ? b : std::isnan(b) ? a : std::min(a, b);
}

double maxOf(double a, double b) {
    return std::isnan(a) ? b : std::isnan(b) ? a : std::max(a, b);
}

std::vector<double> rowMajor(const Eigen::MatrixXd& m) {
    std::vector<double> out;
    for (Eigen::Index r = 0; r < m.rows(); ++r)
        for (Eigen::Index c = 0; c < m.cols(); ++c)
            out.push_back(m(r, c));
    return out;
}

/// Why the design's margins do not cover `factor`, empty when they do.
std::string marginProblem(const LoopMargins& margins, double factor) {
    if (!margins.closedLoopStable) return "the loop of the new design is not stable on the identified plant";
    for (std::size_t i = 0; i < margins.channels.size(); ++i) {
        const ChannelMargins& c = margins.channels[i];
        if (c.gain && *c.gain < factor)
            return "point " + std::to_string(i + 1) + ": its gain margin " + formatSignificant(*c.gain, 3) +
                   " is under the " + formatSignificant(factor, 3) + " the identified gain's uncertainty needs";
        if (c.gainLower && *c.gainLower > 1.0 / factor)
            return "point " + std::to_string(i + 1) + ": its lower gain margin " + formatSignificant(*c.gainLower, 3) +
                   " is above the " + formatSignificant(1.0 / factor, 3) + " the identified gain's uncertainty needs";
    }
    return {};
}

}  // namespace

FallbackDesign designFallback(int delayParts) {
    if (delayParts < 1 || delayParts > kMaxDelay)
        throw std::invalid_argument("the fallback needs a plant delay of 1 .. " + std::to_string(kMaxDelay) +
                                    " parts, got " + std::to_string(delayParts));
    for (int percent = 100; percent >= 1; --percent) {
        const double weight = percent / 100.0;
        if (!coversGainRange(weight, delayParts, delayParts) ||
            !coversGainRange(weight, delayParts, delayParts + kFallbackExtraParts))
            continue;
        FallbackDesign f;
        f.weight = weight;
        f.delayParts = delayParts;
        f.margins = computeLoopMargins(Eigen::VectorXd::Ones(1), delayParts,
                                       ewmaLoopController(Eigen::VectorXd::Ones(1), delayParts, weight))
                        .channels.front();
        return f;
    }
    throw std::invalid_argument("no EWMA weight of 0.01 .. 1 keeps a loop of delay " + std::to_string(delayParts) +
                                " stable for plant gains 0.5 .. 2 times the model's and one part more");
}

std::unique_ptr<RunToRunController> makeFallbackController(const RunToRunSetup& setup, const FallbackDesign& fallback) {
    return makeRunToRunController(setup, buildRunToRunPlant(designPlantSpec(setup)), ControllerKind::Ewma,
                                  fallback.weight);
}

ControllerModel controllerModelFrom(const PlantIdentification& id, std::string source) {
    ControllerModel model;
    for (const PointPlantFit& p : id.points) {
        model.gain.push_back(p.fit.gain);
        model.disturbance.push_back(identifiedDisturbance(p));
    }
    model.lagParts = id.lagParts;
    model.innovationCorrelation = id.innovationCorrelation;
    model.source = std::move(source);
    return model;
}

double requiredGainFactor(const std::vector<double>& gain, const std::vector<double>& gainStdErr,
                          double minGainMargin) {
    double worstShare = 0.0;
    for (std::size_t i = 0; i < gain.size() && i < gainStdErr.size(); ++i)
        if (std::isfinite(gainStdErr[i]) && gain[i] > 0.0) worstShare = std::max(worstShare, gainStdErr[i] / gain[i]);
    return std::max(minGainMargin, 1.0 + kGainSigmas * worstShare);
}

double worstGainShare(const PlantModelRecord& model, bool joint) {
    double worst = 0.0;
    for (const PointModelRecord& p : model.points) {
        const double e = joint && !std::isnan(p.gainStdErrJoint) ? p.gainStdErrJoint : p.gainStdErr;
        if (!std::isnan(e) && p.gain > 0.0) worst = std::max(worst, e / p.gain);
    }
    return worst;
}

AdaptedDesign designAdapted(const RunToRunSetup& current, const PlantIdentification& id, const std::string& source,
                            double minGainMargin) {
    RunToRunSetup next = current;
    next.model = controllerModelFrom(id, source);
    // The margins cover the identified gains' uncertainty as the identification chose the model (given the
    // disturbance when it kept it); a model that is wrong beyond that is the mismatch monitor's to find.
    std::vector<double> gain, stdErr;
    for (const PointPlantFit& p : id.points) {
        gain.push_back(p.fit.gain);
        stdErr.push_back(p.fit.gainStdErr);
    }
    return designForModel(next, requiredGainFactor(gain, stdErr, minGainMargin));
}

AdaptedDesign designForModel(const RunToRunSetup& withModel, double required) {
    AdaptedDesign out;
    out.setup = withModel;
    out.requiredGainFactor = required;
    const RunToRunPlantSpec spec = designPlantSpec(out.setup);
    const RunToRunPlant designPlant =
        buildRunToRunPlant(out.setup.integral.enabled ? withIntegralAction(spec, out.setup.integral) : spec);
    for (double factor : kDetuneFactors) {
        LqgWeights weights = withModel.weights;
        weights.R2 *= factor;
        const LqgDesign design = designLqg(designPlant, weights);
        out.margins = lqgMargins(designPlant, design);
        out.worst = worstMargins(out.margins);
        out.why = marginProblem(out.margins, out.requiredGainFactor);
        out.r2Factor = factor;
        if (out.why.empty()) {
            out.setup.weights = weights;
            out.passes = true;
            return out;
        }
    }
    out.why += " (also with R2 up to " + formatSignificant(kDetuneFactors[std::size(kDetuneFactors) - 1], 3) +
               " times the setup's)";
    return out;
}

std::unique_ptr<RunToRunController> makeAdaptedController(const RunToRunSetup& adapted) {
    const RunToRunPlantSpec spec = designPlantSpec(adapted);
    const RunToRunPlant plant =
        buildRunToRunPlant(adapted.integral.enabled ? withIntegralAction(spec, adapted.integral) : spec);
    return makeRunToRunController(adapted, plant, ControllerKind::Lqg, adapted.ewma.weight);
}

MarginsRecord marginsRecord(const ChannelMargins& c) {
    MarginsRecord r;
    r.gain = c.gain.value_or(kNaN);
    r.gainLower = c.gainLower.value_or(kNaN);
    r.phaseDeg = c.phaseDeg.value_or(kNaN);
    r.delayParts = c.delayParts.value_or(kNaN);
    r.extraPartsTolerated = c.extraPartsTolerated;
    return r;
}

MarginsRecord worstMargins(const LoopMargins& margins) {
    MarginsRecord r;
    r.extraPartsTolerated = std::numeric_limits<int>::max();
    for (const ChannelMargins& c : margins.channels) {
        const MarginsRecord one = marginsRecord(c);
        r.gain = minOf(r.gain, one.gain);
        r.gainLower = maxOf(r.gainLower, one.gainLower);
        r.phaseDeg = minOf(r.phaseDeg, one.phaseDeg);
        r.delayParts = minOf(r.delayParts, one.delayParts);
        r.extraPartsTolerated = std::min(r.extraPartsTolerated, one.extraPartsTolerated);
    }
    if (margins.channels.empty()) r.extraPartsTolerated = 0;
    return r;
}

std::optional<ArmaForm> armaForm(const DisturbanceModel& model) {
    if (model.components().size() != 1) return std::nullopt;
    const DisturbanceComponent& c = model.components().front();
    switch (c.kind()) {
        case DisturbanceComponent::Kind::White:
            return ArmaForm{{}, {}, c.inputVarianceMm2()};
        case DisturbanceComponent::Kind::Ar1:
            return ArmaForm{{c.pole()}, {}, c.inputVarianceMm2()};
        case DisturbanceComponent::Kind::ShapingFilter: {
            const ShapingFilter& f = *c.filter();
            const std::vector<double>& num = f.numerator();
            if (num.empty() || num.front() == 0.0) return std::nullopt;
            ArmaForm a;
            for (std::size_t i = 1; i < f.denominator().size(); ++i)
                a.ar.push_back(-f.denominator()[i]);
            for (std::size_t i = 1; i < num.size(); ++i)
                a.ma.push_back(num[i] / num.front());
            a.noiseVarianceMm2 = num.front() * num.front() * c.inputVarianceMm2();
            return a;
        }
        case DisturbanceComponent::Kind::RandomWalk:
            return std::nullopt;
    }
    return std::nullopt;
}

PlantModelRecord modelRecord(const RunToRunSetup& setup) {
    const RunToRunPlantSpec spec = designPlantSpec(setup);
    PlantModelRecord r;
    r.delayParts = spec.delay;
    r.lagParts = actuationLag(setup);
    r.source = setup.model ? setup.model->source : std::string("the preset's model");
    if (setup.model) r.innovationCorrelation = rowMajor(setup.model->innovationCorrelation);
    for (const ControlPointSpec& p : spec.points) {
        PointModelRecord point;
        point.gain = p.gain;
        if (const std::optional<ArmaForm> a = armaForm(p.disturbance)) {
            point.ar = a->ar;
            point.ma = a->ma;
            point.noiseVarianceMm2 = a->noiseVarianceMm2;
        }
        r.points.push_back(std::move(point));
    }
    return r;
}

PlantModelRecord modelRecord(const PlantIdentification& id, const std::string& source) {
    PlantModelRecord r;
    r.delayParts = id.delayParts();
    r.lagParts = id.lagParts;
    r.source = source;
    r.criterion = informationCriterionName(id.criterion);
    r.innovationCorrelation = rowMajor(id.innovationCorrelation);
    for (const PointPlantFit& p : id.points) {
        PointModelRecord point;
        point.gain = p.fit.gain;
        point.gainStdErr = p.fit.gainStdErr;
        point.gainStdErrJoint = p.fit.gainStdErrJoint;
        point.ar = p.fit.noise.ar;
        point.ma = p.fit.noise.ma;
        point.arStdErr = p.fit.noise.arStdErr;
        point.maStdErr = p.fit.noise.maStdErr;
        point.noiseVarianceMm2 = p.fit.noise.noiseVarianceMm2;
        point.meanMm = p.fit.meanMm;
        r.points.push_back(std::move(point));
    }
    return r;
}

ControllerModel controllerModelFrom(const PlantModelRecord& record, const RunToRunSetup& setup) {
    const std::size_t m = setup.plant.points.size();
    if (record.points.size() != m)
        throw std::invalid_argument("the recorded model has " + std::to_string(record.points.size()) +
                                    " control points, the run " + std::to_string(m));
    ControllerModel model;
    for (std::size_t i = 0; i < m; ++i) {
        const PointModelRecord& p = record.points[i];
        if (!std::isfinite(p.noiseVarianceMm2) || p.noiseVarianceMm2 <= 0.0)
            throw std::invalid_argument("the recorded model of point " + std::to_string(i + 1) +
                                        " is not an ARMA model");
        ArmaFit fit;
        fit.ar = p.ar;
        fit.ma = p.ma;
        fit.noiseVarianceMm2 = p.noiseVarianceMm2;
        model.gain.push_back(p.gain);
        model.disturbance.push_back(fit.disturbanceModel());
    }
    model.lagParts = record.lagParts;
    if (record.innovationCorrelation.size() == m * m) {
        model.innovationCorrelation.resize(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
        for (std::size_t r = 0; r < m; ++r)
            for (std::size_t c = 0; c < m; ++c)
                model.innovationCorrelation(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) =
                    record.innovationCorrelation[r * m + c];
    }
    model.source = record.source;
    model.validate(m, setup.plant.delay);
    return model;
}

}  // namespace tt::core
