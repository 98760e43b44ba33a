#pragma once

#include <vector>

#include "ui/calibration/calibration_wizard.h"
#include "ui/calibration/probe_wizard_context.h"

namespace tt::storage {
class CalibrationStore;
}

namespace tt::ui {

class ProbeAcceptPage;
class ProbeCapturePage;
class ProbeChoosePage;
class ProbeFitPage;
class ProbeReferencePage;
class ProbeSavePage;

/// The probe mandrel linearisation wizard (issue 6, item 5): choose the probe and plane → set up
/// the reference → capture points live (or type them) with a live plot → fit with the residual
/// plot and the degree choice explained → verify and accept → save a versioned table and upload
/// it with read-back of its CRC. The steps are core::ProbeLinearisationProcedure's; the pages show
/// its state and forward the clicks. Works on the session it is given, so Back and Cancel lose
/// nothing.
class ProbeCalibrationWizard : public CalibrationWizard {
    Q_OBJECT
public:
    enum PageId { ChoosePage, ReferencePage, CapturePage, FitPage, AcceptPage, SavePage };

    ProbeCalibrationWizard(AppContext& app, ProbeCalibrationSession& session,
                           std::vector<DeviceCalibrationProbe*> probes, storage::CalibrationStore* store,
                           QWidget* parent = nullptr);

    ProbeChoosePage* choosePage() const { return m_choose; }
    ProbeReferencePage* referencePage() const { return m_reference; }
    ProbeCapturePage* capturePage() const { return m_capture; }
    ProbeFitPage* fitPage() const { return m_fit; }
    ProbeAcceptPage* acceptPage() const { return m_accept; }
    ProbeSavePage* savePage() const { return m_save; }

protected:
    QString titleText() const override;

private:
    ProbeWizardContext m_ctx;
    ProbeChoosePage* m_choose;
    ProbeReferencePage* m_reference;
    ProbeCapturePage* m_capture;
    ProbeFitPage* m_fit;
    ProbeAcceptPage* m_accept;
    ProbeSavePage* m_save;
};

}  // namespace tt::ui
