#pragma once

#include <vector>

#include "ui/calibration/calibration_wizard.h"
#include "ui/calibration/kp_wizard_context.h"

namespace tt::storage {
class CalibrationStore;
class ToolStore;
}  // namespace tt::storage

namespace tt::ui {

class KpFitPage;
class KpLoadsPage;
class KpSavePage;
class KpSetupPage;

/// The k_p calibration wizard (issue 6, item 5): known loads on the cross slide, the current
/// difference with dither at each, the fit of k_p verified at a further load, saved and written
/// into the tool table. The steps are core::KpCalibrationProcedure's.
class KpCalibrationWizard : public CalibrationWizard {
    Q_OBJECT
public:
    enum PageId { SetupPage, LoadsPage, FitPage, SavePage };

    KpCalibrationWizard(AppContext& app, KpSession& session, std::vector<DeviceKpDrive*> drives,
                        storage::CalibrationStore* calibrations, storage::ToolStore* tools, QWidget* parent = nullptr);

    KpSetupPage* setupPage() const { return m_setup; }
    KpLoadsPage* loadsPage() const { return m_loads; }
    KpFitPage* fitPage() const { return m_fit; }
    KpSavePage* savePage() const { return m_save; }

protected:
    QString titleText() const override;

private:
    KpWizardContext m_ctx;
    KpSetupPage* m_setup;
    KpLoadsPage* m_loads;
    KpFitPage* m_fit;
    KpSavePage* m_save;
};

}  // namespace tt::ui
