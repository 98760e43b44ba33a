#include "ui/calibration/probe_wizard.h"

#include "ui/calibration/probe_accept_page.h"
#include "ui/calibration/probe_capture_page.h"
#include "ui/calibration/probe_choose_page.h"
#include "ui/calibration/probe_fit_page.h"
#include "ui/calibration/probe_reference_page.h"
#include "ui/calibration/probe_save_page.h"

namespace tt::ui {

ProbeCalibrationWizard::ProbeCalibrationWizard(AppContext& app, ProbeCalibrationSession& session,
                                               std::vector<DeviceCalibrationProbe*> probes,
                                               storage::CalibrationStore* store, QWidget* parent)
    : CalibrationWizard(QStringLiteral("probeWizard"), parent), m_ctx{&app, &session, std::move(probes), store} {
    m_choose = new ProbeChoosePage(m_ctx, this);
    m_reference = new ProbeReferencePage(m_ctx, this);
    m_capture = new ProbeCapturePage(m_ctx, this);
    m_fit = new ProbeFitPage(m_ctx, this);
    m_accept = new ProbeAcceptPage(m_ctx, this);
    m_save = new ProbeSavePage(m_ctx, this);
    setPage(ChoosePage, m_choose);
    setPage(ReferencePage, m_reference);
    setPage(CapturePage, m_capture);
    setPage(FitPage, m_fit);
    setPage(AcceptPage, m_accept);
    setPage(SavePage, m_save);
    retranslate();
}

QString ProbeCalibrationWizard::titleText() const {
    return tr("Probe mandrel linearisation");
}

}  // namespace tt::ui
