#include "core/loop/adaptive_loop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/common/text_format.h"

namespace tt::core {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// After a design failed its margins the next attempt waits this many retry periods (more data, a tighter gain);
/// a refused identification is tried again after at most kMaxRetryPeriods.
constexpr int kRetriesAfterRefusedDesign = 4;
constexpr int kMaxRetryPeriods = 4;

/// SplitMix64 (Steele, Lea & Flood 2014): a fixed pseudo-random bit per part and point, so a resumed run
/// continues the same dither.
bool ditherBit(std::int64_t part, std::size_t point) {
    std::uint64_t x = static_cast<std::uint64_t>(part) * 0x9E3779B97F4A7C15ull + point * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    x ^= x >> 31;
    return (x & 1u) != 0;
}

Eigen::VectorXd toVector(const std::vector<double>& v) {
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

Eigen::VectorXd nanVector(std::size_t m) {
    return Eigen::VectorXd::Constant(static_cast<Eigen::Index>(m), kNaN);
}

std::string weightText(double weight) {
    return "ewma " + formatFixed(weight, 2);
}

}  // namespace

AdaptiveLoop::AdaptiveLoop(RunToRunSetup setup, AdaptationConfig config, MismatchAction action, int loopDelay,
                           std::vector<ToleranceZone> tolerances)
    : m_runSetup(std::move(setup)),
      m_setup(m_runSetup),
      m_config(config),
      m_action(action),
      m_loopDelay(loopDelay),
      m_tolerances(std::move(tolerances)) {
    m_config.validate();
    if (loopDelay < 1 || loopDelay > kMaxDelay)
        throw std::invalid_argument("the adaptive loop needs a delay of 1 .. " + std::to_string(kMaxDelay) + " parts");
    (void)designPlantSpec(m_setup);  // refuses a model that does not fit the plant
}

void AdaptiveLoop::reset() {
    m_setup = m_runSetup;
    m_phase = Phase::Model;
    m_fallback.reset();
    m_proposal.reset();
    m_last.reset();
    m_adaptedAt = 0;
    m_nextAttempt = 0;
    m_modelShare = 0.0;
    m_nextRefinement = 0;
    m_refinements = 0;
    m_recent.clear();
}

void AdaptiveLoop::scheduleRefinement(std::int64_t part, double worstShare) {
    m_modelShare = worstShare;
    m_refinements = 0;
    m_nextRefinement =
        m_action == MismatchAction::Adapt && m_config.refineBelow > 0.0 && worstShare > m_config.refineBelow
            ? part + m_config.refineParts
            : 0;
}

AdaptiveLoop::RecentPart* AdaptiveLoop::find(std::int64_t part) {
    if (m_recent.empty() || part < m_recent.front().part || part > m_recent.back().part) return nullptr;
    RecentPart& r = m_recent[static_cast<std::size_t>(part - m_recent.front().part)];
    return r.part == part ? &r : nullptr;
}

const AdaptiveLoop::RecentPart* AdaptiveLoop::find(std::int64_t part) const {
    return const_cast<AdaptiveLoop*>(this)->find(part);
}

void AdaptiveLoop::partStarted(std::int64_t part, const std::vector<double>& appliedMm) {
    if (!m_recent.empty() && part != m_recent.back().part + 1) m_recent.clear();  // a gap: start the record again
    RecentPart r;
    r.part = part;
    r.appliedMm = toVector(appliedMm);
    r.offeredMm = nanVector(appliedMm.size());
    r.usedMm = r.offeredMm;
    m_recent.push_back(std::move(r));
    const auto keep = static_cast<std::size_t>(std::max(m_config.windowParts, kPrimeParts) + 2 * kMaxDelay + 2);
    while (m_recent.size() > keep)
        m_recent.pop_front();
}

void AdaptiveLoop::partMeasured(std::int64_t part, const Eigen::VectorXd& offeredMm, const std::vector<bool>& used) {
    RecentPart* r = find(part);
    if (!r || offeredMm.size() != r->appliedMm.size()) return;
    r->offeredMm = offeredMm;
    r->usedMm = nanVector(static_cast<std::size_t>(offeredMm.size()));
    for (Eigen::Index i = 0; i < offeredMm.size(); ++i)
        if (static_cast<std::size_t>(i) < used.size() && used[static_cast<std::size_t>(i)]) r->usedMm(i) = offeredMm(i);
    r->measured = true;
}

void AdaptiveLoop::controllerReplaced(std::optional<RunToRunSetup> tuning, std::int64_t part) {
    if (tuning) m_setup = std::move(*tuning);
    m_phase = Phase::Model;
    m_fallback.reset();
    m_proposal.reset();
    m_adaptedAt = part;
}

void AdaptiveLoop::prime(RunToRunController& controller, std::int64_t nextPart) const {
    const std::int64_t from = m_recent.empty() ? nextPart : std::max(m_recent.front().part, nextPart - kPrimeParts);
    auto offer = [&](std::int64_t part) {
        const RecentPart* r = find(part);
        if (r && r->measured && part >= from) controller.addMeasurement({part, r->offeredMm});
    };
    for (std::int64_t p = from; p < nextPart; ++p) {
        const RecentPart* r = find(p);
        if (!r) continue;
        offer(p - m_loopDelay);
        (void)controller.nextCorrection(p);
        controller.correctionApplied(p, r->appliedMm);
    }
    offer(nextPart - m_loopDelay);
}

Eigen::VectorXd AdaptiveLoop::dither(std::int64_t part) const {
    const std::size_t m = m_setup.plant.points.size();
    Eigen::VectorXd d = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m));
    if (m_phase != Phase::Fallback || m_config.ditherShare <= 0.0 || m_tolerances.size() != m) return d;
    const RunToRunPlantSpec spec = designPlantSpec(m_setup);
    for (std::size_t i = 0; i < m; ++i) {
        const double width = m_tolerances[i].upperDeviationMm - m_tolerances[i].lowerDeviationMm;
        const double radial = m_config.ditherShare * width / spec.points[i].gain;
        d(static_cast<Eigen::Index>(i)) = ditherBit(part, i) ? radial : -radial;
    }
    return d;
}

AdaptationRecord AdaptiveLoop::record(const char* kind, std::int64_t part, double timeS) const {
    AdaptationRecord r;
    r.kind = kind;
    r.partNumber = part;
    r.timeS = timeS;
    r.modelBefore = modelRecord(m_setup);
    if (m_fallback) {
        r.fallback = weightText(m_fallback->weight);
        r.fallbackWeight = m_fallback->weight;
    }
    return r;
}

AdaptationStep AdaptiveLoop::onMismatch(const Notice& mismatch, std::int64_t nextPart, double timeS) {
    AdaptationStep step;
    if (m_phase != Phase::Model) return step;
    m_fallback = designFallback(designPlantSpec(m_setup).delay);
    step.controller = makeFallbackController(m_setup, *m_fallback);
    m_phase = Phase::Fallback;
    m_nextAttempt = nextPart;
    AdaptationRecord r = record(adaptation_kind::kFallback, nextPart, timeS);
    r.reason = describe(mismatch);
    r.margins = marginsRecord(m_fallback->margins);
    r.applied = true;
    r.notice = Notice(NoticeKind::FallbackEngaged, nextPart, mismatch.part);
    r.notice.value = m_fallback->weight;
    r.notice.point = mismatch.point;
    step.notice = r.notice;
    step.record = r;
    m_last = r;
    return step;
}

AdaptationStep AdaptiveLoop::beforePart(std::int64_t part, double timeS) {
    if (m_phase == Phase::Model && m_nextRefinement > 0 && part >= m_nextRefinement) return refine(part, timeS);
    if (m_phase != Phase::Fallback || part < m_nextAttempt) return {};
    return identifyAndDesign(part, timeS);
}

AdaptationStep AdaptiveLoop::refine(std::int64_t part, double timeS) {
    const LoopHistory history = window();
    const std::string source = "parts " + std::to_string(history.firstPart) + " .. " +
                               std::to_string(history.firstPart + static_cast<std::int64_t>(history.size()) - 1) +
                               " of the run";
    // Each refinement that does not help waits twice as long for the next (the data tell more slowly than 1 / n).
    ++m_refinements;
    m_nextRefinement = m_refinements < kMaxRefinements
                           ? part + (static_cast<std::int64_t>(m_config.refineParts) << std::min(m_refinements, 10))
                           : 0;
    PlantIdentification id;
    try {
        id = identifyPlant(history, m_config.identification(m_loopDelay, designPlantSpec(m_setup)));
    } catch (const std::invalid_argument&) {
        return {};  // the data do not tell more yet: the model in use stays, quietly
    }
    // Only data that tell the gain better on their own (the joint standard error, not the one given a kept
    // disturbance: under a controller that is nearly right, closed-loop data hardly tell a gain from a disturbance
    // change, and a gain re-estimated given the old disturbance would just wander).
    const PlantModelRecord model = modelRecord(id, source);
    const double share = worstGainShare(model, true);
    if (!(share < kRefineImprovement * m_modelShare)) return {};
    // The plant has not changed (the monitor would say so): new gains far from the ones in use, beyond both standard
    // errors, are a wandering estimate, not more knowledge.
    if (m_setup.model && m_modelRecord.points.size() == model.points.size())
        for (std::size_t i = 0; i < model.points.size(); ++i) {
            const PointModelRecord& now = m_modelRecord.points[i];
            const PointModelRecord& next = model.points[i];
            const double spread = std::hypot(now.gainStdErrJoint, next.gainStdErrJoint);
            if (std::isfinite(spread) && std::abs(next.gain - now.gain) > kRefineConsistency * spread) return {};
        }
    const AdaptedDesign design = designAdapted(m_setup, id, source, m_config.minGainMargin);
    if (!design.passes) return {};
    AdaptationRecord r = record(adaptation_kind::kRefined, part, timeS);
    r.modelAfter = model;
    r.margins = design.worst;
    r.reason = "refined from " + source + ": the largest gain standard error (the disturbance free) fell from " +
               formatFixed(100.0 * m_modelShare, 1) + " % to " + formatFixed(100.0 * share, 1) + " %";
    r.applied = true;
    r.notice = Notice(NoticeKind::ControllerAdapted, part);
    r.notice.value = id.delayParts();
    r.notice.reference = design.worst.gain;
    r.notice.cause = source;
    AdaptationStep step;
    step.controller = makeAdaptedController(design.setup);
    m_setup = design.setup;
    m_modelRecord = model;
    m_adaptedAt = part;
    const int refinements = m_refinements;
    scheduleRefinement(part, share);
    m_refinements = refinements;
    if (m_nextRefinement > 0 && m_refinements >= kMaxRefinements) m_nextRefinement = 0;
    step.notice = r.notice;
    step.record = r;
    m_last = r;
    return step;
}

LoopHistory AdaptiveLoop::window() const {
    LoopHistory h;
    auto last = m_recent.rbegin();
    while (last != m_recent.rend() && !last->measured)
        ++last;
    if (last == m_recent.rend()) return h;
    const std::int64_t lastPart = last->part;
    const std::int64_t firstPart = std::max(m_recent.front().part, lastPart - m_config.windowParts + 1);
    h.firstPart = firstPart;
    for (std::int64_t p = firstPart; p <= lastPart; ++p) {
        const RecentPart* r = find(p);
        h.appliedMm.push_back(r->appliedMm);
        h.deviationMm.push_back(r->usedMm);
    }
    return h;
}

AdaptationStep AdaptiveLoop::refusal(std::int64_t part, const std::string& why, std::int64_t partsNeeded) {
    AdaptationStep step;
    // The parts needed are an estimate (a standard error falls as 1 / sqrt(n) only on average): try again after them
    // (and the z parts still to be measured), but at least every kMaxRetryPeriods retry periods.
    const std::int64_t wait =
        partsNeeded > 0 ? std::clamp<std::int64_t>(partsNeeded + m_loopDelay, m_config.retryParts,
                                                   static_cast<std::int64_t>(kMaxRetryPeriods) * m_config.retryParts)
                        : static_cast<std::int64_t>(kMaxRetryPeriods) * m_config.retryParts;
    m_nextAttempt = part + wait;
    step.notice = Notice(NoticeKind::IdentificationWaiting, part);
    step.notice.value = partsNeeded > 0 ? static_cast<double>(partsNeeded) : kNaN;
    step.notice.cause = why;
    return step;
}

AdaptationStep AdaptiveLoop::identifyAndDesign(std::int64_t part, double timeS) {
    const LoopHistory history = window();
    PlantIdentification id;
    try {
        id = identifyPlant(history, m_config.identification(m_loopDelay, designPlantSpec(m_setup)));
    } catch (const IdentificationRefused& refused) {
        return refusal(part, refused.what(), refused.partsNeeded);
    } catch (const std::invalid_argument& e) {
        return refusal(part, e.what(), 0);
    }
    const std::string source = "parts " + std::to_string(history.firstPart) + " .. " +
                               std::to_string(history.firstPart + static_cast<std::int64_t>(history.size()) - 1) +
                               " of the run";
    const AdaptedDesign design = designAdapted(m_setup, id, source, m_config.minGainMargin);
    const bool propose = m_action == MismatchAction::Propose;
    AdaptationRecord r = record(!design.passes ? adaptation_kind::kRefused
                                : propose      ? adaptation_kind::kProposed
                                               : adaptation_kind::kAdapted,
                                part, timeS);
    r.modelAfter = modelRecord(id, source);
    r.margins = design.worst;
    AdaptationStep step;
    if (!design.passes) {
        m_nextAttempt = part + kRetriesAfterRefusedDesign * m_config.retryParts;
        r.reason = design.why;
        r.notice = Notice(NoticeKind::AdaptationRefused, part);
        r.notice.cause = design.why;
    } else {
        r.reason =
            "identified from " + source + " by the " +
            std::string(id.criterion == InformationCriterion::Aic ? "AIC" : "BIC") +
            (design.r2Factor > 1.0 ? "; R2 raised " + formatSignificant(design.r2Factor, 3) + " times for the margins"
                                   : std::string());
        r.notice = Notice(propose ? NoticeKind::AdaptationProposed : NoticeKind::ControllerAdapted, part);
        r.notice.value = id.delayParts();
        r.notice.reference = design.worst.gain;
        r.notice.cause = source;
        if (propose) {
            m_proposal = design.setup;
            m_proposalModel = *r.modelAfter;
            m_phase = Phase::Proposed;
        } else {
            step.controller = makeAdaptedController(design.setup);
            m_setup = design.setup;
            m_modelRecord = *r.modelAfter;
            m_phase = Phase::Model;
            m_fallback.reset();
            m_adaptedAt = part;
            scheduleRefinement(part, worstGainShare(*r.modelAfter, true));
            r.applied = true;
        }
    }
    step.notice = r.notice;
    step.record = r;
    m_last = r;
    return step;
}

AdaptationStep AdaptiveLoop::acceptProposal(std::int64_t part, double timeS) {
    AdaptationStep step;
    if (!m_proposal) return step;
    AdaptationRecord r = record(adaptation_kind::kAccepted, part, timeS);
    r.modelAfter = m_proposalModel;
    r.reason = "the proposed design was applied by an engineer";
    m_setup = *m_proposal;
    m_modelRecord = m_proposalModel;
    m_proposal.reset();
    step.controller = makeAdaptedController(m_setup);
    const RunToRunPlantSpec spec = designPlantSpec(m_setup);
    const RunToRunPlant plant =
        buildRunToRunPlant(m_setup.integral.enabled ? withIntegralAction(spec, m_setup.integral) : spec);
    r.margins = worstMargins(lqgMargins(plant, designLqg(plant, m_setup.weights)));
    r.applied = true;
    r.notice = Notice(NoticeKind::ProposalAccepted, part);
    m_phase = Phase::Model;
    m_fallback.reset();
    m_adaptedAt = part;
    scheduleRefinement(part, 0.0);
    step.notice = r.notice;
    step.record = r;
    m_last = r;
    return step;
}

std::unique_ptr<RunToRunController> AdaptiveLoop::restore(const std::vector<AdaptationRecord>& records,
                                                          const std::vector<StoredPart>& parts) {
    reset();
    for (const StoredPart& part : parts) {
        std::vector<double> applied;
        for (const PointCorrectionRecord& c : part.corrections)
            applied.push_back(c.appliedMm);
        partStarted(part.partNumber, applied);
        if (!part.measurement) continue;
        Eigen::VectorXd offered = nanVector(applied.size());
        std::vector<bool> used(applied.size(), false);
        for (const PointMeasurementRecord& p : part.measurement->points) {
            const auto i = static_cast<std::size_t>(p.pointIndex);
            if (i >= applied.size() || !p.measuredMm) continue;
            offered(static_cast<Eigen::Index>(i)) = *p.measuredMm - p.nominalMm;
            used[i] = p.accepted;
        }
        partMeasured(part.partNumber, offered, used);
    }
    std::unique_ptr<RunToRunController> controller;
    for (const AdaptationRecord& r : records) {
        m_last = r;
        if (r.kind == adaptation_kind::kFallback) {
            m_fallback = designFallback(designPlantSpec(m_setup).delay);
            controller = makeFallbackController(m_setup, *m_fallback);
            m_phase = Phase::Fallback;
            m_nextAttempt = r.partNumber;
        } else if (r.applied && r.modelAfter) {
            // The design again as it was applied (the margins may have raised R2).
            RunToRunSetup next = m_runSetup;
            next.model = controllerModelFrom(*r.modelAfter, m_runSetup);
            std::vector<double> gain, stdErr;
            for (const PointModelRecord& p : r.modelAfter->points) {
                gain.push_back(p.gain);
                stdErr.push_back(p.gainStdErr);
            }
            m_setup = designForModel(next, requiredGainFactor(gain, stdErr, m_config.minGainMargin)).setup;
            m_modelRecord = *r.modelAfter;
            controller = makeAdaptedController(m_setup);
            m_phase = Phase::Model;
            m_fallback.reset();
            m_adaptedAt = r.partNumber;
            if (r.kind != adaptation_kind::kAccepted)
                scheduleRefinement(r.partNumber, worstGainShare(*r.modelAfter, true));
        }
    }
    return controller;
}

std::string AdaptiveLoop::controllerDescription() const {
    switch (m_phase) {
        case Phase::Fallback:
            return "fallback EWMA " + formatFixed(m_fallback ? m_fallback->weight : kNaN, 2) +
                   ", identifying the plant";
        case Phase::Proposed:
            return "fallback EWMA " + formatFixed(m_fallback ? m_fallback->weight : kNaN, 2) + ", a design is proposed";
        case Phase::Model:
            break;
    }
    return m_adaptedAt > 0 ? "LQG adapted at part " + std::to_string(m_adaptedAt) : "LQG on the run's model";
}

}  // namespace tt::core
