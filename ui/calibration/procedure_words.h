#pragma once

#include <QCoreApplication>
#include <QString>
#include <vector>

#include "core/calibration/kp_procedure.h"
#include "core/calibration/probe_procedure.h"

namespace tt::ui {

/// The calibration procedures' events and outcomes (core kinds with data) in the operator's words
/// and language. Plain text; the callers escape it for rich text.
class ProcedureWords {
    Q_DECLARE_TR_FUNCTIONS(ProcedureWords)
public:
    /// A probe capture event: point captured, repeated, typed, removed, or why none was read.
    static QString probeEvent(const core::ProbeEvent& event, int adcBits, double noSampleTimeoutS);
    /// Why the captured points give no table.
    static QString fitRefusal(const core::ProbeFitOutcome& outcome, int adcBits);
    /// How the degree was chosen.
    static QString degreeChoice(const core::CharacteristicFit& fit, int pointsUsed);
    /// The saturated points left out of the fit ("Points 22 and 23 are not used …").
    static QString leftOut(const std::vector<int>& points, int adcBits);
    /// A verification point of the table.
    static QString probeCheck(const core::ProbeCheck& check);
    /// How an upload ended (verified, read-back differs, refused, failed).
    static QString uploadOutcome(const core::TableUploadProcedure& upload);
    /// What the mandrel reports against the image sent (the upload has a read-back).
    static QString readbackDiffers(const core::TableUploadProcedure& upload);
    /// "CRC-32C 0x1A2B3C4D" or "CRC-16 0x1A2B".
    static QString crc(const core::TableReadback& readback);

    /// A k_p measurement event: load measured, repeated, typed, removed, or why none was read.
    static QString kpEvent(const core::KpEvent& event, double noSampleTimeoutS);
    /// Why the dithering cross feed gives no current difference.
    static QString strokeProblem(core::StrokeProblem problem);
    /// Why the loads give no k_p.
    static QString kpRefusal(const core::KpFitOutcome& outcome);
    /// A verification load.
    static QString kpCheck(const core::KpCheck& check);
};

}  // namespace tt::ui
