#include "config/deformation_model_config.h"

#include <QJsonArray>
#include <QJsonValue>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "config/json_eigen.h"
#include "config/json_section.h"

namespace tt::config {

namespace {

const QString kKind = QStringLiteral("trueturn-deformation-model");
constexpr int kFormat = 1;
const char* const kFactorKeys[3] = {"a_mm", "f_mm_rev", "z_mm"};
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kHuge = 1e300;

/// A statistic that may be null in the file (an exact fit's F or t): null reads as +infinity.
double statisticAt(const JsonSection& s, const QString& key, double lo) {
    if (s.value(key).isNull()) return kInfinity;
    return s.required(key, lo, kHuge);
}

QJsonObject codingToJson(const core::FactorCoding& c) {
    return {{QStringLiteral("centre"), c.centre},
            {QStringLiteral("half_range"), c.halfRange},
            {QStringLiteral("min"), c.min},
            {QStringLiteral("max"), c.max}};
}

core::FactorCoding codingFromJson(const JsonSection& s) {
    core::FactorCoding c;
    c.centre = s.required(QStringLiteral("centre"), -1e6, 1e6);
    c.halfRange = s.required(QStringLiteral("half_range"), 0.0, 1e6);
    c.min = s.required(QStringLiteral("min"), -1e6, 1e6);
    c.max = s.required(QStringLiteral("max"), -1e6, 1e6);
    if (!(c.halfRange > 0.0)) s.fail(QStringLiteral("half_range"), "must be > 0");
    // min = max: the model holds the factor at one value (a model of one depth of cut).
    if (!(c.min <= c.max)) s.fail(QStringLiteral("max"), "must not be below min");
    return c;
}

QJsonArray termsToJson(const DeformationModelFile& file) {
    QJsonArray terms;
    const auto& t = file.model.terms();
    for (std::size_t k = 0; k < t.size(); ++k) {
        const DeformationTermReport& r = file.statistics.terms.at(k);
        terms.append(
            QJsonObject{{QStringLiteral("term"), QString::fromStdString(r.name)},
                        {QStringLiteral("powers"), QJsonArray{t[k].depthPower, t[k].feedPower, t[k].axialPower}},
                        {QStringLiteral("coefficient_um"), r.coefficient},
                        {QStringLiteral("std_error_um"), r.stdError},
                        {QStringLiteral("t"), finiteOrNull(r.tValue)}});
    }
    return terms;
}

core::DeformationTerm powersFromJson(const QJsonValue& value, const QString& where) {
    const QJsonArray a = value.toArray();
    if (!value.isArray() || a.size() != 3)
        throw std::invalid_argument(where.toStdString() + ": must be three whole numbers [i, j, k]");
    int p[3];
    for (int i = 0; i < 3; ++i) {
        const double v = numberAt(a.at(i), where + QStringLiteral("[%1]").arg(i), 0.0, 3.0);
        if (v != std::floor(v)) throw std::invalid_argument(where.toStdString() + ": powers must be whole numbers");
        p[i] = static_cast<int>(v);
    }
    return {p[0], p[1], p[2]};
}

}  // namespace

DeformationModelFile deformationModelFile(const core::DeformationFit& fit) {
    DeformationModelStatistics s;
    const core::LinearRegression& r = fit.regression;
    s.pointCount = r.pointCount;
    s.termCount = r.termCount;
    s.residualDof = r.residualDof;
    s.r2 = r.r2;
    s.r2Adjusted = r.r2Adjusted;
    s.fStatistic = r.fStatistic;
    s.fCritical95 = r.fCritical95;
    s.tCritical95 = r.tCritical95;
    s.residualSigmaUm = r.residualSigma;
    s.termSet = core::deformationTermSetName(fit.termSet);
    s.stepwise = fit.stepwise;
    const auto& terms = fit.model.terms();
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const auto i = static_cast<Eigen::Index>(k);
        s.terms.push_back({terms[k].name(), r.coefficients(i), r.coefficientStdErrors(i), r.tValues(i)});
    }
    for (const core::RemovedTerm& removed : fit.removed)
        s.removed.emplace_back(removed.term.name(), removed.tValue);
    return {fit.model, std::move(s), {}, {}, std::nullopt, std::nullopt};
}

QJsonObject deformationModelToJson(const DeformationModelFile& file) {
    const DeformationModelStatistics& s = file.statistics;
    QJsonObject factors;
    for (int f = 0; f < 3; ++f)
        factors.insert(QLatin1String(kFactorKeys[f]), codingToJson(file.model.codings()[static_cast<std::size_t>(f)]));
    QJsonArray removed;
    for (const auto& [name, t] : s.removed)
        removed.append(QJsonObject{{QStringLiteral("term"), QString::fromStdString(name)}, {QStringLiteral("t"), t}});
    QJsonObject statistics{{QStringLiteral("n"), s.pointCount},
                           {QStringLiteral("terms"), s.termCount},
                           {QStringLiteral("residual_dof"), s.residualDof},
                           {QStringLiteral("r2"), s.r2},
                           {QStringLiteral("r2_adj"), s.r2Adjusted},
                           {QStringLiteral("f"), finiteOrNull(s.fStatistic)},
                           {QStringLiteral("f_critical"), s.fCritical95},
                           {QStringLiteral("significant"), s.significant()},
                           {QStringLiteral("t_critical"), s.tCritical95},
                           {QStringLiteral("sigma_resid_um"), s.residualSigmaUm},
                           {QStringLiteral("two_sigma_um"), s.twoSigmaUm()}};
    QJsonObject source{{QStringLiteral("file"), file.sourceFile}, {QStringLiteral("preset"), file.preset}};
    if (file.seed) source.insert(QStringLiteral("seed"), static_cast<double>(*file.seed));
    QJsonObject out{
        {QStringLiteral("kind"), kKind},
        {QStringLiteral("format"), kFormat},
        {QStringLiteral("description"),
         QStringLiteral("Force deformation Y(a, f, z) in um (paper 004, eq. (1)): a polynomial in the coded "
                        "factors x = (value - centre) / half_range; a depth of cut mm, f feed mm/rev, "
                        "z axial position mm.")},
        {QStringLiteral("units"), QJsonObject{{QStringLiteral("y"), QStringLiteral("um")},
                                              {QStringLiteral("a"), QStringLiteral("mm")},
                                              {QStringLiteral("f"), QStringLiteral("mm/rev")},
                                              {QStringLiteral("z"), QStringLiteral("mm")}}},
        {QStringLiteral("factors"), factors},
        {QStringLiteral("term_set"), QString::fromStdString(s.termSet)},
        {QStringLiteral("stepwise"), s.stepwise},
        {QStringLiteral("terms"), termsToJson(file)},
        {QStringLiteral("removed_terms"), removed},
        {QStringLiteral("statistics"), statistics},
        {QStringLiteral("source"), source}};
    if (file.job) out.insert(QStringLiteral("job"), feedPassJobToJson(*file.job));
    return out;
}

DeformationModelFile deformationModelFromJson(const QJsonObject& json) {
    if (json.value(QStringLiteral("kind")).toString() != kKind)
        throw std::invalid_argument("not a force-deformation model file (\"kind\" must be \"" + kKind.toStdString() +
                                    "\"; write one with 'trueturn fit-deformation FILE.csv --json')");
    const JsonSection top = JsonSection::of(json, QString());
    if (top.integer(QStringLiteral("format"), kFormat, 1, 1000) != kFormat)
        top.fail(QStringLiteral("format"), "this version reads format 1 only");
    const JsonSection factors(json, QStringLiteral("factors"));
    const QJsonObject factorObject = json.value(QStringLiteral("factors")).toObject();
    std::array<core::FactorCoding, 3> coding;
    for (int f = 0; f < 3; ++f) {
        const QString key = QLatin1String(kFactorKeys[f]);
        if (!factors.has(key)) factors.fail(key, "missing");
        coding[static_cast<std::size_t>(f)] = codingFromJson(JsonSection(factorObject, key, factors.name()));
    }

    const QJsonValue termsValue = json.value(QStringLiteral("terms"));
    if (!termsValue.isArray() || termsValue.toArray().isEmpty() || termsValue.toArray().size() > 64)
        throw std::invalid_argument("terms: must be a list of 1 .. 64 terms");
    DeformationModelFile file{
        core::DeformationModel(coding, {{0, 0, 0}}, Eigen::VectorXd::Zero(1)), {}, {}, {}, {}, {}};
    std::vector<core::DeformationTerm> terms;
    Eigen::VectorXd coefficients(termsValue.toArray().size());
    const QJsonArray termArray = termsValue.toArray();
    for (qsizetype k = 0; k < termArray.size(); ++k) {
        const QString where = QStringLiteral("terms[%1]").arg(k);
        if (!termArray.at(k).isObject()) throw std::invalid_argument(where.toStdString() + ": must be an object");
        const JsonSection t = JsonSection::of(termArray.at(k).toObject(), where);
        terms.push_back(powersFromJson(t.value(QStringLiteral("powers")), where + QStringLiteral(".powers")));
        DeformationTermReport report;
        report.name = terms.back().name();
        report.coefficient = t.required(QStringLiteral("coefficient_um"), -kHuge, kHuge);
        report.stdError = t.number(QStringLiteral("std_error_um"), 0.0, 0.0, kHuge);
        report.tValue =
            t.value(QStringLiteral("t")).isNull() ? kInfinity : t.number(QStringLiteral("t"), 0.0, -kHuge, kHuge);
        coefficients(k) = report.coefficient;
        file.statistics.terms.push_back(report);
    }
    try {
        file.model = core::DeformationModel(coding, terms, coefficients);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("terms: ") + e.what());
    }

    const JsonSection s(json, QStringLiteral("statistics"));
    DeformationModelStatistics& st = file.statistics;
    st.pointCount = s.integer(QStringLiteral("n"), 0, 0, 100000000);
    st.termCount = static_cast<int>(terms.size());
    st.residualDof = s.integer(QStringLiteral("residual_dof"), 0, 0, 100000000);
    st.r2 = s.number(QStringLiteral("r2"), 0.0, -kHuge, 1.0);
    st.r2Adjusted = s.number(QStringLiteral("r2_adj"), 0.0, -kHuge, 1.0);
    st.fStatistic = statisticAt(s, QStringLiteral("f"), 0.0);
    st.fCritical95 = s.number(QStringLiteral("f_critical"), 0.0, 0.0, kHuge);
    st.tCritical95 = s.number(QStringLiteral("t_critical"), 0.0, 0.0, kHuge);
    st.residualSigmaUm = s.required(QStringLiteral("sigma_resid_um"), 0.0, kHuge);
    st.termSet = top.text(QStringLiteral("term_set"), "");
    st.stepwise = top.flag(QStringLiteral("stepwise"), false);
    for (const QJsonValue& r : json.value(QStringLiteral("removed_terms")).toArray())
        st.removed.emplace_back(r.toObject().value(QStringLiteral("term")).toString().toStdString(),
                                r.toObject().value(QStringLiteral("t")).toDouble());

    const JsonSection source(json, QStringLiteral("source"));
    file.sourceFile = QString::fromStdString(source.text(QStringLiteral("file"), ""));
    file.preset = QString::fromStdString(source.text(QStringLiteral("preset"), ""));
    if (source.has(QStringLiteral("seed")))
        file.seed = static_cast<std::uint64_t>(source.number(QStringLiteral("seed"), 0.0, 0.0, 9007199254740992.0));
    if (json.contains(QStringLiteral("job")))
        file.job = feedPassJobFromJson(json.value(QStringLiteral("job")).toObject(), QStringLiteral("job"));
    return file;
}

QJsonObject feedPassJobToJson(const devices::FeedPassJob& job) {
    return {{QStringLiteral("finish_diameter_mm"), job.finishDiameterMm},
            {QStringLiteral("spindle_rpm"), job.spindleRpm},
            {QStringLiteral("coolant"), job.coolant},
            {QStringLiteral("tool"), job.toolNumber},
            {QStringLiteral("program_number"), job.programNumber},
            {QStringLiteral("z_origin_mm"), job.zOriginMm},
            {QStringLiteral("z_direction"), job.zDirection},
            {QStringLiteral("clearance_mm"), job.clearanceMm}};
}

devices::FeedPassJob feedPassJobFromJson(const QJsonObject& json, const QString& where) {
    const JsonSection s = JsonSection::of(json, where);
    devices::FeedPassJob job;
    job.finishDiameterMm = s.required(QStringLiteral("finish_diameter_mm"), 0.1, 10000.0);
    job.spindleRpm = static_cast<int>(s.required(QStringLiteral("spindle_rpm"), 1.0, 10000.0));
    if (s.required(QStringLiteral("spindle_rpm"), 1.0, 10000.0) != job.spindleRpm)
        s.fail(QStringLiteral("spindle_rpm"), "must be a whole number");
    job.coolant = s.flag(QStringLiteral("coolant"), job.coolant);
    job.toolNumber = s.integer(QStringLiteral("tool"), job.toolNumber, 1, 99);
    job.programNumber = s.integer(QStringLiteral("program_number"), job.programNumber, 1, 9999);
    job.zOriginMm = s.number(QStringLiteral("z_origin_mm"), job.zOriginMm, -100000.0, 100000.0);
    job.zDirection = s.integer(QStringLiteral("z_direction"), job.zDirection, -1, 1);
    if (job.zDirection == 0) s.fail(QStringLiteral("z_direction"), "must be +1 or -1");
    job.clearanceMm = s.number(QStringLiteral("clearance_mm"), job.clearanceMm, 0.01, 100.0);
    return job;
}

}  // namespace tt::config
