#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/ports/correction_output.h"
#include "devices/linuxcnc/linuxcnc_controller.h"
#include "devices/parsers/linuxcnc_mdi.h"

namespace tt::devices::linuxcnc {

/// How the correction reaches the cut.
enum class CorrectionMode {
    Profile,  ///< the control-point corrections as numbered parameters read by TrueTurn's parametric program
    Wear,     ///< one correction (their mean) as the X wear of a tool entry, applied by the shop's program (G43.2)
};

/// "profile" / "wear"; the mode named so (throws std::invalid_argument listing both).
std::string correctionModeName(CorrectionMode mode);
CorrectionMode correctionModeFromName(const std::string& name);

/// What is written where, and the limits checked before every write.
struct CorrectionSettings {
    CorrectionMode mode = CorrectionMode::Profile;
    int firstParameter = 500;        ///< profile: #first .. #first+N-1, the part number at #first+N
    int toolNumber = 1;              ///< the tool that cuts the part (its offset is applied by G43)
    int wearTool = 10001;            ///< wear: the tool-table entry holding the X wear (G43.2 H<wearTool>)
    ProgramConventions conventions;  ///< the part program's units and X mode the values are written in
    double largestStepMm = 0.1;      ///< largest change of a value from the last written one, radial mm
    double largestTotalMm = 0.5;     ///< largest value, radial mm
};

/// How a write ended.
enum class WriteOutcome {
    Verified,     ///< written and read back equal: applied
    OutOfLimits,  ///< beyond the largest step or total: nothing written
    NotReady,     ///< E-stop, machine off, not homed or a program running: nothing written
    Refused,      ///< LinuxCNC refused the write
    Differs,      ///< written, but LinuxCNC holds other values: not applied
};

/// One write, for the history: what was asked, written and read back, and whether it counts as applied.
struct WriteRecord {
    std::int64_t partNumber = 0;
    double timeS = 0.0;               ///< when, s since the Unix epoch
    std::vector<double> requestedMm;  ///< radial mm: one per control point (profile) or one (wear)
    std::vector<double> writtenMm;    ///< as written, after rounding to the program's six decimals
    std::vector<double> readBackMm;   ///< what LinuxCNC holds (empty when nothing was written or read)
    WriteOutcome outcome = WriteOutcome::Refused;
    std::string message;  ///< in the user's terms: what was written, or why it was not applied
    bool applied() const { return outcome == WriteOutcome::Verified; }
};

/// The values the mode writes for a part: its per-point corrections (profile) or their mean (wear: the one
/// size correction that the control points share, least squares).
std::vector<double> valuesToWrite(const core::PartCorrection& correction, CorrectionMode mode);

/// Why `values` may not be written (beyond the largest total, or further than the largest step from `last`),
/// in the user's terms; empty when they may.
std::string limitProblem(const std::vector<double>& values, const std::optional<std::vector<double>>& last,
                         const CorrectionSettings& settings);

/// Writes corrections into LinuxCNC between parts and has LinuxCNC compare what it holds with what was written
/// (never with `get tool_offset`, which returns garbage): profile mode by the check lines of parameterWrite,
/// wear mode by applying the wear (G43.2) and comparing the programmed X. On a difference the values LinuxCNC
/// holds are read back with an operator message for the report. Use from the thread that owns the controller.
class CorrectionWriter {
public:
    explicit CorrectionWriter(CorrectionSettings settings);
    /// Writes `values` for part `part`. Refusals, differences, limits and an unready machine end in the record;
    /// a failed connection throws LinuxCncError (the caller resets it).
    WriteRecord write(LinuxCncController& controller, std::int64_t part, const std::vector<double>& values);
    /// The values last verified (the reference of the step limit).
    const std::optional<std::vector<double>>& lastVerified() const { return m_last; }
    const CorrectionSettings& settings() const { return m_settings; }

private:
    void writeProfile(LinuxCncController& controller, WriteRecord& record);
    void writeWear(LinuxCncController& controller, WriteRecord& record);

    CorrectionSettings m_settings;
    std::optional<std::vector<double>> m_last;
};

/// "0.0123, -0.0040 mm": values for messages, four decimals.
std::string valuesText(const std::vector<double>& valuesMm);

}  // namespace tt::devices::linuxcnc
