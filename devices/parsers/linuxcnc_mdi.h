#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

/// The MDI lines TrueTurn sends to LinuxCNC to write corrections and to have the controller check what it
/// holds (rs274ngc syntax, LinuxCNC 2.9). Pure functions, so the exact text is tested without a controller.
/// An MDI line is at most 254 characters (LinuxCNC's LINELEN); longer writes are split over several lines.
namespace tt::devices::linuxcnc {

/// The named parameter the checks assign: a division by zero (an interpreter error, so the MDI command is
/// refused) when a value differs, 1 when all match.
inline constexpr const char* kCheckParameter = "#<_trueturn_check>";
/// The named parameter that keeps the programmed X before the wear is applied (wear check).
inline constexpr const char* kReferenceParameter = "#<_trueturn_x_before_wear>";
/// Lowest and highest numbered parameter a part program may use for corrections (LinuxCNC: 31 .. 5000 are
/// free for programs).
inline constexpr int kFirstFreeParameter = 31;
inline constexpr int kLastFreeParameter = 5000;
/// Longest MDI line LinuxCNC takes, characters.
inline constexpr std::size_t kMaxMdiLength = 254;

/// How the part program reads numbers: its units and its X mode.
struct ProgramConventions {
    bool inch = false;          ///< G20 (inch) instead of G21 (mm)
    bool diameterMode = false;  ///< G7 (X is a diameter) instead of G8 (radius)
};

/// Corrections as numbered parameters.
struct ParameterWrite {
    /// "#500=0.012300 #501=... ": the values, at most eight a line; the last line ends with the token
    /// ("#505=12"), so a program never sees a token with only some of the values written.
    std::vector<std::string> lines;
    /// The lines that make LinuxCNC compare what it holds with what was written (at most five values a line).
    std::vector<std::string> checks;
    std::vector<double> writtenMm;      ///< each value as LinuxCNC holds it, radial mm (after rounding)
    std::vector<std::string> literals;  ///< each value as written, in the program's units and X mode
};

/// Writes the radial corrections `radialMm` into #first .. #first+N-1 in the program's units (mm or inch) and
/// X mode (a diameter correction, twice the radial one, in diameter mode), six decimals, and `token` (the
/// part number the corrections are for, >= 1) into #first+N: the parametric program refuses to cut when it
/// is not set and clears it, so a part never runs on stale values. Throws std::invalid_argument for no values,
/// a value that is not finite or beyond 1000 mm, parameters outside 31 .. 5000 or a token < 1.
ParameterWrite parameterWrite(int first, std::span<const double> radialMm, std::int64_t token,
                              const ProgramConventions& conventions);

/// The X wear of tool entry `wearTool` set to the radial correction `radialMm` by G10 L1.
struct WearWrite {
    std::string modes;                ///< "G21 G8": the units and X mode the words are read in
    std::string line;                 ///< "G10 L1 P10001 X-0.012000" (in diameter mode the diameter correction)
    std::vector<std::string> verify;  ///< the lines that apply it and make LinuxCNC compare it (see wearWrite)
    double writtenMm = 0.0;           ///< the radial wear as LinuxCNC holds it, mm (after rounding)
    std::string literal;              ///< the X word's value as written
};

/// The wear write and its check, in the program's units and X mode (in diameter mode LinuxCNC stores half the
/// X word of G10 L1, so the word is the diameter correction): G43 H<tool> (the tool's own offset), remember the
/// programmed X (#5420, always a radius), G43.2 H<wearTool> (add the wear entry), then compare the change of
/// the programmed X with the radial wear: the check proves the wear that a program applying
/// `G43.2 H<wearTool>` after its `G43` gets. Throws std::invalid_argument for a tool or wear tool < 1 or a value
/// that is not finite or beyond 1000 mm.
WearWrite wearWrite(int tool, int wearTool, double radialMm, const ProgramConventions& conventions);

/// `(DEBUG,<tag> #a #b ...)`: LinuxCNC answers with the values of the parameters as an operator message (read
/// back only to report what it holds when a check failed: the message takes the controller 0.1 s).
std::string debugLine(const std::string& tag, std::span<const std::string> parameters);

/// "#500" for parameter 500.
std::string parameterName(int number);

/// `value` with six decimals, never "-0.000000".
std::string sixDecimals(double value);

}  // namespace tt::devices::linuxcnc
