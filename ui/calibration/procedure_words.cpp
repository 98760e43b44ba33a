#include "ui/calibration/procedure_words.h"

#include <QStringList>
#include <cmath>

#include "core/calibration/linearisation_image.h"

namespace tt::ui {

namespace {

QString number(double v, int decimals) {
    return QString::number(v, 'f', decimals);
}

QString topCode(int adcBits) {
    return QString::number(static_cast<long long>(std::ldexp(1.0, adcBits)) - 1);
}

}  // namespace

QString ProcedureWords::probeEvent(const core::ProbeEvent& e, int adcBits, double noSampleTimeoutS) {
    using Kind = core::ProbeEvent::Kind;
    const core::ProbePoint& p = e.value;
    const QString saturated =
        p.saturated ? QLatin1Char(' ') + tr("The ADC saturated here (raw codes %1 to %2, limits 0 and %3): the point "
                                            "is kept but not used in the fit.")
                                             .arg(p.lowestCode)
                                             .arg(p.highestCode)
                                             .arg(topCode(adcBits))
                    : QString();
    switch (e.kind) {
        case Kind::PointCaptured:
            return tr("Point %1: %2 µm at ADC code %3 (mean of %4 samples).")
                       .arg(e.point)
                       .arg(number(p.referenceUm, 1), number(p.adcCode, 1))
                       .arg(p.samples) +
                   saturated;
        case Kind::PointRepeated:
            return tr("Point %1 read again: %2 µm at ADC code %3.")
                       .arg(e.point)
                       .arg(number(p.referenceUm, 1), number(p.adcCode, 1)) +
                   saturated;
        case Kind::PointTyped:
            return tr("Typed point %1 added.").arg(e.point) + saturated;
        case Kind::PointRemoved:
            return tr("Point %1 removed.").arg(e.point);
        case Kind::CaptureFailed:
            switch (e.problem) {
                case core::CaptureProblem::NotReady:
                    return tr("The probe is not ready (%1): type the point instead.")
                        .arg(QString::fromStdString(e.deviceMessage));
                case core::CaptureProblem::NoSamples:
                    return tr("No samples from the probe for %1 s. A mandrel withholds its samples while its ADC is "
                              "over range (the bar bent beyond the probe's travel): unload the bar a little. "
                              "Otherwise check its connection, or type the point.")
                        .arg(number(noSampleTimeoutS, 0));
                case core::CaptureProblem::LoadChanged:
                    return tr("The load changed while the point was read: capture it again once the bar is still.");
                case core::CaptureProblem::Aborted:
                case core::CaptureProblem::None:
                    break;
            }
            return tr("Capture stopped; no point added.");
        case Kind::CheckDone:
            return e.check ? probeCheck(*e.check) : QString();
        case Kind::Fitted:
        case Kind::FitRefused:
        case Kind::Accepted:
        case Kind::AcceptRefused:
        case Kind::UploadVerified:
        case Kind::UploadFailed:
            break;
    }
    return {};
}

QString ProcedureWords::fitRefusal(const core::ProbeFitOutcome& o, int adcBits) {
    switch (o.refusal) {
        case core::ProbeFitRefusal::None:
            return {};
        case core::ProbeFitRefusal::TooFewPoints:
            return tr("the fit needs at least %1 points within the ADC's range, there are %2").arg(o.needed).arg(o.got);
        case core::ProbeFitRefusal::TooFewReferences:
            return tr("the fit needs at least %1 different reference deflections, there are %2")
                .arg(o.needed)
                .arg(o.got);
        case core::ProbeFitRefusal::ConstantCode:
            return tr("the ADC code is %1 at every point: it does not follow the deflection (is the probe connected?)")
                .arg(number(o.constantCode, 0));
        case core::ProbeFitRefusal::NonMonotonic: {
            const core::Monotonicity& m = o.fit->monotonicity;
            const QString where =
                m.insideCalibratedRange
                    ? tr("inside the calibrated range %1 to %2 µm")
                          .arg(number(o.fit->calibratedMinUm, 1), number(o.fit->calibratedMaxUm, 1))
                    : tr("within the ADC's range 0 to %1, beyond the calibrated range").arg(topCode(adcBits));
            return tr("the fitted characteristic is not monotonic: it turns at %1 µm (ADC code %2) %3, so one code "
                      "would stand for two deflections; check the points near there or choose another degree")
                .arg(number(m.turningDeflectionUm.value_or(0.0), 1), number(m.turningCode.value_or(0.0), 0), where);
        }
        case core::ProbeFitRefusal::OutOfRange:
            return tr("the table does not fit the ADC's range 0 to %1 or 16-bit entries; calibrate over the whole "
                      "travel of the probe")
                .arg(topCode(adcBits));
        case core::ProbeFitRefusal::BadInput:
            break;
    }
    return tr("the points cannot be fitted (a value that is not a number, or a set-up out of range)");
}

QString ProcedureWords::degreeChoice(const core::CharacteristicFit& f, int pointsUsed) {
    QString text;
    switch (f.choice) {
        case core::DegreeChoice::Asked:
            return tr("Degree %1, as chosen").arg(f.degree);
        case core::DegreeChoice::LowestError:
            text = tr("Degree %1 chosen by cross-validation: it predicts the points best").arg(f.degree);
            break;
        case core::DegreeChoice::WithinStandardError:
            text = tr("Degree %1 chosen by cross-validation: within one standard error of degree %2, which "
                      "predicts best, so the simpler curve is kept")
                       .arg(f.degree)
                       .arg(f.bestDegree);
            break;
        case core::DegreeChoice::WithinHalfCode:
            text = tr("Degree %1 chosen by cross-validation: within half an ADC code of degree %2, which "
                      "predicts best, so the simpler curve is kept")
                       .arg(f.degree)
                       .arg(f.bestDegree);
            break;
    }
    if (!f.scores.empty() && f.scores.back().degree < 4)
        text += QLatin1Char(' ') +
                tr("(only degrees up to %1 can be tried with %2 points)").arg(f.scores.back().degree).arg(pointsUsed);
    return text;
}

QString ProcedureWords::leftOut(const std::vector<int>& points, int adcBits) {
    if (points.empty()) return {};
    QStringList numbers;
    for (int p : points)
        numbers << QString::number(p);
    return tr("Not used in the fit: point(s) %1, where the ADC saturated (a raw code reached 0 or %2). Capture them "
              "within the probe's range, or remove them.")
        .arg(numbers.join(QStringLiteral(", ")), topCode(adcBits));
}

QString ProcedureWords::probeCheck(const core::ProbeCheck& c) {
    if (c.point.saturated)
        return tr("Check at %1 µm: the ADC saturated (raw code %2 to %3), so the table cannot be verified there.")
            .arg(number(c.point.referenceUm, 1))
            .arg(c.point.lowestCode)
            .arg(c.point.highestCode);
    const QString text = tr("Check at %1 µm: the table reads %2 µm, %3 µm off (allowed ±%4 µm).")
                             .arg(number(c.point.referenceUm, 1), number(c.readingUm, 1), number(c.deviationUm, 1),
                                  number(c.toleranceUm, 1));
    return text + QLatin1Char(' ') +
           (c.passed ? tr("Passed.") : tr("Failed: capture more points or choose another degree."));
}

QString ProcedureWords::crc(const core::TableReadback& r) {
    return r.crc32c ? QStringLiteral("CRC-32C %1").arg(QString::fromStdString(core::crcText(*r.crc32c)))
                    : QStringLiteral("CRC-16 %1").arg(QString::fromStdString(core::crcText(r.crc16, 16)));
}

QString ProcedureWords::uploadOutcome(const core::TableUploadProcedure& u) {
    using Phase = core::TableUploadProcedure::Phase;
    using Problem = core::TableUploadProcedure::Problem;
    const QString device = QString::fromStdString(u.deviceMessage());
    switch (u.phase()) {
        case Phase::Idle:
            return {};
        case Phase::Sending:
            return device.isEmpty() ? tr("Uploading…") : device;
        case Phase::ReadingBack:
            return tr("Stored; asking the mandrel which table it holds…");
        case Phase::Verified:
            return tr("Verified: the mandrel reports version %1, %2, the same as the image sent.")
                .arg(u.readback()->version)
                .arg(crc(*u.readback()));
        case Phase::Mismatch:
            if (u.problem() == Problem::NoReadback || !u.readback())
                return tr("The mandrel did not report its table; upload again.");
            return readbackDiffers(u) + QLatin1Char(' ') + tr("Upload again.");
        case Phase::Failed:
            switch (u.problem()) {
                case Problem::Refused:
                    return tr("Upload refused: %1").arg(device);
                case Problem::Aborted:
                    return tr("Upload stopped. The saved table is kept; upload it again.");
                case Problem::LinkFailed:
                case Problem::NoReadback:
                case Problem::ReadbackDiffers:
                case Problem::None:
                    break;
            }
            return tr("Upload failed: %1.").arg(device) + QLatin1Char(' ') +
                   (u.readback() ? readbackDiffers(u) + QLatin1Char(' ') : QString()) +
                   tr("The saved table is kept; try again.");
    }
    return {};
}

QString ProcedureWords::readbackDiffers(const core::TableUploadProcedure& u) {
    return tr("Read-back does not match: the mandrel reports version %1, %2%3; the image has version %4, "
              "CRC-32C %5.")
        .arg(u.readback()->version)
        .arg(crc(*u.readback()), u.readback()->valid ? QString() : tr(", and says the table is not valid"))
        .arg(u.version())
        .arg(QString::fromStdString(core::crcText(u.imageCrc32c())));
}

QString ProcedureWords::strokeProblem(core::StrokeProblem problem) {
    switch (problem) {
        case core::StrokeProblem::NotCylindrical:
            return tr("the forward and reverse strokes differ (taper or feed motion, not a dither)");
        case core::StrokeProblem::SlideNotMoving:
            return tr("the slide does not move: is the dither running?");
        case core::StrokeProblem::WindowTooShort:
            return tr(
                "too few samples at constant velocity in each stroke: a longer dither period or faster "
                "polling is needed");
        case core::StrokeProblem::WaitingForStrokes:
        case core::StrokeProblem::None:
            break;
    }
    return tr("too few complete forward and reverse strokes");
}

QString ProcedureWords::kpEvent(const core::KpEvent& e, double noSampleTimeoutS) {
    using Kind = core::KpEvent::Kind;
    const core::KpLoadPoint& p = e.value;
    switch (e.kind) {
        case Kind::LoadMeasured:
        case Kind::LoadRepeated:
            return tr("%1 N: ΔI = %2 A from %3 stroke pairs.")
                .arg(number(p.loadN, 0), number(p.currentDifferenceA, 3))
                .arg(p.pairs);
        case Kind::LoadTyped:
            return tr("Typed point added.");
        case Kind::LoadRemoved:
            return tr("Load %1 removed.").arg(e.point);
        case Kind::MeasureFailed:
            switch (e.problem) {
                case core::KpMeasureProblem::NotReady:
                    return tr("The drive read-out is not ready: %1").arg(QString::fromStdString(e.deviceMessage));
                case core::KpMeasureProblem::NoSamples:
                    return tr("No samples from the drive read-out for %1 s: check its connection.")
                        .arg(number(noSampleTimeoutS, 0));
                case core::KpMeasureProblem::TooFewPairs:
                    return tr("No reliable current difference at %1 N (%2 stroke pairs): %3")
                        .arg(number(p.loadN, 0))
                        .arg(p.pairs)
                        .arg(strokeProblem(e.strokeProblem));
                case core::KpMeasureProblem::Aborted:
                case core::KpMeasureProblem::None:
                    break;
            }
            return tr("Measurement stopped; no point added.");
        case Kind::CheckDone:
            return e.check ? kpCheck(*e.check) : QString();
        case Kind::Fitted:
        case Kind::FitRefused:
        case Kind::Accepted:
        case Kind::AcceptRefused:
            break;
    }
    return {};
}

QString ProcedureWords::kpRefusal(const core::KpFitOutcome& o) {
    if (!o.refusal) return {};
    switch (*o.refusal) {
        case core::KpFitProblem::TooFewLoads:
            return tr("k_p needs at least %1 known loads, there are %2").arg(core::kMinKpLoads).arg(o.count);
        case core::KpFitProblem::TooFewDifferentLoads:
            return tr("k_p needs at least 2 different loads");
        case core::KpFitProblem::NotANumber:
            return tr("load %1 is not a number").arg(o.count);
        case core::KpFitProblem::ConstantCurrent:
            return tr("the current difference is the same at every load: the drive current is not read");
        case core::KpFitProblem::FallsWithLoad:
            return tr("the current difference falls as the load grows (slope %1 N/A): the load acts the other way "
                      "or the current sign is reversed")
                .arg(number(o.slopeNPerA, 1));
    }
    return {};
}

QString ProcedureWords::kpCheck(const core::KpCheck& c) {
    return tr("Check at %1 N: k_p ΔI + offset gives %2 N, %3 N off (allowed ±%4 N).")
               .arg(number(c.point.loadN, 0), number(c.forceN, 0), number(c.deviationN, 0), number(c.toleranceN, 0)) +
           QLatin1Char(' ') + (c.passed ? tr("Passed.") : tr("Failed: measure the loads again."));
}

}  // namespace tt::ui
