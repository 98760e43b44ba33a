#include "config/feed_schedule_config.h"

#include <QJsonArray>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "config/json_eigen.h"
#include "config/json_section.h"
#include "config/lathe_config.h"

namespace tt::config {

namespace {

std::vector<double> levelsAt(const QJsonObject& section, const QString& key, const QString& where, double lo,
                             double hi) {
    const QJsonValue v = section.value(key);
    const QString name = where + QLatin1Char('.') + key;
    if (!v.isArray() || v.toArray().isEmpty() || v.toArray().size() > 50)
        throw std::invalid_argument(name.toStdString() + ": must be a list of 1 .. 50 numbers");
    std::vector<double> out;
    const QJsonArray a = v.toArray();
    for (qsizetype i = 0; i < a.size(); ++i)
        out.push_back(numberAt(a.at(i), name + QStringLiteral("[%1]").arg(i), lo, hi));
    return out;
}

core::DeformationExperimentPlan experimentFromJson(const QJsonObject& preset, double lengthMm) {
    const QString where = QStringLiteral("experiment");
    const JsonSection e(preset, where);
    const QJsonObject object = preset.value(where).toObject();
    core::DeformationExperimentPlan plan;
    plan.depthsMm = levelsAt(object, QStringLiteral("depths_mm"), where, 0.001, 20.0);
    plan.feedsMmPerRev = levelsAt(object, QStringLiteral("feeds_mm_per_rev"), where, 0.001, 5.0);
    const JsonSection z(object, QStringLiteral("z_mm"), where);
    const double from = z.required(QStringLiteral("from"), 0.0, lengthMm);
    const double to = z.required(QStringLiteral("to"), 0.0, lengthMm);
    const double step = z.required(QStringLiteral("step"), 0.01, lengthMm);
    if (!(to > from)) z.fail(QStringLiteral("to"), "must be above from");
    const auto count = static_cast<long>(std::floor((to - from) / step + 1e-9)) + 1;
    if (count > 2000) z.fail(QStringLiteral("step"), "gives more than 2000 positions");
    for (long i = 0; i < count; ++i)
        plan.zMm.push_back(from + static_cast<double>(i) * step);
    plan.seed = static_cast<std::uint64_t>(e.number(QStringLiteral("seed"), 1.0, 0.0, 4294967295.0));
    return plan;
}

core::FeedScheduleRequest requestFromJson(const QJsonObject& preset) {
    const JsonSection s(preset, QStringLiteral("schedule"));
    core::FeedScheduleRequest r;
    r.depthMm = s.required(QStringLiteral("depth_mm"), 0.001, 20.0);
    r.feedMinMmPerRev = s.required(QStringLiteral("feed_min_mm_per_rev"), 0.001, 5.0);
    r.feedMaxMmPerRev = s.required(QStringLiteral("feed_max_mm_per_rev"), 0.001, 5.0);
    r.feedStepMmPerRev = s.required(QStringLiteral("feed_step_mm_per_rev"), 0.0001, 5.0);
    r.zStartMm = s.required(QStringLiteral("z_start_mm"), -10000.0, 10000.0);
    r.zEndMm = s.required(QStringLiteral("z_end_mm"), -10000.0, 10000.0);
    r.levelFraction = s.number(QStringLiteral("level_fraction"), 0.5, 0.0, 1.0);
    r.minLengthMm = s.number(QStringLiteral("min_length_mm"), 0.0, 0.0, 10000.0);
    return r;
}

std::string fixed(double v, int decimals) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
    return text;
}

}  // namespace

FeedSchedulingSetup feedSchedulingSetupFromPreset(const QJsonObject& preset) {
    FeedSchedulingSetup s;
    s.lathe = latheSetupFromJson(preset.value(QStringLiteral("lathe")).toObject());
    s.experiment = experimentFromJson(preset, s.lathe.workpiece.lengthMm);
    if (!preset.contains(QStringLiteral("job"))) throw std::invalid_argument("job: missing");
    s.job = *feedPassJobFromPreset(preset);
    s.request = requestFromJson(preset);
    return s;
}

std::optional<devices::FeedPassJob> feedPassJobFromPreset(const QJsonObject& preset) {
    if (!preset.contains(QStringLiteral("job"))) return std::nullopt;
    if (!preset.value(QStringLiteral("job")).isObject()) throw std::invalid_argument("job: must be an object");
    QJsonObject job = preset.value(QStringLiteral("job")).toObject();
    if (!job.contains(QStringLiteral("finish_diameter_mm"))) {
        const JsonSection workpiece(preset.value(QStringLiteral("lathe")).toObject(), QStringLiteral("workpiece"),
                                    QStringLiteral("lathe"));
        job.insert(QStringLiteral("finish_diameter_mm"),
                   workpiece.required(QStringLiteral("finish_diameter_mm"), 0.1, 10000.0));
    }
    return feedPassJobFromJson(job, QStringLiteral("job"));
}

devices::FeedPassProgram feedPassProgram(const core::FeedSchedule& schedule, const core::FeedScheduleRequest& request,
                                         const DeformationModelFile& model) {
    devices::FeedPassProgram program;
    const DeformationModelStatistics& st = model.statistics;
    program.notes.push_back("MODEL " + std::to_string(st.termCount) + " TERMS " + st.termSet +
                            (st.stepwise ? " STEPWISE" : "") + ", N " + std::to_string(st.pointCount) + ", R2 " +
                            fixed(st.r2, 4) + ", RESIDUAL 2 SIGMA " + fixed(st.twoSigmaUm(), 2) + " UM");
    if (!model.sourceFile.isEmpty() || !model.preset.isEmpty())
        program.notes.push_back("FITTED FROM " + model.sourceFile.toStdString() +
                                (model.preset.isEmpty() ? "" : ", SET-UP " + model.preset.toStdString()));
    program.notes.push_back("YC " + fixed(schedule.levelUm, 2) + " UM IN Y1 " + fixed(schedule.y1Um, 2) + " .. Y2 " +
                            fixed(schedule.y2Um, 2) + " UM, DEPTH " + fixed(request.depthMm, 3) + " MM");
    program.notes.push_back("FEEDS " + fixed(request.feedMinMmPerRev, 4) + " .. " + fixed(request.feedMaxMmPerRev, 4) +
                            " MM/REV, STEP " + fixed(request.feedStepMmPerRev, 4) + ", LMIN " +
                            fixed(request.minLengthMm, 1) + " MM, " + std::to_string(schedule.segments.size()) +
                            " SEGMENTS");
    for (const core::FeedSegment& s : schedule.segments)
        program.segments.push_back({s.zFromMm, s.zToMm, s.feedMmPerRev, s.yFromUm, s.yToUm});
    return program;
}

}  // namespace tt::config
