#include "devices/linuxcnc/linuxcnc_corrections.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>

namespace tt::devices::linuxcnc {

namespace {

double epochS() {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::string mm(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4f", value);
    return text;
}

bool isDivisionByZero(const std::string& why) {
    return why.find("divide by zero") != std::string::npos;
}

/// Radial mm of a value in the program's units and X mode.
double radialMm(double programValue, const ProgramConventions& c) {
    const double v = c.diameterMode ? programValue / 2.0 : programValue;
    return c.inch ? v * 25.4 : v;
}

}  // namespace

std::string correctionModeName(CorrectionMode mode) {
    return mode == CorrectionMode::Wear ? "wear" : "profile";
}

CorrectionMode correctionModeFromName(const std::string& name) {
    if (name == "profile") return CorrectionMode::Profile;
    if (name == "wear") return CorrectionMode::Wear;
    throw std::invalid_argument("unknown correction mode '" + name + "' (profile, wear)");
}

std::vector<double> valuesToWrite(const core::PartCorrection& correction, CorrectionMode mode) {
    const std::vector<double>& points = correction.pointCorrectionMm;
    if (mode == CorrectionMode::Profile || points.empty()) return points;
    return {std::accumulate(points.begin(), points.end(), 0.0) / static_cast<double>(points.size())};
}

std::string valuesText(const std::vector<double>& valuesMm) {
    std::string text;
    for (const double v : valuesMm)
        text += (text.empty() ? "" : ", ") + mm(v);
    return text + " mm";
}

std::string limitProblem(const std::vector<double>& values, const std::optional<std::vector<double>>& last,
                         const CorrectionSettings& s) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::string which = values.size() == 1 ? "the correction" : "correction " + std::to_string(i + 1);
        if (!std::isfinite(values[i])) return which + " is not a number";
        if (std::fabs(values[i]) > s.largestTotalMm)
            return which + " " + mm(values[i]) + " mm is beyond the largest correction of " + mm(s.largestTotalMm) +
                   " mm";
        if (last && last->size() == values.size() && std::fabs(values[i] - (*last)[i]) > s.largestStepMm)
            return which + " changes by " + mm(values[i] - (*last)[i]) + " mm, more than the largest step of " +
                   mm(s.largestStepMm) + " mm";
    }
    return {};
}

CorrectionWriter::CorrectionWriter(CorrectionSettings settings) : m_settings(settings) {}

WriteRecord CorrectionWriter::write(LinuxCncController& controller, std::int64_t part,
                                    const std::vector<double>& values) {
    WriteRecord record;
    record.partNumber = part;
    record.timeS = epochS();
    record.requestedMm = values;
    if (std::string problem = limitProblem(values, m_last, m_settings); !problem.empty()) {
        record.outcome = WriteOutcome::OutOfLimits;
        record.message = "part " + std::to_string(part) + ": " + problem + "; nothing written";
        return record;
    }
    const MachineStatus status = controller.status();
    if (std::string reason = notReadyReason(status); !reason.empty()) {
        record.outcome = WriteOutcome::NotReady;
        record.message = "part " + std::to_string(part) + ": " + reason + " at LinuxCNC " +
                         controller.options().endpoint.text() + "; nothing written";
        return record;
    }
    controller.setMode(TaskMode::Mdi);
    if (m_settings.mode == CorrectionMode::Profile)
        writeProfile(controller, record);
    else
        writeWear(controller, record);
    if (record.applied()) m_last = record.writtenMm;
    return record;
}

void CorrectionWriter::writeProfile(LinuxCncController& controller, WriteRecord& record) {
    const ParameterWrite w =
        parameterWrite(m_settings.firstParameter, record.requestedMm, record.partNumber, m_settings.conventions);
    const int t = controller.options().replyTimeoutMs;
    record.writtenMm = w.writtenMm;
    std::string why;
    for (const std::string& line : w.lines) {
        if (!controller.tryMdi(line, t, why)) {
            record.outcome = WriteOutcome::Refused;
            record.message =
                "part " + std::to_string(record.partNumber) + ": LinuxCNC refused the corrections (" + why + ")";
            return;
        }
    }
    for (const std::string& check : w.checks) {
        if (controller.tryMdi(check, t, why)) continue;
        if (!isDivisionByZero(why)) {
            record.outcome = WriteOutcome::Refused;
            record.message = "part " + std::to_string(record.partNumber) + ": LinuxCNC refused the check (" + why + ")";
            return;
        }
        std::vector<std::string> names;
        for (std::size_t i = 0; i < record.requestedMm.size(); ++i)
            names.push_back(parameterName(m_settings.firstParameter + static_cast<int>(i)));
        for (const double v : controller.readParameters(names))
            record.readBackMm.push_back(radialMm(v, m_settings.conventions));
        record.outcome = WriteOutcome::Differs;
        record.message = "part " + std::to_string(record.partNumber) + ": wrote " + valuesText(record.writtenMm) +
                         " but LinuxCNC holds " + valuesText(record.readBackMm) + "; not applied";
        return;
    }
    record.readBackMm = record.writtenMm;
    record.outcome = WriteOutcome::Verified;
    record.message = "part " + std::to_string(record.partNumber) + ": " + valuesText(record.writtenMm) +
                     " written to " + parameterName(m_settings.firstParameter) + ".. and read back";
}

void CorrectionWriter::writeWear(LinuxCncController& controller, WriteRecord& record) {
    const WearWrite w =
        wearWrite(m_settings.toolNumber, m_settings.wearTool, record.requestedMm.front(), m_settings.conventions);
    const int t = controller.options().replyTimeoutMs;
    record.writtenMm = {w.writtenMm};
    std::string why;
    if (!controller.tryMdi(w.modes, t, why) || !controller.tryMdi(w.line, t, why)) {
        record.outcome = WriteOutcome::Refused;
        record.message = "part " + std::to_string(record.partNumber) + ": LinuxCNC refused the wear of tool " +
                         std::to_string(m_settings.wearTool) + " (" + why + ")";
        return;
    }
    for (std::size_t i = 0; i < w.verify.size(); ++i) {
        if (controller.tryMdi(w.verify[i], t, why)) continue;
        if (i + 1 < w.verify.size() || !isDivisionByZero(why)) {
            record.outcome = WriteOutcome::Refused;
            record.message =
                "part " + std::to_string(record.partNumber) + ": LinuxCNC refused '" + w.verify[i] + "' (" + why + ")";
            return;
        }
        const std::vector<double> held = controller.readParameters({kReferenceParameter, "#5420"});
        const double radial = held[0] - held[1];  // a radius, in the program's units
        record.readBackMm = {m_settings.conventions.inch ? radial * 25.4 : radial};
        record.outcome = WriteOutcome::Differs;
        record.message = "part " + std::to_string(record.partNumber) + ": wrote the wear " +
                         valuesText(record.writtenMm) + " but LinuxCNC applies " + valuesText(record.readBackMm) +
                         "; not applied";
        return;
    }
    record.readBackMm = record.writtenMm;
    record.outcome = WriteOutcome::Verified;
    record.message = "part " + std::to_string(record.partNumber) + ": X wear " + valuesText(record.writtenMm) +
                     " written to tool " + std::to_string(m_settings.wearTool) + " and read back";
}

}  // namespace tt::devices::linuxcnc
