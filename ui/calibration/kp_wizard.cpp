#include "ui/calibration/kp_wizard.h"

#include "ui/calibration/kp_fit_page.h"
#include "ui/calibration/kp_loads_page.h"
#include "ui/calibration/kp_save_page.h"
#include "ui/calibration/kp_setup_page.h"

namespace tt::ui {

KpCalibrationWizard::KpCalibrationWizard(AppContext& app, KpSession& session, std::vector<DeviceKpDrive*> drives,
                                         storage::CalibrationStore* calibrations, storage::ToolStore* tools,
                                         QWidget* parent)
    : CalibrationWizard(QStringLiteral("kpWizard"), parent),
      m_ctx{&app, &session, std::move(drives), calibrations, tools} {
    m_setup = new KpSetupPage(m_ctx, this);
    m_loads = new KpLoadsPage(m_ctx, this);
    m_fit = new KpFitPage(m_ctx, this);
    m_save = new KpSavePage(m_ctx, this);
    setPage(SetupPage, m_setup);
    setPage(LoadsPage, m_loads);
    setPage(FitPage, m_fit);
    setPage(SavePage, m_save);
    retranslate();
}

QString KpCalibrationWizard::titleText() const {
    return tr("k_p from known loads");
}

}  // namespace tt::ui
