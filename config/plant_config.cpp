#include "config/plant_config.h"

#include <QJsonArray>

#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>
#include "config/controller_model_config.h"
#include "config/json_eigen.h"
#include "config/preset_library.h"

namespace tt::config {

namespace {

using core::ControlPointSpec;
using core::DisturbanceComponent;
using core::DisturbanceModel;
using core::ShapingFilter;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::invalid_argument fieldError(const QString& where, const std::string& why) {
    return std::invalid_argument(where.toStdString() + ": " + why);
}

QString child(const QString& where, const QString& key) {
    return where.isEmpty() ? key : where + QLatin1Char('.') + key;
}

QString item(const QString& where, qsizetype index) {
    return where + QLatin1Char('[') + QString::number(index) + QLatin1Char(']');
}

/// The largest variance a plant may state, mm² (a standard deviation of 10 mm: far beyond any turned part).
constexpr double kMaxVarianceMm2 = 100.0;
/// The largest correction or correction step, mm.
constexpr double kMaxCorrectionMm = 100.0;

double positiveAt(const QJsonValue& value, const QString& where, double maxValue = kInf) {
    const double v = numberAt(value, where, 0.0, maxValue);
    if (v <= 0.0) throw fieldError(where, "must be > 0");
    return v;
}

std::vector<double> numbersAt(const QJsonValue& value, const QString& where) {
    if (!value.isArray() || value.toArray().isEmpty()) throw fieldError(where, "must be a non-empty array of numbers");
    std::vector<double> out;
    const QJsonArray a = value.toArray();
    for (qsizetype i = 0; i < a.size(); ++i)
        out.push_back(numberAt(a.at(i), item(where, i), -kInf, kInf));
    return out;
}

QJsonObject objectAt(const QJsonValue& value, const QString& where) {
    if (!value.isObject()) throw fieldError(where, "must be an object");
    return value.toObject();
}

/// Roots: a number is a real root, [re, im] a complex pair re +- i im.
std::vector<std::complex<double>> rootsAt(const QJsonValue& value, const QString& where) {
    if (!value.isArray() || value.toArray().isEmpty()) throw fieldError(where, "must be a non-empty array of roots");
    std::vector<std::complex<double>> roots;
    const QJsonArray a = value.toArray();
    for (qsizetype i = 0; i < a.size(); ++i) {
        const QJsonValue r = a.at(i);
        if (r.isArray()) {
            const std::vector<double> pair = numbersAt(r, item(where, i));
            if (pair.size() != 2) throw fieldError(item(where, i), "a complex root is [re, im]");
            roots.emplace_back(pair[0], pair[1]);
            roots.emplace_back(pair[0], -pair[1]);
        } else {
            roots.emplace_back(numberAt(r, item(where, i), -kInf, kInf), 0.0);
        }
    }
    return roots;
}

/// Wraps engine errors with the field they come from.
template <typename F>
auto at(const QString& where, F&& make) {
    try {
        return make();
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        if (what.rfind(where.toStdString(), 0) == 0) throw;
        throw fieldError(where, what);
    }
}

DisturbanceComponent shapingFilterAt(const QJsonObject& o, const QString& where) {
    const std::vector<double> numerator = numbersAt(o.value(QStringLiteral("numerator")), child(where, "numerator"));
    const bool byRoots = o.contains(QStringLiteral("roots"));
    if (byRoots == o.contains(QStringLiteral("denominator")))
        throw fieldError(where, "give the denominator either as \"roots\" or as \"denominator\" coefficients");
    const ShapingFilter filter =
        byRoots
            ? at(child(where, "roots"),
                 [&] { return ShapingFilter::fromRoots(numerator, rootsAt(o.value("roots"), child(where, "roots"))); })
            : at(child(where, "denominator"), [&] {
                  return ShapingFilter::fromCoefficients(
                      numerator, numbersAt(o.value("denominator"), child(where, "denominator")));
              });
    const bool byVariance = o.contains(QStringLiteral("variance_mm2"));
    if (byVariance == o.contains(QStringLiteral("input_variance_mm2")))
        throw fieldError(where, "give either \"variance_mm2\" (output) or \"input_variance_mm2\" (driving noise)");
    if (byVariance)
        return DisturbanceComponent::shapingFilterWithVariance(
            filter, positiveAt(o.value("variance_mm2"), child(where, "variance_mm2"), kMaxVarianceMm2));
    return DisturbanceComponent::shapingFilter(
        filter, positiveAt(o.value("input_variance_mm2"), child(where, "input_variance_mm2"), kMaxVarianceMm2));
}

DisturbanceComponent componentAt(const QJsonValue& value, const QString& where) {
    const QJsonObject o = objectAt(value, where);
    const QString type = o.value(QStringLiteral("type")).toString();
    if (type == QLatin1String("shaping_filter")) return shapingFilterAt(o, where);
    if (type == QLatin1String("ar1"))
        return at(where, [&] {
            return DisturbanceComponent::ar1(
                numberAt(o.value("pole"), child(where, "pole"), -kInf, kInf),
                positiveAt(o.value("variance_mm2"), child(where, "variance_mm2"), kMaxVarianceMm2));
        });
    if (type == QLatin1String("random_walk"))
        return DisturbanceComponent::randomWalk(
            positiveAt(o.value("step_variance_mm2"), child(where, "step_variance_mm2"), kMaxVarianceMm2));
    if (type == QLatin1String("white"))
        return DisturbanceComponent::white(
            positiveAt(o.value("variance_mm2"), child(where, "variance_mm2"), kMaxVarianceMm2));
    throw fieldError(child(where, "type"),
                     "'" + type.toStdString() + "' is not one of shaping_filter, ar1, random_walk, white");
}

/// A scalar for every point or an array with one value per point.
Eigen::VectorXd perPoint(const QJsonValue& value, const QString& where, int points, double fallback, bool positive) {
    Eigen::VectorXd out = Eigen::VectorXd::Constant(points, fallback);
    if (value.isUndefined()) return out;
    if (value.isArray()) {
        const std::vector<double> v = numbersAt(value, where);
        if (static_cast<int>(v.size()) != points)
            throw fieldError(where, "needs one value per control point (" + std::to_string(points) + ")");
        for (int i = 0; i < points; ++i)
            out(i) = v[static_cast<std::size_t>(i)];
    } else {
        out.setConstant(numberAt(value, where, -kInf, kInf));
    }
    for (int i = 0; i < points; ++i)
        if (out(i) < 0.0 || (positive && out(i) <= 0.0))
            throw fieldError(where, positive ? "must be > 0" : "must be >= 0");
    return out;
}

core::RunToRunPlantSpec plantAt(const QJsonObject& plant, std::optional<int> delay) {
    const QString where = QStringLiteral("plant");
    core::RunToRunPlantSpec spec;
    spec.delay = 4;
    if (delay) {
        spec.delay = *delay;
    } else if (plant.contains(QStringLiteral("delay"))) {
        const double d = numberAt(plant.value("delay"), child(where, "delay"), 1, core::kMaxDelay);
        if (std::floor(d) != d) throw fieldError(child(where, "delay"), "must be a whole number of parts");
        spec.delay = static_cast<int>(d);
    }
    const double gain = plant.contains("gain") ? positiveAt(plant.value("gain"), child(where, "gain"), 100.0) : 2.0;
    const bool hasNoise = plant.contains("gauge_noise_variance_mm2");
    const double noise = hasNoise ? positiveAt(plant.value("gauge_noise_variance_mm2"),
                                               child(where, "gauge_noise_variance_mm2"), kMaxVarianceMm2)
                                  : 0.0;
    std::optional<DisturbanceModel> disturbance;
    if (plant.contains("disturbance"))
        disturbance = disturbanceFromJson(plant.value("disturbance"), child(where, "disturbance"));

    auto makePoint = [&](double x, const QJsonObject& o, const QString& pw) {
        const double g = o.contains("gain") ? positiveAt(o.value("gain"), child(pw, "gain"), 100.0) : gain;
        const double v = o.contains("gauge_noise_variance_mm2")
                             ? positiveAt(o.value("gauge_noise_variance_mm2"), child(pw, "gauge_noise_variance_mm2"),
                                          kMaxVarianceMm2)
                             : noise;
        if (v <= 0.0) throw fieldError(child(pw, "gauge_noise_variance_mm2"), "missing (here or for the whole plant)");
        if (o.contains("disturbance"))
            return ControlPointSpec{x, g, disturbanceFromJson(o.value("disturbance"), child(pw, "disturbance")), v};
        if (!disturbance) throw fieldError(child(pw, "disturbance"), "missing (here or for the whole plant)");
        return ControlPointSpec{x, g, *disturbance, v};
    };

    if (plant.contains("points")) {
        if (!plant.value("points").isArray()) throw fieldError(child(where, "points"), "must be an array of objects");
        const QJsonArray a = plant.value("points").toArray();
        for (qsizetype i = 0; i < a.size(); ++i) {
            const QString pw = item(child(where, "points"), i);
            const QJsonObject o = objectAt(a.at(i), pw);
            spec.points.push_back(makePoint(numberAt(o.value("x_mm"), child(pw, "x_mm"), 0.0, 1e5), o, pw));
        }
    } else {
        std::vector<double> xs;
        if (plant.contains("points_mm")) {
            xs = numbersAt(plant.value("points_mm"), child(where, "points_mm"));
        } else {
            const double length = numberAt(plant.value("part_length_mm"), child(where, "part_length_mm"), 100.0, 1e5);
            xs = core::paperControlPointsMm(length);
        }
        for (std::size_t i = 0; i < xs.size(); ++i)
            spec.points.push_back(
                makePoint(xs[i], QJsonObject(), item(child(where, "points_mm"), static_cast<qsizetype>(i))));
    }
    if (spec.points.empty() || spec.points.size() > static_cast<std::size_t>(core::kMaxControlPoints))
        throw fieldError(child(where, "points"), "needs 1 .. " + std::to_string(core::kMaxControlPoints) + " points");
    return spec;
}

void controllerAt(const QJsonObject& c, core::RunToRunSetup& setup) {
    const QString where = QStringLiteral("controller");
    const int m = static_cast<int>(setup.plant.points.size());
    setup.weights.R1 = perPoint(c.value("output_weight"), child(where, "output_weight"), m, 1.0, false).asDiagonal();
    setup.weights.R2 =
        perPoint(c.value("correction_weight"), child(where, "correction_weight"), m, 0.01, true).asDiagonal();
    if (c.contains("max_correction_mm"))
        setup.limits.maxAbsMm =
            positiveAt(c.value("max_correction_mm"), child(where, "max_correction_mm"), kMaxCorrectionMm);
    if (c.contains("max_step_mm"))
        setup.limits.maxStepMm = positiveAt(c.value("max_step_mm"), child(where, "max_step_mm"), kMaxCorrectionMm);
    if (c.contains("gate_sigma"))
        setup.lqg.gateSigma = numberAt(c.value("gate_sigma"), child(where, "gate_sigma"), 1, 100);
    if (c.contains("history_parts"))
        setup.lqg.historyParts =
            static_cast<int>(numberAt(c.value("history_parts"), child(where, "history_parts"), 1, 4096));
    if (!c.contains("ewma")) return;
    const QString ew = child(where, "ewma");
    const QJsonObject e = objectAt(c.value("ewma"), ew);
    const QJsonValue weight = e.value("weight");
    setup.ewmaWeightAuto = weight.isUndefined() || weight.toString() == QLatin1String("auto");
    if (!setup.ewmaWeightAuto) {
        setup.ewma.weight = numberAt(weight, child(ew, "weight"), 0.0, 1.0);
        if (setup.ewma.weight <= 0.0) throw fieldError(child(ew, "weight"), "must be in (0, 1] or \"auto\"");
    }
    if (e.contains("dead_band_mm"))
        setup.ewma.deadBandMm = numberAt(e.value("dead_band_mm"), child(ew, "dead_band_mm"), 0, 10);
    if (e.contains("warning_mm")) setup.ewma.warningMm = positiveAt(e.value("warning_mm"), child(ew, "warning_mm"));
    if (e.contains("alarm_mm")) setup.ewma.alarmMm = positiveAt(e.value("alarm_mm"), child(ew, "alarm_mm"));
    setup.ewma.historyParts = setup.lqg.historyParts;
    at(ew, [&] {
        setup.ewma.validate();
        return 0;
    });
}

}  // namespace

core::DisturbanceModel disturbanceFromJson(const QJsonValue& value, const QString& where) {
    if (!value.isArray() || value.toArray().isEmpty())
        throw fieldError(where, "must be a non-empty array of disturbance components");
    const QJsonArray a = value.toArray();
    if (a.size() > kMaxDisturbanceComponents)
        throw fieldError(where, "has " + std::to_string(a.size()) + " components; the limit is " +
                                    std::to_string(kMaxDisturbanceComponents));
    std::vector<DisturbanceComponent> components;
    for (qsizetype i = 0; i < a.size(); ++i)
        components.push_back(componentAt(a.at(i), item(where, i)));
    DisturbanceModel model(std::move(components));
    const Eigen::Index order = model.realise().A.rows();
    if (order > kMaxDisturbanceOrder)
        throw fieldError(where, "the model order " + std::to_string(order) + " is above the limit of " +
                                    std::to_string(kMaxDisturbanceOrder) + " states per control point");
    return model;
}

core::RunToRunSetup runToRunSetupFromPreset(const QJsonObject& preset, std::optional<int> delay) {
    if (!preset.value("plant").isObject())
        throw fieldError("plant", "missing: this preset is not a run-to-run scenario");
    core::RunToRunSetup setup;
    setup.plant = plantAt(preset.value("plant").toObject(), delay);
    controllerAt(preset.value("controller").toObject(), setup);
    setup.model = controllerModelFromPreset(preset, setup.plant.points.size(), setup.plant.delay);
    at("controller", [&] {
        setup.limits.validate();
        setup.lqg.validate();
        return 0;
    });
    return setup;
}

core::RunToRunSetup loadRunToRunSetup(const QString& nameOrPath, std::optional<int> delay) {
    const QJsonObject preset = PresetLibrary::load(nameOrPath);
    try {
        return runToRunSetupFromPreset(preset, delay);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("preset '" + nameOrPath.toStdString() + "': " + e.what());
    }
}

}  // namespace tt::config
