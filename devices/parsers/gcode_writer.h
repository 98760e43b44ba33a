#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/ports/correction_output.h"

namespace tt::devices {

/// What the G-code of the corrected finishing pass needs besides the path: the part and the
/// machine conventions. Lathe, metric (G21), feed per revolution (G95), XZ plane (G18).
struct GCodeJob {
    double nominalDiameterMm = 27.0;  ///< finished diameter the correction is added to, mm
    double feedMmPerRev = 0.25;       ///< finishing feed, mm/rev (paper 000: 0.25)
    int spindleRpm = 546;             ///< constant spindle speed, rpm (0: leave the spindle alone)
    bool diameterMode = true;         ///< X words are diameters (else radii)
    bool emitModeCode = false;        ///< also write G7 (diameter) / G8 (radius), as LinuxCNC expects
    double zOriginMm = 0.0;           ///< machine Z of the part's x = 0 (its left end), mm
    int zDirection = -1;              ///< machine Z = zOriginMm + zDirection * x (+1 or -1)
    double clearanceMm = 2.0;         ///< radial and axial clearance of the approach and retract, mm
    int toolNumber = 1;               ///< T word (tool and offset number), 1..99
    int programNumber = 1001;         ///< O word, 1..9999
    double maxCorrectionMm = 0.5;     ///< largest radial correction accepted, mm (safety limit)
};

/// The G-code program of the corrected cutting path for the next part. The header states the
/// part, the units (G21, mm), the X mode (diameter or radius) and the sign convention; each G1
/// segment ends at one point of the path with its correction in a comment (the approximation
/// unit's correction per segment, paper 000: y_set(x) = y_ff(x) + y(x)). Coordinates with three
/// decimals (0.001 mm). Throws std::invalid_argument, in the user's terms, for an empty or
/// inconsistent path, non-finite values, a correction beyond maxCorrectionMm, or a bad job.
std::string writeCorrectionGCode(const core::PartCorrection& correction, const GCodeJob& job);

/// The G-code dialect of a program: what the control expects around the same moves.
enum class GCodeDialect {
    Fanuc,     ///< Fanuc-style, G-code system B (G90 absolute, G95 feed/rev): O number, T0101, X in diameter
    LinuxCnc,  ///< LinuxCNC (rs274ngc): program number in a comment, G7 diameter mode, T1 M6 G43
};

/// "fanuc" or "linuxcnc".
std::string gcodeDialectName(GCodeDialect dialect);
/// The dialect named `name` ("fanuc", "linuxcnc"); throws std::invalid_argument listing both.
GCodeDialect gcodeDialectFromName(const std::string& name);

/// The machine and part conventions of a longitudinal pass with a scheduled feed (paper 004): metric
/// (G21), absolute (G90), feed per revolution (G95), XZ plane (G18), X words are diameters.
struct FeedPassJob {
    double finishDiameterMm = 50.0;  ///< the diameter the pass leaves (X of the cut), mm
    double depthMm = 1.0;            ///< radial depth of cut a, mm: the blank is finishDiameter + 2a
    int spindleRpm = 730;            ///< constant spindle speed (G97 S), rpm, 1..10000
    bool coolant = true;             ///< flood coolant on (M8) during the pass, off (M9) after
    int toolNumber = 1;              ///< tool (and offset) number, 1..99
    int programNumber = 4004;        ///< O word (Fanuc) or the number in the header comment, 1..9999
    double zOriginMm = 0.0;          ///< machine Z of the model's z = 0, mm
    int zDirection = 1;              ///< machine Z = zOriginMm + zDirection * z (+1 or -1)
    double clearanceMm = 2.0;        ///< radial and axial clearance of the approach and retract, mm
    GCodeDialect dialect = GCodeDialect::Fanuc;
};

/// One segment of the pass at constant feed, in the model's z (mm) and in the order of travel.
struct FeedPassSegment {
    double zFromMm = 0.0;
    double zToMm = 0.0;
    double feedMmPerRev = 0.0;
    double yFromUm = 0.0;  ///< predicted deformation at zFrom, µm (for the header comment)
    double yToUm = 0.0;    ///< predicted deformation at zTo, µm
};

/// What the program of a scheduled pass states and does: the segments and the header's notes (the
/// model, the level Yc; one comment line each, printable ASCII, parentheses replaced).
struct FeedPassProgram {
    std::vector<FeedPassSegment> segments;
    std::vector<std::string> notes;
};

/// The CNC program of a feed-scheduled pass (paper 004: automatic part programming): a header
/// comment (units, X mode, the notes, one line per segment with its feed and predicted deformation),
/// G18 G21 G40 G90 G95, the tool, G97 S.. M3, M8, the approach a clearance before z_start outside the
/// blank, then one `G1 Z.. F..` per segment, the retract, M9, M5, M30. Z with three decimals, feeds
/// with four (rounded down to 0.0001 mm/rev, so the program never asks for more than the schedule).
/// Throws std::invalid_argument, in the user's terms, for no segments, segments that do not join or
/// reverse, non-finite values, a feed outside (0, 5] mm/rev, or a bad job.
std::string writeFeedScheduleGCode(const FeedPassProgram& program, const FeedPassJob& job);

}  // namespace tt::devices
