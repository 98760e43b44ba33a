#include "config/lathe_config.h"

#include <stdexcept>

#include "config/json_section.h"

namespace tt::config {

core::LatheSetup latheSetupFromJson(const QJsonObject& lathe) {
    core::LatheSetup s;
    const QString root = QStringLiteral("lathe");
    const JsonSection w(lathe, QStringLiteral("workpiece"), root);
    s.workpiece.lengthMm = w.positive(QStringLiteral("length_mm"), s.workpiece.lengthMm);
    s.workpiece.finishDiameterMm = w.positive(QStringLiteral("finish_diameter_mm"), s.workpiece.finishDiameterMm);
    s.workpiece.youngModulusNPerMm2 =
        w.positive(QStringLiteral("young_modulus_n_per_mm2"), s.workpiece.youngModulusNPerMm2);

    const JsonSection c(lathe, QStringLiteral("cutting"), root);
    s.cutting.depthOfCutMm = c.positive(QStringLiteral("depth_mm"), s.cutting.depthOfCutMm);
    s.cutting.feedMmPerRev = c.positive(QStringLiteral("feed_mm_per_rev"), s.cutting.feedMmPerRev);
    s.cutting.cuttingSpeedMPerMin = c.positive(QStringLiteral("speed_m_per_min"), s.cutting.cuttingSpeedMPerMin);
    s.cutting.feedTowardsHeadstock = c.flag(QStringLiteral("feed_towards_headstock"), s.cutting.feedTowardsHeadstock);

    const JsonSection f(lathe, QStringLiteral("force"), root);
    s.force.specificForceNPerMm2 = f.positive(QStringLiteral("specific_force_n_per_mm2"), s.force.specificForceNPerMm2);
    s.force.exponent = f.number(QStringLiteral("exponent"), s.force.exponent, 0.0, 0.99);
    s.force.leadAngleDeg = f.number(QStringLiteral("lead_angle_deg"), s.force.leadAngleDeg, 1.0, 179.0);
    s.force.referenceSpeedMPerMin =
        f.positive(QStringLiteral("reference_speed_m_per_min"), s.force.referenceSpeedMPerMin);
    s.force.speedExponent = f.number(QStringLiteral("speed_exponent"), s.force.speedExponent, -1.0, 1.0);

    const JsonSection k(lathe, QStringLiteral("stiffness"), root);
    s.stiffness.headstockNPerMm = k.positive(QStringLiteral("headstock_n_per_mm"), s.stiffness.headstockNPerMm);
    s.stiffness.tailstockNPerMm = k.positive(QStringLiteral("tailstock_n_per_mm"), s.stiffness.tailstockNPerMm);
    s.stiffness.toolNPerMm = k.positive(QStringLiteral("tool_n_per_mm"), s.stiffness.toolNPerMm);

    const JsonSection u(lathe, QStringLiteral("warm_up"), root);
    s.warmUp.diameterShiftMm = u.number(QStringLiteral("diameter_shift_mm"), s.warmUp.diameterShiftMm, -1.0, 1.0);
    s.warmUp.durationParts = u.positive(QStringLiteral("duration_parts"), s.warmUp.durationParts);

    const JsonSection t(lathe, QStringLiteral("tool_wear"), root);
    s.wear.diameterGrowthMm = t.number(QStringLiteral("diameter_growth_mm"), s.wear.diameterGrowthMm, -1.0, 1.0);
    s.wear.toolLifeParts =
        static_cast<int>(t.number(QStringLiteral("tool_life_parts"), s.wear.toolLifeParts, 1.0, 100000.0));
    s.wear.changeRepeatabilityMm =
        t.number(QStringLiteral("change_repeatability_mm"), s.wear.changeRepeatabilityMm, 0.0, 1.0);

    const JsonSection m(lathe, QStringLiteral("micrometer"), root);
    s.micrometer.resolutionMm = m.number(QStringLiteral("resolution_mm"), s.micrometer.resolutionMm, 0.0, 1.0);
    s.micrometer.error95Mm = m.number(QStringLiteral("error95_mm"), s.micrometer.error95Mm, 0.0, 1.0);

    const JsonSection top = JsonSection::of(lathe, root);
    s.toolSettingOffsetMm = top.number(QStringLiteral("tool_setting_offset_mm"), 0.0, -5.0, 5.0);
    s.beamElementMm = top.positive(QStringLiteral("element_length_mm"), s.beamElementMm);
    s.randomCommonShare = top.number(QStringLiteral("random_common_share"), s.randomCommonShare, 0.0, 1.0);
    s.randomScale = top.number(QStringLiteral("random_scale"), s.randomScale, 0.0, 100.0);
    try {
        core::validateLatheSetup(s);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("lathe: ") + e.what());
    }
    return s;
}

core::LatheStationTiming stationTimingFromJson(const QJsonObject& lathe) {
    core::LatheStationTiming t;
    const JsonSection s(lathe, QStringLiteral("station"), QStringLiteral("lathe"));
    t.partTimeS = s.number(QStringLiteral("part_time_s"), t.partTimeS, 1.0, 86400.0);
    t.measureStartS = s.number(QStringLiteral("measure_start_s"), t.measureStartS, 0.0, 1e6);
    t.perPointS = s.number(QStringLiteral("per_point_s"), t.perPointS, 0.0, 1e6);
    return t;
}

}  // namespace tt::config
