#include "devices/parsers/gcode_writer.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace tt::devices {

namespace {

/// The words every program of this writer has: the Z direction, the clearance, the tool and the program
/// number (GCodeJob and FeedPassJob alike).
template <typename Job>
void checkMachineWords(const Job& job) {
    if (job.zDirection != 1 && job.zDirection != -1)
        throw std::invalid_argument("G-code: the Z direction must be +1 or -1");
    if (!(job.clearanceMm > 0.0 && job.clearanceMm <= 100.0))
        throw std::invalid_argument("G-code: the clearance must be between 0 and 100 mm");
    if (job.toolNumber < 1 || job.toolNumber > 99)
        throw std::invalid_argument("G-code: the tool number must be 1 to 99");
    if (job.programNumber < 1 || job.programNumber > 9999)
        throw std::invalid_argument("G-code: the program number must be 1 to 9999");
}

std::string mm(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", std::fabs(value) < 0.0005 ? 0.0 : value);
    return text;
}

void checkJob(const GCodeJob& job) {
    if (!(job.nominalDiameterMm > 0.0) || !std::isfinite(job.nominalDiameterMm))
        throw std::invalid_argument("G-code: the nominal diameter must be a positive number of millimetres");
    if (!(job.feedMmPerRev > 0.0 && job.feedMmPerRev <= 5.0))
        throw std::invalid_argument("G-code: the feed must be between 0 and 5 mm/rev");
    if (job.spindleRpm < 0 || job.spindleRpm > 10000)
        throw std::invalid_argument("G-code: the spindle speed must be 0 to 10000 rpm");
    checkMachineWords(job);
    if (!(job.maxCorrectionMm > 0.0) || !std::isfinite(job.zOriginMm))
        throw std::invalid_argument("G-code: the correction limit must be positive and the Z origin finite");
}

void checkPath(const core::CorrectionPath& path, const GCodeJob& job) {
    const std::size_t n = path.zMm.size();
    if (n < 2) throw std::invalid_argument("G-code: the correction path needs at least two points");
    if (path.xCorrectionMm.size() != n)
        throw std::invalid_argument("G-code: the correction path has " + std::to_string(n) + " positions but " +
                                    std::to_string(path.xCorrectionMm.size()) + " corrections");
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(path.zMm[i]) || !std::isfinite(path.xCorrectionMm[i]))
            throw std::invalid_argument("G-code: point " + std::to_string(i + 1) + " of the path is not a number");
        if (i > 0 && !(path.zMm[i] > path.zMm[i - 1]))
            throw std::invalid_argument("G-code: the path positions must increase (point " + std::to_string(i + 1) +
                                        " at " + mm(path.zMm[i]) + " mm)");
        if (std::fabs(path.xCorrectionMm[i]) > job.maxCorrectionMm)
            throw std::invalid_argument("G-code: the correction " + mm(path.xCorrectionMm[i]) + " mm at " +
                                        mm(path.zMm[i]) + " mm exceeds the limit of " + mm(job.maxCorrectionMm) +
                                        " mm");
        if (job.nominalDiameterMm / 2.0 + path.xCorrectionMm[i] <= 0.0)
            throw std::invalid_argument("G-code: the correction at " + mm(path.zMm[i]) +
                                        " mm would cut through the axis");
    }
}

}  // namespace

std::string writeCorrectionGCode(const core::PartCorrection& correction, const GCodeJob& job) {
    checkJob(job);
    const core::CorrectionPath& path = correction.path;
    checkPath(path, job);
    const double factor = job.diameterMode ? 2.0 : 1.0;
    const double nominalX = job.diameterMode ? job.nominalDiameterMm : job.nominalDiameterMm / 2.0;
    auto xWord = [&](double correctionMm) { return mm(nominalX + factor * correctionMm); };
    auto zWord = [&](double x) { return mm(job.zOriginMm + job.zDirection * x); };
    const double safeX = nominalX + factor * (job.maxCorrectionMm + job.clearanceMm);
    // Approach and retract a clearance before the first point of the path, outside the part.
    const double approachZ = job.zOriginMm + job.zDirection * (path.zMm.front() - job.clearanceMm);

    std::string out;
    auto line = [&](const std::string& text) { out += text + "\n"; };
    char head[64];
    std::snprintf(head, sizeof head, "O%04d (TRUETURN CORRECTED FINISHING PASS)", job.programNumber);
    line("%");
    line(head);
    line("(PART " + std::to_string(correction.partNumber) + ")");
    line("(LATHE, METRIC: G21, MILLIMETRES; FEED PER REVOLUTION: G95)");
    line(job.diameterMode ? "(X WORDS ARE DIAMETERS: DIAMETER MODE)" : "(X WORDS ARE RADII: RADIUS MODE)");
    line("(NOMINAL DIAMETER " + mm(job.nominalDiameterMm) + " MM, FEED " + mm(job.feedMmPerRev) + " MM/REV)");
    line("(MACHINE Z = " + mm(job.zOriginMm) + (job.zDirection > 0 ? " + " : " - ") + "PART X)");
    line("(CORRECTION DX IS RADIAL, MM, NEGATIVE = TOWARDS THE AXIS; " + std::to_string(path.zMm.size() - 1) +
         " SEGMENTS)");
    if (!correction.pointZMm.empty() && correction.pointZMm.size() == correction.pointCorrectionMm.size()) {
        std::string points = "(CONTROL POINTS:";
        for (std::size_t i = 0; i < correction.pointZMm.size(); ++i)
            points += " X" + mm(correction.pointZMm[i]) + "=" + mm(correction.pointCorrectionMm[i]);
        line(points + ")");
    }
    line(std::string("G18 G21 G40 G90 G95") + (job.emitModeCode ? (job.diameterMode ? " G7" : " G8") : ""));
    char tool[16];
    std::snprintf(tool, sizeof tool, "T%02d%02d", job.toolNumber, job.toolNumber);
    line(tool);
    if (job.spindleRpm > 0) line("G97 S" + std::to_string(job.spindleRpm) + " M3");
    line("G0 X" + mm(safeX) + " Z" + mm(approachZ));
    line("G0 X" + xWord(path.xCorrectionMm.front()));
    line("G1 Z" + zWord(path.zMm.front()) + " F" + mm(job.feedMmPerRev) + " (START X" + mm(path.zMm.front()) + " DX" +
         mm(path.xCorrectionMm.front()) + ")");
    for (std::size_t i = 1; i < path.zMm.size(); ++i)
        line("G1 X" + xWord(path.xCorrectionMm[i]) + " Z" + zWord(path.zMm[i]) + " (SEG " + std::to_string(i) + " X" +
             mm(path.zMm[i]) + " DX" + mm(path.xCorrectionMm[i]) + ")");
    line("G0 X" + mm(safeX));
    line("G0 Z" + mm(approachZ));
    if (job.spindleRpm > 0) line("M5");
    line("M30");
    line("%");
    return out;
}

namespace {

/// Feed with four decimals, rounded down (0.0001 mm/rev is the finest feed word of both dialects).
std::string feedWord(double feedMmPerRev) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4f", std::floor(feedMmPerRev * 1e4 + 1e-6) / 1e4);
    return text;
}

/// A comment's text: upper case, printable ASCII, no parentheses (neither dialect nests comments).
std::string commentText(const std::string& text) {
    std::string out;
    for (unsigned char c : text) {
        if (c == '(' || c == '[')
            out += '<';
        else if (c == ')' || c == ']')
            out += '>';
        else if (c >= 0x20 && c < 0x7f)
            out += static_cast<char>(std::toupper(c));
    }
    return out;
}

void checkFeedJob(const FeedPassJob& job) {
    if (!(job.finishDiameterMm > 0.0) || !std::isfinite(job.finishDiameterMm) || job.finishDiameterMm > 10000.0)
        throw std::invalid_argument("G-code: the finished diameter must be between 0 and 10000 mm");
    if (!(job.depthMm > 0.0) || !std::isfinite(job.depthMm) || job.depthMm > 50.0)
        throw std::invalid_argument("G-code: the depth of cut must be between 0 and 50 mm");
    if (job.spindleRpm < 1 || job.spindleRpm > 10000)
        throw std::invalid_argument("G-code: the spindle speed must be 1 to 10000 rpm (got " +
                                    std::to_string(job.spindleRpm) + ")");
    checkMachineWords(job);
    if (!std::isfinite(job.zOriginMm) || std::fabs(job.zOriginMm) > 100000.0)
        throw std::invalid_argument("G-code: the Z origin must be a finite number within 100 m");
}

void checkSegments(const std::vector<FeedPassSegment>& segments) {
    if (segments.empty()) throw std::invalid_argument("G-code: the feed schedule has no segments");
    const double direction = segments.front().zToMm >= segments.front().zFromMm ? 1.0 : -1.0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const FeedPassSegment& s = segments[i];
        const std::string which = "G-code: segment " + std::to_string(i + 1);
        if (!std::isfinite(s.zFromMm) || !std::isfinite(s.zToMm) || !std::isfinite(s.feedMmPerRev) ||
            !std::isfinite(s.yFromUm) || !std::isfinite(s.yToUm))
            throw std::invalid_argument(which + " has a value that is not a number");
        if (!(s.feedMmPerRev > 0.0 && s.feedMmPerRev <= 5.0))
            throw std::invalid_argument(which + ": the feed " + feedWord(s.feedMmPerRev) +
                                        " mm/rev is outside (0, 5] mm/rev");
        if (!(direction * (s.zToMm - s.zFromMm) > 0.0))
            throw std::invalid_argument(which + " does not advance in the direction of the pass (from " +
                                        mm(s.zFromMm) + " to " + mm(s.zToMm) + " mm)");
        if (i > 0 && std::fabs(s.zFromMm - segments[i - 1].zToMm) > 1e-9)
            throw std::invalid_argument(which + " starts at " + mm(s.zFromMm) + " mm, not where segment " +
                                        std::to_string(i) + " ends (" + mm(segments[i - 1].zToMm) + " mm)");
    }
}

}  // namespace

std::string gcodeDialectName(GCodeDialect dialect) {
    return dialect == GCodeDialect::LinuxCnc ? "linuxcnc" : "fanuc";
}

GCodeDialect gcodeDialectFromName(const std::string& name) {
    if (name == "fanuc") return GCodeDialect::Fanuc;
    if (name == "linuxcnc") return GCodeDialect::LinuxCnc;
    throw std::invalid_argument("unknown G-code dialect '" + name + "' (fanuc, linuxcnc)");
}

std::string writeFeedScheduleGCode(const FeedPassProgram& program, const FeedPassJob& job) {
    checkFeedJob(job);
    checkSegments(program.segments);
    const bool fanuc = job.dialect == GCodeDialect::Fanuc;
    const std::vector<FeedPassSegment>& segments = program.segments;
    const double travel = segments.front().zToMm > segments.front().zFromMm ? 1.0 : -1.0;
    auto zWord = [&](double z) { return mm(job.zOriginMm + job.zDirection * z); };
    const double safeX = job.finishDiameterMm + 2.0 * job.depthMm + 2.0 * job.clearanceMm;
    const double approachZ = segments.front().zFromMm - travel * job.clearanceMm;

    std::string out;
    auto line = [&](const std::string& text) { out += text + "\n"; };
    auto comment = [&](const std::string& text) {
        std::string c(1, '(');
        c += commentText(text);
        c += ')';
        line(c);
    };
    char number[16];
    std::snprintf(number, sizeof number, "%04d", job.programNumber);
    line("%");
    if (fanuc)
        line(std::string("O") + number + " (TRUETURN FEED SCHEDULE)");
    else
        comment(std::string("PROGRAM ") + number + " TRUETURN FEED SCHEDULE");
    comment(fanuc ? "FANUC-STYLE, G-CODE SYSTEM B: G90 ABSOLUTE, G95 FEED PER REVOLUTION" : "LINUXCNC");
    comment("LATHE, METRIC: G21, MILLIMETRES; X WORDS ARE DIAMETERS");
    comment("FEED SCHEDULED AGAINST FORCE DEFORMATION Y<A, F, Z>, PAPER 004");
    for (const std::string& note : program.notes)
        comment(note);
    comment("PASS DIAMETER " + mm(job.finishDiameterMm) + " MM, DEPTH " + mm(job.depthMm) + " MM, " +
            std::to_string(job.spindleRpm) + " RPM, MACHINE Z = " + mm(job.zOriginMm) +
            (job.zDirection > 0 ? " + " : " - ") + "MODEL Z");
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const FeedPassSegment& s = segments[i];
        char y[64];
        std::snprintf(y, sizeof y, " Y %.1f TO %.1f UM", s.yFromUm, s.yToUm);
        comment("SEG " + std::to_string(i + 1) + " Z" + zWord(s.zFromMm) + " TO Z" + zWord(s.zToMm) + " F" +
                feedWord(s.feedMmPerRev) + y);
    }
    line(fanuc ? "G18 G21 G40 G90 G95" : "G18 G21 G40 G90 G95 G7");
    char tool[24];
    if (fanuc)
        std::snprintf(tool, sizeof tool, "T%02d%02d", job.toolNumber, job.toolNumber);
    else
        std::snprintf(tool, sizeof tool, "T%d M6 G43", job.toolNumber);
    line(tool);
    line("G97 S" + std::to_string(job.spindleRpm) + " M3");
    if (job.coolant) line("M8");
    line("G0 X" + mm(safeX) + " Z" + zWord(approachZ));
    line("G0 X" + mm(job.finishDiameterMm));
    line("G1 Z" + zWord(segments.front().zFromMm) + " F" + feedWord(segments.front().feedMmPerRev));
    for (const FeedPassSegment& s : segments)
        line("G1 Z" + zWord(s.zToMm) + " F" + feedWord(s.feedMmPerRev));
    line("G0 X" + mm(safeX));
    line("G0 Z" + zWord(approachZ));
    if (job.coolant) line("M9");
    line("M5");
    line("M30");
    line("%");
    return out;
}

}  // namespace tt::devices
