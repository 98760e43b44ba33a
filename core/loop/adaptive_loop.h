#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/common/tolerance.h"
#include "core/control/adaptive_design.h"
#include "core/control/run_to_run_setup.h"
#include "core/loop/adaptation_config.h"
#include "core/loop/mismatch_monitor.h"
#include "core/ports/adaptation_record.h"
#include "core/ports/history_store.h"

namespace tt::core {

/// What one step of the adaptation hands the loop engine.
struct AdaptationStep {
    std::unique_ptr<RunToRunController> controller;  ///< takes over at the part (null: no switch)
    std::optional<AdaptationRecord> record;          ///< stored with the run
    Notice notice;                                   ///< told to the operator (kind None: nothing to tell)
};

/// The self-tuning part of the loop (paper 000's LQG made adaptive): on a model mismatch it hands the engine a
/// robust fallback (designFallback), keeps the run's recent record, identifies the plant from it (identifyPlant)
/// every retryParts parts until the data tell, re-synthesises the LQG with its margins checked (designAdapted) and
/// hands over the new controller (adapt) or keeps it as a proposal for an engineer (propose). Every controller it
/// hands over is primed with the recent record (prime), so its estimate starts consistent with what the parts
/// really received. Single-threaded: the engine's thread.
class AdaptiveLoop {
public:
    /// Where the loop is: on the model's controller, on the fallback while identifying, or on the fallback with
    /// a design proposed.
    enum class Phase { Model, Fallback, Proposed };

    /// `setup`: the controllers' setup the run started from; `tolerances`: per point (for the dither; may be
    /// empty without a dither). Throws std::invalid_argument for a bad config or delay.
    AdaptiveLoop(RunToRunSetup setup, AdaptationConfig config, MismatchAction action, int loopDelay,
                 std::vector<ToleranceZone> tolerances);

    /// A new run: the model is the run's own again, the record is empty.
    void reset();
    /// Part `part` was started with these corrections (after every limit).
    void partStarted(std::int64_t part, const std::vector<double>& appliedMm);
    /// The deviations of part `part` offered to the controller (NaN: not plausible or not measured) and which
    /// of them it used.
    void partMeasured(std::int64_t part, const Eigen::VectorXd& offeredMm, const std::vector<bool>& used);

    /// The monitor found a mismatch (`mismatch`, the alarm's notice): the fallback for the model in use, taking
    /// over at `nextPart`. Nothing when the loop is already on the fallback.
    AdaptationStep onMismatch(const Notice& mismatch, std::int64_t nextPart, double timeS);
    /// Before part `part` is started: on the fallback, an identification attempt when one is due; on an adapted
    /// model less certain than config().refineBelow, a refinement when one is due (a design whose gains are clearly
    /// more certain takes over).
    AdaptationStep beforePart(std::int64_t part, double timeS);
    /// The engineer applies the proposed design (Phase::Proposed) from part `part`; nothing without a proposal.
    AdaptationStep acceptProposal(std::int64_t part, double timeS);

    /// A controller was applied from outside (an engineer's tuning) at part `part`: an adaptation in progress
    /// ends, a proposal is dropped; `tuning`, when given, is the model the loop adapts from next.
    void controllerReplaced(std::optional<RunToRunSetup> tuning, std::int64_t part);

    /// Replays the recent record into a fresh `controller` that takes over at `nextPart`: for each part before it,
    /// the measurement due, its correction and the correction really applied; then the measurement of
    /// nextPart - z when it has been offered.
    void prime(RunToRunController& controller, std::int64_t nextPart) const;
    /// The dither added to part `part`'s corrections, radial mm (zeros unless identifying with a dither).
    Eigen::VectorXd dither(std::int64_t part) const;

    /// Continues a stored run: the model and controller the recorded adaptations left in place at `lastPart` and
    /// the recent record from the stored parts. Returns that controller (null: the run's own, nothing adapted).
    std::unique_ptr<RunToRunController> restore(const std::vector<AdaptationRecord>& records,
                                                const std::vector<StoredPart>& parts);

    Phase phase() const { return m_phase; }
    /// The controller's setup now in use (its model: the preset's or the identified one).
    const RunToRunSetup& setup() const { return m_setup; }
    /// The last adaptation record (none before the first).
    const std::optional<AdaptationRecord>& last() const { return m_last; }
    /// A design waits for the engineer's Apply.
    bool hasProposal() const { return m_proposal.has_value(); }
    /// The loop's controller now, in stable English ("LQG on the preset's model", "fallback EWMA 0.23",
    /// "LQG adapted at part 512").
    std::string controllerDescription() const;
    const AdaptationConfig& config() const { return m_config; }

private:
    struct RecentPart {
        std::int64_t part = 0;
        Eigen::VectorXd appliedMm;
        Eigen::VectorXd offeredMm;
        Eigen::VectorXd usedMm;
        bool measured = false;
    };
    RecentPart* find(std::int64_t part);
    const RecentPart* find(std::int64_t part) const;
    LoopHistory window() const;
    AdaptationStep identifyAndDesign(std::int64_t part, double timeS);
    AdaptationStep refine(std::int64_t part, double timeS);
    /// After a model took over at `part` with gains this uncertain (largest relative standard error): refine later?
    void scheduleRefinement(std::int64_t part, double worstShare);
    AdaptationStep refusal(std::int64_t part, const std::string& why, std::int64_t partsNeeded);
    AdaptationRecord record(const char* kind, std::int64_t part, double timeS) const;

    RunToRunSetup m_runSetup;  ///< the run's own (restored by reset)
    RunToRunSetup m_setup;     ///< the model in use
    AdaptationConfig m_config;
    MismatchAction m_action;
    int m_loopDelay = 1;
    std::vector<ToleranceZone> m_tolerances;
    Phase m_phase = Phase::Model;
    std::optional<FallbackDesign> m_fallback;
    std::int64_t m_nextAttempt = 0;
    std::optional<RunToRunSetup> m_proposal;
    PlantModelRecord m_proposalModel;  ///< the proposal's identified model as recorded
    std::optional<AdaptationRecord> m_last;
    std::int64_t m_adaptedAt = 0;       ///< part the model in use took over at (0: the run's own)
    double m_modelShare = 0.0;          ///< the largest relative standard error of the model's gains in use
    PlantModelRecord m_modelRecord;     ///< the identified model in use, as recorded
    std::int64_t m_nextRefinement = 0;  ///< 0: no refinement due
    int m_refinements = 0;
    std::deque<RecentPart> m_recent;
};

/// Parts replayed into a controller that takes over (its estimate forgets a start 0.95^500 away).
inline constexpr int kPrimeParts = 500;
/// A refinement takes a new design only when its largest gain standard error is below this share of the model's;
/// at most this many refinement attempts follow one adaptation (each unsuccessful one waits twice as long).
inline constexpr double kRefineImprovement = 0.8;
/// ... and only when every new gain lies within this many combined standard errors of the gain in use.
inline constexpr double kRefineConsistency = 2.0;
inline constexpr int kMaxRefinements = 8;

}  // namespace tt::core
