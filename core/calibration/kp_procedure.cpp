#include "core/calibration/kp_procedure.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tt::core {

namespace {

/// An event of `kind` about point `point` (from 1) with its value.
KpEvent event(KpEvent::Kind kind, int point = 0, const KpLoadPoint& value = {}) {
    KpEvent e;
    e.kind = kind;
    e.point = point;
    e.value = value;
    return e;
}

}  // namespace

KpCalibrationProcedure::KpCalibrationProcedure(std::unique_ptr<CurrentDifferenceMeter> meter,
                                               const KpProcedureConfig& config)
    : m_meter(std::move(meter)), m_config(config), m_average(config.settleS, config.pairsPerLoad, config.windowS) {
    if (!m_meter) throw std::invalid_argument("the k_p procedure needs a current-difference meter");
    if (config.minPairs < 1 || config.minPairs > config.pairsPerLoad)
        throw std::invalid_argument("the fewest stroke pairs must be within 1 .. the pairs per load");
    if (!(config.noSampleTimeoutS > 0.0) || config.noSampleTimeoutS > 600.0)
        throw std::invalid_argument("the sample timeout must be within 0 .. 600 s");
}

void KpCalibrationProcedure::requireStep(Step step, const char* action) const {
    if (m_step != step) throw std::logic_error(std::string(action) + " is not possible at this step");
}

void KpCalibrationProcedure::start(double loadN, std::optional<int> repeat, bool check) {
    if (measuring()) throw std::logic_error("a measurement is already running");
    if (!std::isfinite(loadN) || std::abs(loadN) > 1.0e6)
        throw std::invalid_argument("the known load must be a number within ±1 000 000 N");
    m_loadN = loadN;
    m_repeat = repeat;
    m_checking = check;
    m_quietS = 0.0;
    m_lastProblem = StrokeProblem::WaitingForStrokes;
    m_meter->reset();  // strokes under the previous load say nothing about this one
    m_live.reset();
    m_average.start();
}

void KpCalibrationProcedure::measure(double loadN) {
    requireStep(Step::Capture, "measuring a load");
    start(loadN, std::nullopt, false);
}

void KpCalibrationProcedure::repeatPoint(int index) {
    requireStep(Step::Capture, "repeating a load");
    if (index < 0 || index >= static_cast<int>(m_points.size()))
        throw std::out_of_range("there is no point " + std::to_string(index + 1));
    start(m_points[static_cast<std::size_t>(index)].loadN, index, false);
}

void KpCalibrationProcedure::typePoint(double loadN, double currentDifferenceA) {
    requireStep(Step::Capture, "typing a load");
    if (!std::isfinite(loadN) || !std::isfinite(currentDifferenceA))
        throw std::invalid_argument("a typed load needs a number for the load and the current difference");
    m_points.push_back({loadN, currentDifferenceA, 0});
    report(event(KpEvent::Kind::LoadTyped, static_cast<int>(m_points.size()), m_points.back()));
}

void KpCalibrationProcedure::removePoint(int index) {
    requireStep(Step::Capture, "removing a load");
    if (measuring()) throw std::logic_error("removing a load is not possible while one is measured");
    if (index < 0 || index >= static_cast<int>(m_points.size()))
        throw std::out_of_range("there is no point " + std::to_string(index + 1));
    KpEvent e = event(KpEvent::Kind::LoadRemoved, index + 1, m_points[static_cast<std::size_t>(index)]);
    m_points.erase(m_points.begin() + index);
    report(std::move(e));
}

void KpCalibrationProcedure::abort() {
    if (measuring()) finish(KpMeasureProblem::Aborted);
}

bool KpCalibrationProcedure::canFit() const {
    return m_step == Step::Capture && !measuring() && static_cast<int>(m_points.size()) >= kMinKpLoads;
}

bool KpCalibrationProcedure::next() {
    if (!canFit()) return false;
    m_step = Step::Fit;
    refit();
    return true;
}

void KpCalibrationProcedure::back() {
    if (m_step == Step::Accepted) {
        m_step = Step::Fit;
    } else if (m_step == Step::Fit) {
        abort();
        m_step = Step::Capture;
    }
}

void KpCalibrationProcedure::refit() {
    m_checks.clear();
    m_fit = {};
    std::vector<KpPoint> points;
    for (const KpLoadPoint& p : m_points)
        points.push_back({p.loadN, p.currentDifferenceA});
    try {
        m_fit.fit = fitKp(points);
    } catch (const KpFitRefused& e) {
        m_fit.refusal = e.problem();
        m_fit.count = e.count();
        m_fit.slopeNPerA = e.slopeNPerA();
    }
    report(event(m_fit.fit ? KpEvent::Kind::Fitted : KpEvent::Kind::FitRefused));
}

void KpCalibrationProcedure::check(double loadN) {
    requireStep(Step::Fit, "a verification load");
    if (!m_fit.fit) throw std::logic_error("a verification load needs a fitted k_p");
    start(loadN, std::nullopt, true);
}

bool KpCalibrationProcedure::accept() {
    if (m_step == Step::Accepted) return true;
    const bool failed = std::any_of(m_checks.begin(), m_checks.end(), [](const KpCheck& c) { return !c.passed; });
    if (m_step != Step::Fit || !m_fit.fit || measuring() || failed) {
        report(event(KpEvent::Kind::AcceptRefused));
        return false;
    }
    m_step = Step::Accepted;
    report(event(KpEvent::Kind::Accepted));
    return true;
}

void KpCalibrationProcedure::withdrawAcceptance() {
    if (m_step == Step::Accepted) m_step = Step::Fit;
}

void KpCalibrationProcedure::pump(DriveCurrentReadout& readout, double elapsedS) {
    const DeviceHealth health = readout.health();
    if (!health.ready()) {
        m_live.reset();
        if (measuring()) finish(KpMeasureProblem::NotReady, health.message);
        return;
    }
    bool any = false;
    while (const std::optional<DriveSample> s = readout.takeSample()) {
        any = true;
        const StrokePairReading r = m_meter->update(*s);
        if (r.newPair) m_live = r.currentDifferenceA;
        if (!measuring()) continue;
        if (r.problem != StrokeProblem::None) m_lastProblem = r.problem;
        if (r.newPair)
            m_average.add(s->timeS, r.currentDifferenceA);  // pairs within the settling are not used
        else
            m_average.observe(s->timeS);
        if (m_average.phase() == SettledAverage::Phase::Done) {
            finish(m_average.count() >= m_config.minPairs ? KpMeasureProblem::None : KpMeasureProblem::TooFewPairs);
            return;
        }
    }
    if (!measuring()) return;
    m_quietS = any ? 0.0 : m_quietS + (std::isfinite(elapsedS) ? std::max(0.0, elapsedS) : 0.0);
    if (m_quietS >= m_config.noSampleTimeoutS) finish(KpMeasureProblem::NoSamples);
}

void KpCalibrationProcedure::finish(KpMeasureProblem problem, std::string deviceMessage) {
    const KpLoadPoint point{m_loadN, m_average.mean(), m_average.count()};
    const std::optional<int> repeat = m_repeat;
    const bool check = m_checking;
    m_average.stop();
    m_repeat.reset();
    m_checking = false;
    if (problem != KpMeasureProblem::None) {
        KpEvent e = event(KpEvent::Kind::MeasureFailed, repeat ? *repeat + 1 : 0, point);
        e.problem = problem;
        e.strokeProblem = problem == KpMeasureProblem::TooFewPairs ? m_lastProblem : StrokeProblem::None;
        e.deviceMessage = std::move(deviceMessage);
        report(std::move(e));
        return;
    }
    if (check) {
        finishCheck(point);
    } else if (repeat && *repeat < static_cast<int>(m_points.size())) {
        m_points[static_cast<std::size_t>(*repeat)] = point;
        report(event(KpEvent::Kind::LoadRepeated, *repeat + 1, point));
    } else {
        m_points.push_back(point);
        report(event(KpEvent::Kind::LoadMeasured, static_cast<int>(m_points.size()), point));
    }
}

void KpCalibrationProcedure::finishCheck(const KpLoadPoint& point) {
    if (!m_fit.fit) return;
    const KpFit& f = *m_fit.fit;
    double lo = point.loadN, hi = point.loadN;
    for (const KpLoadPoint& p : m_points) {
        lo = std::min(lo, p.loadN);
        hi = std::max(hi, p.loadN);
    }
    KpCheck c;
    c.point = point;
    c.forceN = f.kpNPerA * point.currentDifferenceA + f.offsetN;
    c.deviationN = c.forceN - point.loadN;
    // The fit scatters by its residual (3σ); with few loads that can be small by chance, so at
    // least 2 % of the load range is allowed.
    c.toleranceN = std::max(3.0 * f.rmsResidualN, 0.02 * (hi - lo));
    c.passed = std::abs(c.deviationN) <= c.toleranceN;
    m_checks.push_back(c);
    KpEvent e = event(KpEvent::Kind::CheckDone, static_cast<int>(m_checks.size()), point);
    e.check = c;
    report(std::move(e));
}

std::vector<KpEvent> KpCalibrationProcedure::takeEvents() {
    std::vector<KpEvent> out;
    out.swap(m_events);
    return out;
}

}  // namespace tt::core
