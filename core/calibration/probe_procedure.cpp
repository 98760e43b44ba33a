#include "core/calibration/probe_procedure.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace tt::core {

namespace {

/// An event of `kind` about point `point` (from 1) with its value.
ProbeEvent event(ProbeEvent::Kind kind, int point = 0, const ProbePoint& value = {}) {
    ProbeEvent e;
    e.kind = kind;
    e.point = point;
    e.value = value;
    return e;
}

}  // namespace

namespace {

ProbeFitRefusal refusalOf(LinearisationProblem problem) {
    switch (problem) {
        case LinearisationProblem::TooFewPoints:
            return ProbeFitRefusal::TooFewPoints;
        case LinearisationProblem::NonMonotonic:
            return ProbeFitRefusal::NonMonotonic;
        case LinearisationProblem::OutOfRange:
            return ProbeFitRefusal::OutOfRange;
        case LinearisationProblem::BadInput:
            break;
    }
    return ProbeFitRefusal::BadInput;
}

/// Checks what fitCharacteristic would refuse, keeping the counts for the words; false when refused.
bool enoughPoints(const std::vector<CalibrationPoint>& points, int degree, ProbeFitOutcome& out) {
    const int lowest = degree == kAutoDegree ? 2 : degree;
    out.got = static_cast<int>(points.size());
    out.needed = pointsNeeded(lowest);
    if (out.got < out.needed) {
        out.refusal = ProbeFitRefusal::TooFewPoints;
        return false;
    }
    std::set<double> references;
    for (const CalibrationPoint& p : points)
        references.insert(p.referenceUm);
    out.got = static_cast<int>(references.size());
    out.needed = referencesNeeded(lowest);
    if (out.got < out.needed) {
        out.refusal = ProbeFitRefusal::TooFewReferences;
        return false;
    }
    const double first = points.front().adcCode;
    if (std::all_of(points.begin(), points.end(), [first](const CalibrationPoint& p) { return p.adcCode == first; })) {
        out.refusal = ProbeFitRefusal::ConstantCode;
        out.constantCode = first;
        return false;
    }
    out.needed = out.got = 0;
    return true;
}

}  // namespace

ProbeFitOutcome fitProbePoints(const std::vector<ProbePoint>& points, int adcBits, int degree) {
    ProbeFitOutcome out;
    std::vector<CalibrationPoint> used;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (points[i].saturated)
            out.leftOut.push_back(static_cast<int>(i) + 1);
        else
            used.push_back({points[i].referenceUm, points[i].adcCode, 0});
    }
    if (!enoughPoints(used, degree, out)) return out;
    try {
        out.fit = fitCharacteristic(used, adcBits, degree);
        if (!out.fit->monotonicity.monotonic) {
            out.refusal = ProbeFitRefusal::NonMonotonic;
            return out;
        }
        out.linearisation = lineariseFit(*out.fit, used);
    } catch (const LinearisationRefused& e) {
        out.refusal = refusalOf(e.problem());
        out.linearisation.reset();
    }
    return out;
}

ProbeLinearisationProcedure::ProbeLinearisationProcedure(const ProbeProcedureConfig& config)
    : m_config(config), m_capture(config.capture, config.plane, config.adcBits), m_upload(config.readbackTimeoutS) {
    checkConfig(config);
}

void ProbeLinearisationProcedure::checkConfig(const ProbeProcedureConfig& config) {
    if (!(config.referenceDivisionUm >= 0.1 && config.referenceDivisionUm <= 10.0))
        throw std::invalid_argument("the division of the reference instrument must be within 0.1 .. 10 µm");
    if (config.minPoints < 1 || config.minPoints > 1000)
        throw std::invalid_argument("the points before a fit must be within 1 .. 1000");
}

void ProbeLinearisationProcedure::requireStep(Step step, const char* action) const {
    if (m_step != step) throw std::logic_error(std::string(action) + " is not possible at this step");
}

void ProbeLinearisationProcedure::configure(int plane, int adcBits, double referenceDivisionUm) {
    requireStep(Step::Capture, "changing the set-up");
    if (capturing()) throw std::logic_error("changing the set-up is not possible while a point is read");
    ProbeProcedureConfig c = m_config;
    c.plane = plane;
    c.adcBits = adcBits;
    c.referenceDivisionUm = referenceDivisionUm;
    checkConfig(c);
    m_capture = ProbeCapture(c.capture, plane, adcBits);  // throws for a plane or resolution out of range
    m_config = c;
}

void ProbeLinearisationProcedure::startCapture(double referenceUm, std::optional<int> repeat, bool check) {
    m_capture.start(referenceUm);  // throws while one runs
    m_repeat = repeat;
    m_checking = check;
}

void ProbeLinearisationProcedure::capture(double referenceUm) {
    requireStep(Step::Capture, "capturing a point");
    startCapture(referenceUm, std::nullopt, false);
}

void ProbeLinearisationProcedure::repeatPoint(int index, double referenceUm) {
    requireStep(Step::Capture, "repeating a point");
    if (index < 0 || index >= static_cast<int>(m_points.size()))
        throw std::out_of_range("there is no point " + std::to_string(index + 1));
    startCapture(referenceUm, index, false);
}

void ProbeLinearisationProcedure::typePoint(double referenceUm, double adcCode) {
    requireStep(Step::Capture, "typing a point");
    if (!std::isfinite(referenceUm) || !std::isfinite(adcCode))
        throw std::invalid_argument("a typed point needs a number for the reference and the code");
    const double top = std::ldexp(1.0, m_config.adcBits) - 1.0;
    if (adcCode < 0.0 || adcCode > top)
        throw std::invalid_argument("the ADC code must be within 0 .. " + std::to_string(static_cast<int>(top)));
    const auto code = static_cast<std::int32_t>(std::lround(adcCode));
    m_points.push_back({referenceUm, adcCode, 0, saturatedCode(adcCode, m_config.adcBits), code, code});
    report(event(ProbeEvent::Kind::PointTyped, static_cast<int>(m_points.size()), m_points.back()));
}

void ProbeLinearisationProcedure::removePoint(int index) {
    requireStep(Step::Capture, "removing a point");
    if (capturing()) throw std::logic_error("removing a point is not possible while a point is read");
    if (index < 0 || index >= static_cast<int>(m_points.size()))
        throw std::out_of_range("there is no point " + std::to_string(index + 1));
    ProbeEvent e = event(ProbeEvent::Kind::PointRemoved, index + 1, m_points[static_cast<std::size_t>(index)]);
    m_points.erase(m_points.begin() + index);
    report(std::move(e));
}

void ProbeLinearisationProcedure::abort() {
    if (const std::optional<ProbeCaptureResult> r = m_capture.abort()) finishCapture(*r);
    if (m_upload.running()) {
        m_upload.abort();
        reportUpload();
    }
}

void ProbeLinearisationProcedure::loadChanged() {
    if (const std::optional<ProbeCaptureResult> r = m_capture.loadChanged()) finishCapture(*r);
}

bool ProbeLinearisationProcedure::canFit() const {
    return m_step == Step::Capture && !capturing() && static_cast<int>(m_points.size()) >= m_config.minPoints;
}

bool ProbeLinearisationProcedure::next() {
    if (m_step == Step::Capture) {
        if (!canFit()) return false;
        m_step = Step::Fit;
        refit();
        return true;
    }
    if (m_step == Step::Accepted) {
        m_step = Step::Upload;
        return true;
    }
    return false;
}

void ProbeLinearisationProcedure::back() {
    switch (m_step) {
        case Step::Capture:
            return;
        case Step::Fit:
            if (const std::optional<ProbeCaptureResult> r = m_capture.abort()) finishCapture(*r);
            m_step = Step::Capture;
            return;
        case Step::Accepted:
            m_step = Step::Fit;
            return;
        case Step::Upload:
            if (m_upload.running()) return;
            m_step = Step::Accepted;
            return;
    }
}

void ProbeLinearisationProcedure::returnToCapture() {
    if (m_upload.running()) abort();
    while (m_step != Step::Capture)
        back();
}

void ProbeLinearisationProcedure::setDegree(int degree) {
    if (degree != kAutoDegree && (degree < 2 || degree > 4))
        throw std::invalid_argument("the degree must be 2, 3, 4 or automatic");
    if (m_degree == degree) return;
    m_degree = degree;
    if (m_step == Step::Accepted) m_step = Step::Fit;  // another table needs another acceptance
    if (m_step == Step::Fit) refit();
}

void ProbeLinearisationProcedure::refit() {
    if (const std::optional<ProbeCaptureResult> r = m_capture.abort()) finishCapture(*r);
    m_checks.clear();
    m_fit = fitProbePoints(m_points, m_config.adcBits, m_degree);
    report(event(m_fit.usable() ? ProbeEvent::Kind::Fitted : ProbeEvent::Kind::FitRefused));
}

void ProbeLinearisationProcedure::check(double referenceUm) {
    requireStep(Step::Fit, "a verification point");
    if (!m_fit.usable()) throw std::logic_error("a verification point needs a usable fit");
    startCapture(referenceUm, std::nullopt, true);
}

bool ProbeLinearisationProcedure::accept() {
    if (m_step == Step::Accepted) return true;
    const bool failedCheck =
        std::any_of(m_checks.begin(), m_checks.end(), [](const ProbeCheck& c) { return !c.passed; });
    if (m_step != Step::Fit || !m_fit.usable() || capturing() || failedCheck) {
        report(event(ProbeEvent::Kind::AcceptRefused));
        return false;
    }
    m_step = Step::Accepted;
    report(event(ProbeEvent::Kind::Accepted));
    return true;
}

void ProbeLinearisationProcedure::withdrawAcceptance() {
    if (m_step == Step::Accepted) m_step = Step::Fit;
}

void ProbeLinearisationProcedure::startUpload(TableUploadPort& port, std::vector<std::uint8_t> image,
                                              std::uint16_t version) {
    requireStep(Step::Upload, "uploading the table");
    m_upload.start(port, std::move(image), version);
    reportUpload();
}

void ProbeLinearisationProcedure::pumpProbe(DeflectionProbe& probe, double elapsedS) {
    if (const std::optional<ProbeCaptureResult> r = m_capture.pump(probe, elapsedS)) finishCapture(*r);
}

void ProbeLinearisationProcedure::pumpUpload(TableUploadPort& port, double elapsedS) {
    if (!m_upload.running()) return;
    m_upload.pump(port, elapsedS);
    reportUpload();
}

void ProbeLinearisationProcedure::reportUpload() {
    const TableUploadProcedure::Phase phase = m_upload.phase();
    if (phase == m_reportedUpload && phase != TableUploadProcedure::Phase::Failed) return;
    m_reportedUpload = phase;
    if (phase == TableUploadProcedure::Phase::Verified) {
        report(event(ProbeEvent::Kind::UploadVerified));
    } else if (phase == TableUploadProcedure::Phase::Mismatch || phase == TableUploadProcedure::Phase::Failed) {
        ProbeEvent e = event(ProbeEvent::Kind::UploadFailed);
        e.uploadProblem = m_upload.problem();
        e.deviceMessage = m_upload.deviceMessage();
        report(std::move(e));
    }
}

void ProbeLinearisationProcedure::finishCapture(const ProbeCaptureResult& result) {
    const std::optional<int> repeat = m_repeat;
    const bool check = m_checking;
    m_repeat.reset();
    m_checking = false;
    if (result.problem != CaptureProblem::None) {
        ProbeEvent e = event(ProbeEvent::Kind::CaptureFailed, repeat ? *repeat + 1 : 0, result.point);
        e.problem = result.problem;
        e.deviceMessage = result.deviceMessage;
        report(std::move(e));
        return;
    }
    if (check) {
        finishCheck(result);
        return;
    }
    if (repeat && *repeat < static_cast<int>(m_points.size())) {
        m_points[static_cast<std::size_t>(*repeat)] = result.point;
        report(event(ProbeEvent::Kind::PointRepeated, *repeat + 1, result.point));
        return;
    }
    m_points.push_back(result.point);
    report(event(ProbeEvent::Kind::PointCaptured, static_cast<int>(m_points.size()), result.point));
}

void ProbeLinearisationProcedure::finishCheck(const ProbeCaptureResult& result) {
    if (!m_fit.usable()) return;
    const Linearisation& lin = *m_fit.linearisation;
    ProbeCheck c;
    c.point = result.point;
    c.readingUm = lin.table.interpolatedUm(result.point.adcCode);
    c.deviationUm = c.readingUm - result.point.referenceUm;
    // The instrument reads to half a division, the fit scatters by its residual (3σ), the table
    // adds its own step.
    c.toleranceUm = 0.5 * m_config.referenceDivisionUm + 3.0 * lin.fit.rmsResidualUm + lin.tableResolutionUm;
    c.passed = !result.point.saturated && std::abs(c.deviationUm) <= c.toleranceUm;
    m_checks.push_back(c);
    ProbeEvent e = event(ProbeEvent::Kind::CheckDone, static_cast<int>(m_checks.size()), result.point);
    e.check = c;
    report(std::move(e));
}

std::vector<ProbeEvent> ProbeLinearisationProcedure::takeEvents() {
    std::vector<ProbeEvent> out;
    out.swap(m_events);
    return out;
}

std::vector<CalibrationPoint> ProbeLinearisationProcedure::calibrationPoints() const {
    std::vector<CalibrationPoint> out;
    for (const ProbePoint& p : m_points)
        out.push_back({p.referenceUm, p.adcCode, 0});
    return out;
}

}  // namespace tt::core
