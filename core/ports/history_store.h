#pragma once

#include "core/common/notice.h"
#include "core/common/tolerance.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/ports/adaptation_record.h"
#include "core/ports/controller_state.h"

namespace tt::core {

/// What a run is: recorded once when it starts.
struct RunDescription {
    std::string preset;      ///< preset name or file the run was set up from
    std::string controller;  ///< "lqg", "ewma", "open"
    int delayParts = 1;      ///< transport delay z
    double nominalDiameterMm = 0.0;
    double partLengthMm = 0.0;
    std::vector<double> pointZMm;  ///< control points, mm
    std::string settingsJson;      ///< everything needed to set the run up again (for resume), JSON text
    std::string machine = {};      ///< which lathe ran it (a plant-wide history holds several); may be empty
};

/// The gauged diameter of one part at one control point, with the verdict.
struct PointMeasurementRecord {
    int pointIndex = 0;
    double zMm = 0.0;
    std::optional<double> measuredMm;  ///< none: the point was not measured
    double nominalMm = 0.0;
    bool accepted = false;  ///< used by the controller
    std::string reason;     ///< why not, in stable English (stored); empty when accepted
    Notice rejection = {};  ///< why not, as a kind with data (kind None when accepted)
    /// The tolerance zone of the point and the verdict on the reading (good / rework / scrap), for every
    /// plausible reading of a job with tolerances; independent of `accepted` (a part can be scrap and its
    /// reading still used by the controller). None: no tolerance, or no plausible reading.
    std::optional<ToleranceZone> tolerance = std::nullopt;
    std::optional<ToleranceVerdict> verdict = std::nullopt;
};

/// All control points of one measured part.
struct PartMeasurementRecord {
    std::int64_t partNumber = 0;
    double timeS = 0.0;  ///< when the last reading arrived (Clock), s
    std::vector<PointMeasurementRecord> points;

    /// The part's verdict: the worst verdict of its points; none when no point has one.
    std::optional<ToleranceVerdict> verdict() const {
        std::optional<ToleranceVerdict> worst;
        for (const PointMeasurementRecord& p : points)
            if (p.verdict) worst = worst ? worseVerdict(*worst, *p.verdict) : *p.verdict;
        return worst;
    }
};

/// The correction at one control point for one part.
struct PointCorrectionRecord {
    int pointIndex = 0;
    double zMm = 0.0;
    double computedMm = 0.0;  ///< what the controller asked for, radial mm
    double appliedMm = 0.0;   ///< what was sent to the CNC after the loop's limits, radial mm
};

/// One finished part: stored in ONE transaction together with the verdicts on the measurement the
/// controller used for it and the controller's state after computing its correction, so a run killed
/// at any moment loses at most the part in progress.
struct PartCompletionRecord {
    std::int64_t partNumber = 0;
    double startedS = 0.0;
    double finishedS = 0.0;
    std::vector<PointCorrectionRecord> corrections;
    /// The measured part whose diameters the controller received before this part (part - z), with
    /// the controller's verdicts (they replace the stored ones); none when no measurement was due.
    std::optional<PartMeasurementRecord> usedMeasurement;
    ControllerState controllerState;  ///< after this part's correction was computed
};

/// A stored run, as listed.
struct RunSummary {
    std::int64_t runId = 0;
    RunDescription description;
    std::string status;      ///< "running", "complete", "stopped", "fault"
    std::string startedAt;   ///< ISO 8601 UTC
    std::string finishedAt;  ///< empty while running
    std::int64_t partCount = 0;
    std::optional<std::int64_t> lastPartNumber;
};

/// A stored part with everything recorded about it.
struct StoredPart {
    std::int64_t partNumber = 0;
    double startedS = 0.0;
    double finishedS = 0.0;
    std::vector<PointCorrectionRecord> corrections;
    std::optional<PartMeasurementRecord> measurement;  ///< none while not yet measured
};

/// Where a run can be continued after an interruption.
struct ResumePoint {
    RunSummary run;
    std::int64_t lastPartNumber = 0;  ///< the next part is lastPartNumber + 1
    ControllerState controllerState;
    /// Parts after the last part whose measurement the controller used, part number ascending:
    /// those with stored measurements have them; the others wait for the gauge (they are on the rack).
    std::vector<StoredPart> pendingParts;
};

/// An alarm or notice of the loop, stored with the run.
struct AlarmRecord {
    std::optional<std::int64_t> partNumber;
    double timeS = 0.0;
    std::string kind;     ///< "gauge-silent", "measurement-rejected", "correction-limited", "fault", ...
    std::string message;  ///< in the user's terms
};

/// The run history the closed loop writes (paper 000's part-by-part records). Implemented over SQL in
/// core/storage; every method throws std::runtime_error (a StorageError) with the reason on failure,
/// and a failed write leaves what was stored before intact.
class HistoryStore {
public:
    virtual ~HistoryStore() = default;

    /// Records a new run; returns its id.
    virtual std::int64_t beginRun(const RunDescription& run) = 0;
    /// Stores one finished part (one transaction; see PartCompletionRecord).
    virtual void recordPart(std::int64_t runId, const PartCompletionRecord& part) = 0;
    /// Stores the diameters of an already recorded part as soon as they are complete (own transaction).
    virtual void recordMeasurement(std::int64_t runId, const PartMeasurementRecord& measurement) = 0;
    /// Stores an alarm.
    virtual void recordAlarm(std::int64_t runId, const AlarmRecord& alarm) = 0;
    /// Marks the run finished with `status` ("complete", "stopped", "fault").
    virtual void finishRun(std::int64_t runId, const std::string& status) = 0;
    /// Stores what the adaptive loop did (a switch to its fallback, an adaptation, a proposal, a refused design)
    /// with the models before and after and the margins; it is also read into the audit trail.
    virtual void recordAdaptation(std::int64_t runId, const AdaptationRecord& adaptation) = 0;

    /// Runs, newest first.
    virtual std::vector<RunSummary> runs() = 0;
    /// The parts of a run in part-number order.
    virtual std::vector<StoredPart> parts(std::int64_t runId) = 0;
    /// The alarms of a run in the order they were raised.
    virtual std::vector<AlarmRecord> alarms(std::int64_t runId) = 0;
    /// The adaptations of a run in the order they happened.
    virtual std::vector<AdaptationRecord> adaptations(std::int64_t runId) = 0;
    /// Where run `runId` (the newest run when none) can continue; none when there is no run or it has
    /// no part yet.
    virtual std::optional<ResumePoint> resumePoint(std::optional<std::int64_t> runId = std::nullopt) = 0;

    /// Whether the store takes another part now: a notice (kind HistoryFull, with the bytes used and the limit)
    /// when it does not, e.g. a terminal's journal at its size limit while the plant database is unreachable.
    /// The loop asks before it starts a part, pauses on a refusal (nothing is dropped) and goes on by itself
    /// once the store takes parts again. The default store always does.
    virtual Notice refusesNextPart() { return {}; }
};

}  // namespace tt::core
