#include "ui/calibration/probe_wizard_context.h"

#include <algorithm>

#include "ui/app_state.h"

namespace tt::ui {

DeviceCalibrationProbe* ProbeWizardContext::probe() const {
    if (probes.empty()) return nullptr;
    const std::size_t i =
        static_cast<std::size_t>(std::clamp(session->probeIndex, 0, static_cast<int>(probes.size()) - 1));
    return probes[i];
}

QString ProbeWizardContext::operatorName() const {
    return app && app->state ? app->state->operatorName().trimmed() : QString();
}

void ProbeWizardContext::pumpProbe(double elapsedS) const {
    if (DeviceCalibrationProbe* p = probe()) procedure().pumpProbe(p->port(), elapsedS);
}

void ProbeWizardContext::setUp(int plane, int adcBits, double divisionUm) const {
    core::ProbeLinearisationProcedure& proc = procedure();
    const core::ProbeProcedureConfig& c = proc.config();
    if (c.plane == plane && c.adcBits == adcBits && c.referenceDivisionUm == divisionUm) return;
    proc.returnToCapture();
    proc.abort();
    proc.configure(plane, adcBits, divisionUm);
    proc.takeEvents();
}

}  // namespace tt::ui
