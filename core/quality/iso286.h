#pragma once

#include <string>

#include "core/common/tolerance.h"

namespace tt::core {

/// The largest nominal size the ISO 286 tables here cover, mm (ISO 286-1:2010 Table 1 up to 500 mm).
inline constexpr double kMaxIso286NominalMm = 500.0;

/// The standard tolerance IT1..IT18 of a nominal size in (0, 500] mm, mm (ISO 286-1:2010 Table 1; a size on
/// a range boundary belongs to the lower range, "over 3 up to and including 6"). Throws std::invalid_argument
/// on a grade or size outside the table.
double iso286StandardToleranceMm(int grade, double nominalMm);

/// The tolerance zone of a SHAFT (outer diameter) of `nominalMm` from an ISO 286 tolerance class such as
/// "h9", "js7", "k6": the letter's fundamental deviation (ISO 286-1:2010 Table 2, shafts: es for d, e, f, g,
/// h; ei for k, m, n, p; js = +-IT/2, with IT7..IT11 of an odd number of micrometres rounded down to the even
/// number below, ISO 286-1:2010 clause 4.1.2.3) and the other deviation one standard tolerance away. Covers
/// the letters d e f g h js k m n p, grades 1..18, sizes in (0, 500] mm. Throws std::invalid_argument naming
/// the class and what is not supported (hole classes in capitals included).
ToleranceZone iso286ShaftZone(double nominalMm, const std::string& toleranceClass);

}  // namespace tt::core
