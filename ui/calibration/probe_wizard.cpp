#include "ui/calibration/probe_wizard.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include "core/calibration/calibration_csv.h"
#include "core/calibration/linearisation_image.h"
#include "core/storage/calibration_store.h"
#include "ui/app_state.h"
#include "ui/calibration/probe_capture_page.h"
#include "ui/calibration/probe_fit_page.h"
#include "ui/calibration/procedure_words.h"
#include "ui/prompt.h"

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

// --- 1. Choose ------------------------------------------------------------------------------

ProbeChoosePage::ProbeChoosePage(ProbeWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_probeLabel(new QLabel(this)),
      m_probe(new QComboBox(this)),
      m_planeLabel(new QLabel(this)),
      m_plane(new QComboBox(this)),
      m_bitsLabel(new QLabel(this)),
      m_bits(new QSpinBox(this)),
      m_health(wrappedLabel(this)) {
    m_probe->setObjectName(QStringLiteral("probeCombo"));
    m_plane->setObjectName(QStringLiteral("planeCombo"));
    m_bits->setObjectName(QStringLiteral("adcBitsSpin"));
    m_bits->setRange(core::kMinAdcBits, core::kMaxAdcBits);
    m_plane->addItem(QString(), 0);
    m_plane->addItem(QString(), 1);
    auto* form = new QFormLayout(this);
    form->setVerticalSpacing(16);
    form->addRow(m_probeLabel, m_probe);
    form->addRow(m_planeLabel, m_plane);
    form->addRow(m_bitsLabel, m_bits);
    form->addRow(m_health);
    connect(m_probe, &QComboBox::currentIndexChanged, this, [this] {
        m_ctx.session->probeIndex = std::max(0, m_probe->currentIndex());
        if (DeviceCalibrationProbe* p = m_ctx.probe(); p && p->adcBits()) m_bits->setValue(*p->adcBits());
        store();
        initializePage();
    });
    connect(m_plane, &QComboBox::currentIndexChanged, this, [this] { store(); });
    connect(m_bits, &QSpinBox::valueChanged, this, [this] { store(); });
}

void ProbeChoosePage::store() {
    m_ctx.session->probeIndex = std::max(0, m_probe->currentIndex());
    m_ctx.setUp(m_plane->currentData().toInt(), m_bits->value(), m_ctx.procedure().config().referenceDivisionUm);
}

void ProbeChoosePage::initializePage() {
    const QSignalBlocker a(m_probe), b(m_plane), c(m_bits);
    m_probe->clear();
    for (DeviceCalibrationProbe* p : m_ctx.probes)
        m_probe->addItem(p->name());
    m_probe->setCurrentIndex(std::clamp(m_ctx.session->probeIndex, 0, std::max(0, m_probe->count() - 1)));
    m_plane->setCurrentIndex(m_ctx.procedure().config().plane);
    m_bits->setValue(m_ctx.procedure().config().adcBits);
    DeviceCalibrationProbe* p = m_ctx.probe();
    m_bits->setEnabled(!p || !p->adcBits());
    if (p && p->adcBits()) {
        m_bits->setValue(*p->adcBits());  // what the mandrel says it has
        store();
    }
    if (!p) {
        m_health->setText(tr("No probe mandrel is configured: add one on the Devices page, or type the points."));
        return;
    }
    const core::DeviceHealth h = p->port().health();
    m_health->setText(
        h.ready()
            ? tr("%1 is ready.").arg(p->name())
            : tr("%1: %2 — you can still type the points by hand.").arg(p->name(), QString::fromStdString(h.message)));
}

bool ProbeChoosePage::validatePage() {
    store();
    return true;
}

void ProbeChoosePage::retranslate() {
    setTitle(tr("Probe and bending plane"));
    setSubTitle(tr("Which probe mandrel is calibrated, in which plane, and its ADC resolution."));
    m_probeLabel->setText(tr("Probe mandrel"));
    m_planeLabel->setText(tr("Bending plane"));
    m_bitsLabel->setText(tr("ADC resolution"));
    m_bits->setSuffix(tr(" bit"));
    m_plane->setItemText(0, tr("X — radial (bore diameter)"));
    m_plane->setItemText(1, tr("Y — tangential"));
}

// --- 2. Reference -----------------------------------------------------------------------------

ProbeReferencePage::ProbeReferencePage(ProbeWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_kindLabel(new QLabel(this)),
      m_kind(new QComboBox(this)),
      m_resolutionLabel(new QLabel(this)),
      m_resolution(new QDoubleSpinBox(this)),
      m_instructions(wrappedLabel(this)) {
    m_kind->setObjectName(QStringLiteral("referenceCombo"));
    m_resolution->setObjectName(QStringLiteral("resolutionSpin"));
    m_kind->addItem(QString());
    m_kind->addItem(QString());
    m_resolution->setRange(0.1, 10.0);
    m_resolution->setDecimals(1);
    m_resolution->setSingleStep(0.5);
    auto* form = new QFormLayout(this);
    form->setVerticalSpacing(16);
    form->addRow(m_kindLabel, m_kind);
    form->addRow(m_resolutionLabel, m_resolution);
    form->addRow(m_instructions);
}

void ProbeReferencePage::initializePage() {
    m_kind->setCurrentIndex(m_ctx.session->referenceKind);
    m_resolution->setValue(m_ctx.procedure().config().referenceDivisionUm);
}

bool ProbeReferencePage::validatePage() {
    m_ctx.session->referenceKind = m_kind->currentIndex();
    const core::ProbeProcedureConfig& c = m_ctx.procedure().config();
    m_ctx.setUp(c.plane, c.adcBits, m_resolution->value());
    return true;
}

void ProbeReferencePage::retranslate() {
    setTitle(tr("Set up the reference"));
    setSubTitle(tr("The deflection is read on an instrument at the tool tip while the bar is loaded."));
    m_kindLabel->setText(tr("Reference instrument"));
    m_kind->setItemText(0, tr("Dial indicator"));
    m_kind->setItemText(1, tr("Micrometer"));
    m_resolutionLabel->setText(tr("Division of the instrument"));
    m_resolution->setSuffix(tr(" µm"));
    m_instructions->setText(
        tr("1. Clamp the boring bar as for cutting; mount the instrument on the lathe bed touching the tool tip "
           "in the chosen plane.\n2. With the bar unloaded, set the instrument to zero.\n3. Load the bar in both "
           "directions in steps (a screw jack against the tool block) over the whole travel of the probe; at each "
           "step read the instrument and capture the point. Aim for 15 to 25 points, both signs."));
}

// --- 5. Verify and accept ---------------------------------------------------------------------

ProbeAcceptPage::ProbeAcceptPage(ProbeWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_summary(wrappedLabel(this)),
      m_checkTitle(new QLabel(this)),
      m_jackLabel(new QLabel(this)),
      m_jack(new QDoubleSpinBox(this)),
      m_setJack(new QPushButton(this)),
      m_referenceLabel(new QLabel(this)),
      m_reference(new QDoubleSpinBox(this)),
      m_check(new QPushButton(this)),
      m_result(wrappedLabel(this)),
      m_accept(new QCheckBox(this)),
      m_timer(new QTimer(this)) {
    m_accept->setObjectName(QStringLiteral("acceptCheck"));
    m_accept->setStyleSheet(
        QStringLiteral("QCheckBox { font-weight: bold; } QCheckBox::indicator { width: 28px; height: 28px; }"));
    m_summary->setObjectName(QStringLiteral("acceptSummary"));
    m_summary->setTextFormat(Qt::RichText);
    m_checkTitle->setObjectName(QStringLiteral("SectionTitle"));
    m_jack->setObjectName(QStringLiteral("checkJackSpin"));
    m_reference->setObjectName(QStringLiteral("checkReferenceSpin"));
    m_check->setObjectName(QStringLiteral("checkPoint"));
    m_result->setObjectName(QStringLiteral("checkResult"));
    for (QDoubleSpinBox* s : {m_jack, m_reference}) {
        s->setRange(-2000.0, 2000.0);
        s->setDecimals(1);
        s->setMinimumWidth(170);
    }
    auto* grid = new QGridLayout;
    grid->addWidget(m_jackLabel, 0, 0);
    grid->addWidget(m_jack, 0, 1);
    grid->addWidget(m_setJack, 0, 2);
    grid->addWidget(m_referenceLabel, 1, 0);
    grid->addWidget(m_reference, 1, 1);
    grid->addWidget(m_check, 1, 2);
    grid->setColumnStretch(3, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addSpacing(8);
    layout->addWidget(m_checkTitle);
    layout->addLayout(grid);
    layout->addWidget(m_result);
    layout->addStretch(1);
    layout->addWidget(m_accept);
    m_timer->setInterval(ProbeCapturePage::kPollMs);
    connect(m_timer, &QTimer::timeout, this, [this] {
        if (isShown()) pollProbe();
    });
    connect(m_setJack, &QPushButton::clicked, this, [this] { setJack(m_jack->value()); });
    connect(m_check, &QPushButton::clicked, this, &ProbeAcceptPage::checkPoint);
    connect(m_accept, &QCheckBox::toggled, this, &ProbeAcceptPage::setAccepted);
}

void ProbeAcceptPage::initializePage() {
    DeviceCalibrationProbe* p = m_ctx.probe();
    const bool jack = p && p->hasJack();
    for (QWidget* w : std::initializer_list<QWidget*>{m_jackLabel, m_jack, m_setJack})
        w->setVisible(jack);
    m_reference->setSingleStep(m_ctx.procedure().config().referenceDivisionUm);
    refresh();
    if (p) m_timer->start();
}

void ProbeAcceptPage::cleanupPage() {
    m_timer->stop();
    m_ctx.procedure().abort();  // a check being read
    m_ctx.procedure().takeEvents();
}

bool ProbeAcceptPage::validatePage() {
    return m_ctx.procedure().accepted();
}

bool ProbeAcceptPage::isComplete() const {
    return m_ctx.procedure().accepted();
}

void ProbeAcceptPage::setJack(double um) {
    DeviceCalibrationProbe* p = m_ctx.probe();
    if (!p || !p->hasJack() || m_ctx.procedure().capturing()) return;
    m_jack->setValue(um);
    pollProbe(0.0);  // the samples queued so far were read under the old load
    try {
        p->bendBar(m_ctx.procedure().config().plane, um / 1000.0);
    } catch (const std::invalid_argument&) {
        return;
    }
    const double division = m_ctx.procedure().config().referenceDivisionUm;
    m_reference->setValue(std::round(um / division) * division);
    m_ctx.procedure().loadChanged();
    m_ctx.procedure().takeEvents();
}

void ProbeAcceptPage::setReferenceUm(double um) {
    m_reference->setValue(um);
}

bool ProbeAcceptPage::checkPoint() {
    core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    if (!m_ctx.probe()) return false;
    if (proc.capturing()) {
        proc.abort();
        proc.takeEvents();
        refresh();
        return false;
    }
    proc.withdrawAcceptance();  // a new check may change the verdict
    pollProbe(0.0);             // samples queued before the press are not the check's
    try {
        proc.check(m_reference->value());
    } catch (const std::logic_error&) {
        return false;
    }
    m_result->setText(tr("Hold still, then the live codes are averaged…"));
    markProblem(m_result, false);
    refresh();
    return true;
}

void ProbeAcceptPage::pollProbe(double elapsedS) {
    m_ctx.pumpProbe(elapsedS);
    const core::ProbeProcedureConfig& c = m_ctx.procedure().config();
    bool any = false;
    for (const core::ProbeEvent& e : m_ctx.procedure().takeEvents()) {
        m_result->setText(ProcedureWords::probeEvent(e, c.adcBits, c.capture.noSampleTimeoutS));
        if (e.check)
            markVerdict(m_result, e.check->passed);
        else
            markProblem(m_result, e.kind == core::ProbeEvent::Kind::CaptureFailed);
        any = true;
    }
    if (any) refresh();
}

void ProbeAcceptPage::setAccepted(bool accepted) {
    core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    if (accepted && !proc.accept()) {
        m_result->setText(
            tr("Not accepted: a verification point failed or is being read. Check again, or go back "
               "and capture more points."));
        markProblem(m_result, true);
    } else if (!accepted) {
        proc.withdrawAcceptance();
    }
    proc.takeEvents();
    refresh();
}

QString ProbeAcceptPage::checkResult() const {
    return m_result->text();
}

void ProbeAcceptPage::refresh() {
    const core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    {
        const QSignalBlocker block(m_accept);
        m_accept->setChecked(proc.accepted());
    }
    m_check->setText(proc.capturing() ? tr("Stop") : tr("Check point"));
    m_check->setEnabled(m_ctx.probe() != nullptr && proc.fitOutcome().usable());
    m_setJack->setEnabled(!proc.capturing());
    emit completeChanged();
    if (!proc.fitOutcome().usable()) return;
    const core::Linearisation& lin = *proc.fitOutcome().linearisation;
    DeviceCalibrationProbe* p = m_ctx.probe();
    const QString probe = p ? p->name() : tr("(typed points)");
    const int plane = proc.config().plane;
    const int version = m_ctx.store ? m_ctx.store->nextTableVersion(probe, plane) : 1;
    const double share = static_cast<double>(lin.extrapolatedEntries) /
                         static_cast<double>(std::max<std::size_t>(1, lin.table.entries.size()));
    const QString warning =
        share > core::kExtrapolatedWarningShare
            ? QStringLiteral("<br><b>%1</b>")
                  .arg(tr("%1 % of the table lies outside the calibrated range and is extrapolated; calibrate over "
                          "more of the probe's travel.")
                           .arg(100.0 * share, 0, 'f', 0)
                           .toHtmlEscaped())
            : QString();
    int passed = 0;
    for (const core::ProbeCheck& c : proc.checks())
        passed += c.passed ? 1 : 0;
    const QString checks = proc.checks().empty()
                               ? tr("no verification point yet")
                               : tr("%1 of %2 verification points passed").arg(passed).arg(proc.checks().size());
    const int used = static_cast<int>(proc.points().size() - proc.fitOutcome().leftOut.size());
    m_summary->setText(
        tr("<p>Characteristic of degree %1 from %2 points, residual RMS %3 µm.</p>"
           "<p>Table: %4 entries of %5 nm, worst error at the calibration points %6 µm, step between codes up "
           "to %7 µm; %8 entries outside the calibrated range %9 .. %10 µm are extrapolated.%11</p>"
           "<p>It will be saved as version <b>%12</b> of %13, plane %14, by <b>%15</b>.</p>")
            .arg(lin.fit.degree)
            .arg(used)
            .arg(lin.fit.rmsResidualUm, 0, 'f', 2)
            .arg(lin.table.entries.size())
            .arg(lin.table.scaleNm)
            .arg(lin.maxTableErrorUm, 0, 'f', 2)
            .arg(lin.tableResolutionUm, 0, 'f', 2)
            .arg(lin.extrapolatedEntries)
            .arg(lin.fit.calibratedMinUm, 0, 'f', 0)
            .arg(lin.fit.calibratedMaxUm, 0, 'f', 0)
            .arg(warning)
            .arg(version)
            .arg(probe.toHtmlEscaped())
            .arg(plane == 0 ? QStringLiteral("X") : QStringLiteral("Y"))
            .arg(m_ctx.operatorName().isEmpty() ? tr("(no operator name — set it in Settings)")
                                                : m_ctx.operatorName().toHtmlEscaped()));
    m_checkTitle->setText(tr("Verify the table — %1").arg(checks));
}

void ProbeAcceptPage::retranslate() {
    setTitle(tr("Verify and accept the table"));
    setSubTitle(
        tr("Load the bar to a deflection not captured and check that the table reads it; the table is "
           "stored only when you accept it."));
    m_jackLabel->setText(tr("Stand's screw jack"));
    m_setJack->setText(tr("Bend the bar"));
    m_referenceLabel->setText(tr("Reference reading"));
    for (QDoubleSpinBox* s : {m_jack, m_reference})
        s->setSuffix(tr(" µm"));
    m_accept->setText(tr("I accept this linearisation table"));
    refresh();
}

// --- 6. Save and upload -----------------------------------------------------------------------

ProbeSavePage::ProbeSavePage(ProbeWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent),
      m_ctx(context),
      m_intro(wrappedLabel(this)),
      m_save(new QPushButton(this)),
      m_upload(new QPushButton(this)),
      m_export(new QPushButton(this)),
      m_progress(new QProgressBar(this)),
      m_saved(wrappedLabel(this)),
      m_result(wrappedLabel(this)),
      m_timer(new QTimer(this)) {
    m_save->setObjectName(QStringLiteral("saveTable"));
    m_save->setProperty("role", QStringLiteral("primary"));
    m_upload->setObjectName(QStringLiteral("uploadTable"));
    m_export->setObjectName(QStringLiteral("exportTable"));
    m_result->setObjectName(QStringLiteral("saveResult"));
    m_progress->setRange(0, 100);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_save);
    buttons->addWidget(m_upload);
    buttons->addWidget(m_export);
    buttons->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_intro);
    layout->addLayout(buttons);
    layout->addWidget(m_progress);
    layout->addWidget(m_saved);
    layout->addWidget(m_result);
    layout->addStretch(1);
    m_timer->setInterval(100);
    connect(m_timer, &QTimer::timeout, this, [this] {
        if (isShown()) pollUpload();
    });
    connect(m_save, &QPushButton::clicked, this, &ProbeSavePage::save);
    connect(m_upload, &QPushButton::clicked, this, &ProbeSavePage::upload);
    connect(m_export, &QPushButton::clicked, this, [this] {
        if (!m_ctx.app || !m_ctx.app->prompt || !m_ctx.procedure().fitOutcome().usable()) return;
        const QString path =
            m_ctx.app->prompt->saveFileName(this, tr("Export the table"), QStringLiteral("linearisation.h"),
                                            tr("C header (*.h);;Binary image (*.bin);;CSV (*.csv)"));
        if (!path.isEmpty()) exportTable(path);
    });
}

void ProbeSavePage::initializePage() {
    core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    proc.next();  // Accepted → Upload
    const bool verified = proc.upload().phase() == core::TableUploadProcedure::Phase::Verified;
    m_progress->setValue(m_ctx.session->saved && verified ? 100 : 0);
    DeviceCalibrationProbe* p = m_ctx.probe();
    m_upload->setEnabled(m_ctx.session->saved.has_value() && p && p->canUpload() && !verified);
    m_save->setEnabled(!m_ctx.session->saved.has_value());
    retranslate();
}

void ProbeSavePage::cleanupPage() {
    m_timer->stop();
    m_ctx.procedure().back();  // Upload → Accepted (not while an upload runs)
}

bool ProbeSavePage::isComplete() const {
    const core::TableUploadProcedure& upload = m_ctx.procedure().upload();
    if (!m_ctx.session->saved || upload.running()) return false;
    DeviceCalibrationProbe* p = m_ctx.probe();
    return upload.phase() == core::TableUploadProcedure::Phase::Verified || !p || !p->canUpload();
}

void ProbeSavePage::showResult(const QString& text, bool problem) {
    m_result->setText(text);
    m_result->setStyleSheet(problem ? QStringLiteral("color: #b71c1c; font-weight: bold;")
                                    : QStringLiteral("color: #1b5e20; font-weight: bold;"));
}

bool ProbeSavePage::save() {
    const core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    if (!proc.accepted() || m_ctx.session->saved) return m_ctx.session->saved.has_value();
    if (!m_ctx.store) {
        showResult(tr("The calibration database is not open; export the table instead."), true);
        return false;
    }
    const QString who = m_ctx.operatorName();
    if (who.isEmpty()) {
        if (m_ctx.app && m_ctx.app->prompt)
            m_ctx.app->prompt->warn(this, tr("Save the table"),
                                    tr("Enter your name on the Settings page first: the table is saved with it."));
        showResult(tr("Not saved: no operator name (Settings)."), true);
        return false;
    }
    const core::Linearisation& lin = *proc.fitOutcome().linearisation;
    DeviceCalibrationProbe* p = m_ctx.probe();
    storage::ProbeTableRecord r;
    r.probe = p ? p->name() : tr("(typed points)");
    r.plane = proc.config().plane;
    r.createdBy = who;
    r.adcBits = lin.fit.adcBits;
    r.degree = lin.fit.degree;
    QStringList coefficients;
    for (Eigen::Index i = 0; i < lin.fit.coefficients.size(); ++i)
        coefficients << QString::number(lin.fit.coefficients(i), 'g', 17);
    r.coefficients = coefficients.join(QLatin1Char(' '));
    r.rmsResidualUm = lin.fit.rmsResidualUm;
    r.maxTableErrorUm = lin.maxTableErrorUm;
    std::vector<core::CalibrationPoint> used;  // the points the table was fitted to
    for (const core::ProbePoint& point : proc.points())
        if (!point.saturated) used.push_back({point.referenceUm, point.adcCode, 0});
    r.pointsCsv = QString::fromStdString(core::calibrationCsv(used));
    try {
        core::TableImageInfo info;
        info.version = static_cast<std::uint16_t>(m_ctx.store->nextTableVersion(r.probe, r.plane));
        info.createdUnixS = QDateTime::currentSecsSinceEpoch();
        info.plane = static_cast<std::uint8_t>(r.plane);
        info.degree = static_cast<std::uint8_t>(lin.fit.degree);
        const std::vector<std::uint8_t> image =
            core::encodeTableImage(lin.table, info, p ? p->imageFormat() : core::kTableImageFormat);
        r.image = QByteArray(reinterpret_cast<const char*>(image.data()), static_cast<qsizetype>(image.size()));
        r.imageCrc = core::tableImageCrc(image);
        r.uploadCrc = core::tableUploadCrc(image);
        m_ctx.session->saved = m_ctx.store->saveTable(r);
    } catch (const std::exception& e) {
        showResult(tr("Not saved: %1").arg(QString::fromStdString(e.what())), true);
        return false;
    }
    const storage::ProbeTableRecord& s = *m_ctx.session->saved;
    m_saved->setText(tr("Saved as version %1 of %2 by %3 at %4.")
                         .arg(s.version)
                         .arg(s.probe, s.createdBy,
                              QDateTime::fromString(s.createdAt, Qt::ISODateWithMs)
                                  .toLocalTime()
                                  .toString(QStringLiteral("yyyy-MM-dd HH:mm"))));
    showResult(p && p->canUpload() ? tr("Now upload it to the mandrel.") : QString(), false);
    m_save->setEnabled(false);
    m_upload->setEnabled(p && p->canUpload());
    emit completeChanged();
    return true;
}

bool ProbeSavePage::upload() {
    DeviceCalibrationProbe* p = m_ctx.probe();
    core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    if (!p || !m_ctx.session->saved || proc.upload().running() ||
        proc.step() != core::ProbeLinearisationProcedure::Step::Upload)
        return false;
    const storage::ProbeTableRecord& s = *m_ctx.session->saved;
    proc.startUpload(*p, std::vector<std::uint8_t>(s.image.begin(), s.image.end()),
                     static_cast<std::uint16_t>(s.version));
    proc.takeEvents();
    if (!proc.upload().running()) {  // refused at once
        showResult(ProcedureWords::uploadOutcome(proc.upload()), true);
        return false;
    }
    m_upload->setEnabled(false);
    showResult(ProcedureWords::uploadOutcome(proc.upload()), false);
    m_timer->start();
    emit completeChanged();
    return true;
}

void ProbeSavePage::pollUpload(double elapsedS) {
    DeviceCalibrationProbe* p = m_ctx.probe();
    core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    if (!p || !proc.upload().running()) return;
    proc.pumpUpload(*p, elapsedS);
    const core::TableUploadProcedure& upload = proc.upload();
    m_progress->setValue(static_cast<int>(std::lround(100.0 * upload.progress())));
    if (upload.running()) {
        m_result->setText(ProcedureWords::uploadOutcome(upload));
        return;
    }
    m_timer->stop();
    proc.takeEvents();
    const bool verified = upload.phase() == core::TableUploadProcedure::Phase::Verified;
    const storage::ProbeTableRecord& s = *m_ctx.session->saved;
    const bool refused = upload.problem() == core::TableUploadProcedure::Problem::Refused ||
                         upload.problem() == core::TableUploadProcedure::Problem::Aborted;
    if (m_ctx.store && !refused)  // what the mandrel holds now is on record
        m_ctx.store->recordUpload(s.id, m_ctx.operatorName(),
                                  upload.readback() ? std::optional<qint64>(upload.readback()->crc()) : std::nullopt,
                                  verified);
    showResult(ProcedureWords::uploadOutcome(upload), !verified);
    m_upload->setEnabled(!verified);
    emit completeChanged();
}

bool ProbeSavePage::exportTable(const QString& path) {
    const core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
    if (!proc.fitOutcome().usable()) return false;
    const core::Linearisation& lin = *proc.fitOutcome().linearisation;
    core::TableImageInfo info;
    info.version = static_cast<std::uint16_t>(m_ctx.session->saved ? m_ctx.session->saved->version : 1);
    info.createdUnixS = QDateTime::currentSecsSinceEpoch();
    info.plane = static_cast<std::uint8_t>(proc.config().plane);
    info.degree = static_cast<std::uint8_t>(lin.fit.degree);
    const QString suffix = QFileInfo(path).suffix().toLower();
    QByteArray bytes;
    if (suffix == QStringLiteral("csv")) {
        bytes = QByteArray::fromStdString(core::tableToCsv(lin.table));
    } else if (suffix == QStringLiteral("bin")) {
        const std::vector<std::uint8_t> image = core::encodeTableImage(lin.table, info);
        bytes = QByteArray(reinterpret_cast<const char*>(image.data()), static_cast<qsizetype>(image.size()));
    } else {
        bytes = QByteArray::fromStdString(core::tableToCHeader(lin.table, info));
    }
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size() || !file.flush()) {
        showResult(tr("Cannot write %1: %2").arg(path, file.errorString()), true);
        return false;
    }
    showResult(tr("Exported to %1.").arg(QFileInfo(path).fileName()), false);
    return true;
}

void ProbeSavePage::retranslate() {
    setTitle(tr("Save and upload"));
    setSubTitle(tr("The table is saved as a new version with your name, then sent to the mandrel and read back."));
    DeviceCalibrationProbe* p = m_ctx.probe();
    m_intro->setText(p && p->canUpload()
                         ? tr("Save the table, then upload it to %1. Finish is possible once the mandrel reports the "
                              "same version and CRC as the image sent.")
                               .arg(p->name())
                         : tr("This probe takes no uploads here: save the table and export it for the "
                              "microcontroller (C header or binary image)."));
    m_save->setText(tr("Save table"));
    m_upload->setText(tr("Upload to the mandrel"));
    m_export->setText(tr("Export…"));
}

// --- The wizard -------------------------------------------------------------------------------

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
