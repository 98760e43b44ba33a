#include "config/lathe_config.h"

#include <QJsonValue>
#include <limits>
#include <stdexcept>

#include "config/json_eigen.h"

namespace tt::config {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

QJsonObject section(const QJsonObject& parent, const QString& key, const QString& where) {
    const QJsonValue v = parent.value(key);
    if (v.isUndefined()) return {};
    if (!v.isObject())
        throw std::invalid_argument((where + QLatin1Char('.') + key).toStdString() + ": must be an object");
    return v.toObject();
}

/// optionalNumber with the section named in the message.
double number(const QJsonObject& object, const QString& where, const QString& key, double fallback, double minValue,
              double maxValue) {
    try {
        return optionalNumber(object, key, fallback, minValue, maxValue);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(where.toStdString() + "." + e.what());
    }
}

double positive(const QJsonObject& object, const QString& where, const QString& key, double fallback) {
    const double v = number(object, where, key, fallback, 0.0, kInf);
    if (v <= 0.0) throw std::invalid_argument((where + QLatin1Char('.') + key).toStdString() + ": must be > 0");
    return v;
}

bool flag(const QJsonObject& object, const QString& where, const QString& key, bool fallback) {
    const QJsonValue v = object.value(key);
    if (v.isUndefined()) return fallback;
    if (!v.isBool())
        throw std::invalid_argument((where + QLatin1Char('.') + key).toStdString() + ": must be true or false");
    return v.toBool();
}

}  // namespace

core::LatheSetup latheSetupFromJson(const QJsonObject& lathe) {
    core::LatheSetup s;
    const QString root = QStringLiteral("lathe");
    const QString wp = root + QStringLiteral(".workpiece");
    const QJsonObject w = section(lathe, QStringLiteral("workpiece"), root);
    s.workpiece.lengthMm = positive(w, wp, QStringLiteral("length_mm"), s.workpiece.lengthMm);
    s.workpiece.finishDiameterMm = positive(w, wp, QStringLiteral("finish_diameter_mm"), s.workpiece.finishDiameterMm);
    s.workpiece.youngModulusNPerMm2 =
        positive(w, wp, QStringLiteral("young_modulus_n_per_mm2"), s.workpiece.youngModulusNPerMm2);

    const QString cp = root + QStringLiteral(".cutting");
    const QJsonObject c = section(lathe, QStringLiteral("cutting"), root);
    s.cutting.depthOfCutMm = positive(c, cp, QStringLiteral("depth_mm"), s.cutting.depthOfCutMm);
    s.cutting.feedMmPerRev = positive(c, cp, QStringLiteral("feed_mm_per_rev"), s.cutting.feedMmPerRev);
    s.cutting.cuttingSpeedMPerMin = positive(c, cp, QStringLiteral("speed_m_per_min"), s.cutting.cuttingSpeedMPerMin);
    s.cutting.feedTowardsHeadstock =
        flag(c, cp, QStringLiteral("feed_towards_headstock"), s.cutting.feedTowardsHeadstock);

    const QString fp = root + QStringLiteral(".force");
    const QJsonObject f = section(lathe, QStringLiteral("force"), root);
    s.force.specificForceNPerMm2 =
        positive(f, fp, QStringLiteral("specific_force_n_per_mm2"), s.force.specificForceNPerMm2);
    s.force.exponent = number(f, fp, QStringLiteral("exponent"), s.force.exponent, 0.0, 0.99);
    s.force.leadAngleDeg = number(f, fp, QStringLiteral("lead_angle_deg"), s.force.leadAngleDeg, 1.0, 179.0);
    s.force.referenceSpeedMPerMin =
        positive(f, fp, QStringLiteral("reference_speed_m_per_min"), s.force.referenceSpeedMPerMin);
    s.force.speedExponent = number(f, fp, QStringLiteral("speed_exponent"), s.force.speedExponent, -1.0, 1.0);

    const QString kp = root + QStringLiteral(".stiffness");
    const QJsonObject k = section(lathe, QStringLiteral("stiffness"), root);
    s.stiffness.headstockNPerMm = positive(k, kp, QStringLiteral("headstock_n_per_mm"), s.stiffness.headstockNPerMm);
    s.stiffness.tailstockNPerMm = positive(k, kp, QStringLiteral("tailstock_n_per_mm"), s.stiffness.tailstockNPerMm);
    s.stiffness.toolNPerMm = positive(k, kp, QStringLiteral("tool_n_per_mm"), s.stiffness.toolNPerMm);

    const QString up = root + QStringLiteral(".warm_up");
    const QJsonObject u = section(lathe, QStringLiteral("warm_up"), root);
    s.warmUp.diameterShiftMm = number(u, up, QStringLiteral("diameter_shift_mm"), s.warmUp.diameterShiftMm, -1.0, 1.0);
    s.warmUp.durationParts = positive(u, up, QStringLiteral("duration_parts"), s.warmUp.durationParts);

    const QString tp = root + QStringLiteral(".tool_wear");
    const QJsonObject t = section(lathe, QStringLiteral("tool_wear"), root);
    s.wear.diameterGrowthMm = number(t, tp, QStringLiteral("diameter_growth_mm"), s.wear.diameterGrowthMm, -1.0, 1.0);
    s.wear.toolLifeParts =
        static_cast<int>(number(t, tp, QStringLiteral("tool_life_parts"), s.wear.toolLifeParts, 1.0, 100000.0));
    s.wear.changeRepeatabilityMm =
        number(t, tp, QStringLiteral("change_repeatability_mm"), s.wear.changeRepeatabilityMm, 0.0, 1.0);

    const QString mp = root + QStringLiteral(".micrometer");
    const QJsonObject m = section(lathe, QStringLiteral("micrometer"), root);
    s.micrometer.resolutionMm = number(m, mp, QStringLiteral("resolution_mm"), s.micrometer.resolutionMm, 0.0, 1.0);
    s.micrometer.error95Mm = number(m, mp, QStringLiteral("error95_mm"), s.micrometer.error95Mm, 0.0, 1.0);

    s.toolSettingOffsetMm = number(lathe, root, QStringLiteral("tool_setting_offset_mm"), 0.0, -5.0, 5.0);
    s.beamElementMm = positive(lathe, root, QStringLiteral("element_length_mm"), s.beamElementMm);
    s.randomCommonShare = number(lathe, root, QStringLiteral("random_common_share"), s.randomCommonShare, 0.0, 1.0);
    s.randomScale = number(lathe, root, QStringLiteral("random_scale"), s.randomScale, 0.0, 100.0);
    try {
        core::validateLatheSetup(s);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("lathe: ") + e.what());
    }
    return s;
}

core::LatheStationTiming stationTimingFromJson(const QJsonObject& lathe) {
    core::LatheStationTiming t;
    const QString where = QStringLiteral("lathe.station");
    const QJsonObject s = section(lathe, QStringLiteral("station"), QStringLiteral("lathe"));
    t.partTimeS = positive(s, where, QStringLiteral("part_time_s"), t.partTimeS);
    t.measureStartS = number(s, where, QStringLiteral("measure_start_s"), t.measureStartS, 0.0, 1e6);
    t.perPointS = number(s, where, QStringLiteral("per_point_s"), t.perPointS, 0.0, 1e6);
    return t;
}

}  // namespace tt::config
