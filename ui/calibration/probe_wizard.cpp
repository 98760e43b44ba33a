#include "ui/calibration/probe_wizard.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>

#include "core/calibration/calibration_csv.h"
#include "core/calibration/linearisation_image.h"
#include "core/storage/calibration_store.h"
#include "ui/app_state.h"
#include "ui/calibration/probe_capture_page.h"
#include "ui/calibration/probe_fit_page.h"
#include "ui/prompt.h"

namespace tt::ui {

CalibrationProbe* ProbeWizardContext::probe() const {
    if (probes.empty()) return nullptr;
    const std::size_t i =
        static_cast<std::size_t>(std::clamp(session->probeIndex, 0, static_cast<int>(probes.size()) - 1));
    return probes[i];
}

QString ProbeWizardContext::operatorName() const {
    return app && app->state ? app->state->operatorName().trimmed() : QString();
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
        store();
        if (CalibrationProbe* p = m_ctx.probe(); p && p->adcBits()) m_bits->setValue(*p->adcBits());
        initializePage();
    });
    connect(m_plane, &QComboBox::currentIndexChanged, this, [this] { store(); });
    connect(m_bits, &QSpinBox::valueChanged, this, [this] { store(); });
}

void ProbeChoosePage::store() {
    m_ctx.session->probeIndex = std::max(0, m_probe->currentIndex());
    m_ctx.session->plane = m_plane->currentData().toInt();
    m_ctx.session->adcBits = m_bits->value();
}

void ProbeChoosePage::initializePage() {
    const QSignalBlocker a(m_probe), b(m_plane), c(m_bits);
    m_probe->clear();
    for (CalibrationProbe* p : m_ctx.probes)
        m_probe->addItem(p->name());
    m_probe->setCurrentIndex(std::clamp(m_ctx.session->probeIndex, 0, std::max(0, m_probe->count() - 1)));
    m_plane->setCurrentIndex(m_ctx.session->plane);
    m_bits->setValue(m_ctx.session->adcBits);
    CalibrationProbe* p = m_ctx.probe();
    m_bits->setEnabled(!p || !p->adcBits());
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
    m_resolution->setValue(m_ctx.session->resolutionUm);
}

bool ProbeReferencePage::validatePage() {
    m_ctx.session->referenceKind = m_kind->currentIndex();
    m_ctx.session->resolutionUm = m_resolution->value();
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

// --- 5. Accept --------------------------------------------------------------------------------

ProbeAcceptPage::ProbeAcceptPage(ProbeWizardContext& context, QWidget* parent)
    : CalibrationWizardPage(parent), m_ctx(context), m_summary(wrappedLabel(this)), m_accept(new QCheckBox(this)) {
    m_accept->setObjectName(QStringLiteral("acceptCheck"));
    m_accept->setStyleSheet(
        QStringLiteral("QCheckBox { font-weight: bold; } QCheckBox::indicator { width: 28px; height: 28px; }"));
    m_summary->setObjectName(QStringLiteral("acceptSummary"));
    m_summary->setTextFormat(Qt::RichText);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addStretch(1);
    layout->addWidget(m_accept);
    connect(m_accept, &QCheckBox::toggled, this, [this](bool on) {
        m_ctx.session->accepted = on;
        emit completeChanged();
    });
}

void ProbeAcceptPage::initializePage() {
    m_accept->setChecked(m_ctx.session->accepted);
    if (!m_ctx.result) return;
    const core::Linearisation& lin = *m_ctx.result;
    CalibrationProbe* p = m_ctx.probe();
    const QString probe = p ? p->name() : tr("(typed points)");
    const int version = m_ctx.store ? m_ctx.store->nextTableVersion(probe, m_ctx.session->plane) : 1;
    QString warnings;
    for (const std::string& w : lin.warnings)
        warnings += QStringLiteral("<br><b>%1</b>").arg(QString::fromStdString(w).toHtmlEscaped());
    m_summary->setText(
        tr("<p>Characteristic of degree %1 from %2 points, residual RMS %3 µm.</p>"
           "<p>Table: %4 entries of %5 nm, worst error at the calibration points %6 µm, step between codes up "
           "to %7 µm; %8 entries outside the calibrated range %9 .. %10 µm are extrapolated.%11</p>"
           "<p>It will be saved as version <b>%12</b> of %13, plane %14, by <b>%15</b>.</p>")
            .arg(lin.fit.degree)
            .arg(m_ctx.session->points.size())
            .arg(lin.fit.rmsResidualUm, 0, 'f', 2)
            .arg(lin.table.entries.size())
            .arg(lin.table.scaleNm)
            .arg(lin.maxTableErrorUm, 0, 'f', 2)
            .arg(lin.tableResolutionUm, 0, 'f', 2)
            .arg(lin.extrapolatedEntries)
            .arg(lin.fit.calibratedMinUm, 0, 'f', 0)
            .arg(lin.fit.calibratedMaxUm, 0, 'f', 0)
            .arg(warnings)
            .arg(version)
            .arg(probe.toHtmlEscaped())
            .arg(m_ctx.session->plane == 0 ? QStringLiteral("X") : QStringLiteral("Y"))
            .arg(m_ctx.operatorName().isEmpty() ? tr("(no operator name — set it in Settings)")
                                                : m_ctx.operatorName().toHtmlEscaped()));
}

bool ProbeAcceptPage::isComplete() const {
    return m_ctx.result.has_value() && m_accept->isChecked();
}

void ProbeAcceptPage::retranslate() {
    setTitle(tr("Accept the table"));
    setSubTitle(tr("Check the figures; the table is stored only when you accept it."));
    m_accept->setText(tr("I accept this linearisation table"));
    initializePage();
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
    m_saved->setObjectName(QStringLiteral("savedVersion"));
    m_saved->setStyleSheet(QStringLiteral("font-weight: bold;"));
    m_progress->setRange(0, 100);
    m_progress->setMinimumHeight(36);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_save);
    buttons->addWidget(m_upload);
    buttons->addWidget(m_export);
    buttons->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_intro);
    layout->addLayout(buttons);
    layout->addWidget(m_saved);
    layout->addWidget(m_progress);
    layout->addWidget(m_result);
    layout->addStretch(1);
    m_timer->setInterval(50);
    connect(m_timer, &QTimer::timeout, this, &ProbeSavePage::pollUpload);
    connect(m_save, &QPushButton::clicked, this, &ProbeSavePage::save);
    connect(m_upload, &QPushButton::clicked, this, &ProbeSavePage::upload);
    connect(m_export, &QPushButton::clicked, this, [this] {
        if (!m_ctx.app || !m_ctx.app->prompt || !m_ctx.result) return;
        const QString path =
            m_ctx.app->prompt->saveFileName(this, tr("Export the table"), QStringLiteral("linearisation.h"),
                                            tr("C header (*.h);;Binary image (*.bin);;CSV (*.csv)"));
        if (!path.isEmpty()) exportTable(path);
    });
}

void ProbeSavePage::initializePage() {
    m_progress->setValue(m_ctx.session->saved && m_ctx.session->uploadVerified ? 100 : 0);
    CalibrationProbe* p = m_ctx.probe();
    m_upload->setEnabled(m_ctx.session->saved.has_value() && p && p->canUpload());
    m_save->setEnabled(!m_ctx.session->saved.has_value());
    retranslate();
}

bool ProbeSavePage::isComplete() const {
    if (!m_ctx.session->saved || m_uploading) return false;
    CalibrationProbe* p = m_ctx.probe();
    return m_ctx.session->uploadVerified || !p || !p->canUpload();
}

void ProbeSavePage::showResult(const QString& text, bool problem) {
    m_result->setText(text);
    m_result->setStyleSheet(problem ? QStringLiteral("color: #b71c1c; font-weight: bold;")
                                    : QStringLiteral("color: #1b5e20; font-weight: bold;"));
}

bool ProbeSavePage::save() {
    if (!m_ctx.result || m_ctx.session->saved) return m_ctx.session->saved.has_value();
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
    const core::Linearisation& lin = *m_ctx.result;
    CalibrationProbe* p = m_ctx.probe();
    storage::ProbeTableRecord r;
    r.probe = p ? p->name() : tr("(typed points)");
    r.plane = m_ctx.session->plane;
    r.createdBy = who;
    r.adcBits = lin.fit.adcBits;
    r.degree = lin.fit.degree;
    QStringList coefficients;
    for (Eigen::Index i = 0; i < lin.fit.coefficients.size(); ++i)
        coefficients << QString::number(lin.fit.coefficients(i), 'g', 17);
    r.coefficients = coefficients.join(QLatin1Char(' '));
    r.rmsResidualUm = lin.fit.rmsResidualUm;
    r.maxTableErrorUm = lin.maxTableErrorUm;
    r.pointsCsv = QString::fromStdString(core::calibrationCsv(m_ctx.session->calibrationPoints()));
    try {
        core::TableImageInfo info;
        info.version = static_cast<std::uint16_t>(m_ctx.store->nextTableVersion(r.probe, r.plane));
        info.createdUnixS = QDateTime::currentSecsSinceEpoch();
        info.plane = static_cast<std::uint8_t>(r.plane);
        info.degree = static_cast<std::uint8_t>(lin.fit.degree);
        m_image = core::encodeTableImage(lin.table, info, p ? p->imageFormat() : core::kTableImageFormat);
        r.image = QByteArray(reinterpret_cast<const char*>(m_image.data()), static_cast<qsizetype>(m_image.size()));
        r.imageCrc = core::tableImageCrc(m_image);
        r.uploadCrc = core::tableUploadCrc(m_image);
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
    CalibrationProbe* p = m_ctx.probe();
    if (!p || !m_ctx.session->saved || m_uploading) return false;
    const storage::ProbeTableRecord& s = *m_ctx.session->saved;
    const QByteArray& bytes = s.image;
    m_image.assign(bytes.begin(), bytes.end());
    try {
        p->startUpload(m_image, static_cast<std::uint16_t>(s.version), static_cast<std::uint32_t>(s.uploadCrc));
    } catch (const std::exception& e) {
        showResult(tr("Upload refused: %1").arg(QString::fromStdString(e.what())), true);
        return false;
    }
    m_uploading = true;
    m_ctx.session->uploadVerified = false;
    m_upload->setEnabled(false);
    showResult(tr("Uploading…"), false);
    m_timer->start();
    emit completeChanged();
    return true;
}

void ProbeSavePage::pollUpload() {
    CalibrationProbe* p = m_ctx.probe();
    if (!p || !m_uploading) return;
    p->poll(m_timer->interval() / 1000.0);
    const ProbeUploadStatus status = p->uploadStatus();
    m_progress->setValue(static_cast<int>(std::lround(100.0 * status.progress)));
    if (status.phase == ProbeUploadStatus::Phase::Running) {
        m_result->setText(status.message);
        return;
    }
    if (status.phase == ProbeUploadStatus::Phase::Idle) return;
    m_timer->stop();
    m_uploading = false;
    const storage::ProbeTableRecord& s = *m_ctx.session->saved;
    if (status.phase == ProbeUploadStatus::Phase::Failed) {
        showResult(tr("Upload failed: %1. The saved table is kept; try again.").arg(status.message), true);
        m_upload->setEnabled(true);
        emit completeChanged();
        return;
    }
    p->requestReadback();
    const std::optional<ProbeTableReadback> back = p->readback();
    const bool verified = back && back->matches(s.version, m_image);
    m_ctx.session->uploadVerified = verified;
    if (m_ctx.store)
        m_ctx.store->recordUpload(s.id, m_ctx.operatorName(), back ? std::optional<qint64>(back->crc()) : std::nullopt,
                                  verified);
    if (verified)
        showResult(tr("Verified: the mandrel reports version %1, %2, the same as the image sent.")
                       .arg(back->version)
                       .arg(back->crcText()),
                   false);
    else
        showResult(back ? tr("Read-back does not match: the mandrel reports version %1, %2; the image has version "
                             "%3, CRC-32C %4. Upload again.")
                              .arg(back->version)
                              .arg(back->crcText())
                              .arg(s.version)
                              .arg(QString::fromStdString(core::crcText(static_cast<std::uint32_t>(s.uploadCrc))))
                        : tr("The mandrel did not report its table; upload again."),
                   true);
    m_upload->setEnabled(!verified);
    emit completeChanged();
}

bool ProbeSavePage::exportTable(const QString& path) {
    if (!m_ctx.result) return false;
    core::TableImageInfo info;
    info.version = static_cast<std::uint16_t>(m_ctx.session->saved ? m_ctx.session->saved->version : 1);
    info.createdUnixS = QDateTime::currentSecsSinceEpoch();
    info.plane = static_cast<std::uint8_t>(m_ctx.session->plane);
    info.degree = static_cast<std::uint8_t>(m_ctx.result->fit.degree);
    const QString suffix = QFileInfo(path).suffix().toLower();
    QByteArray bytes;
    if (suffix == QStringLiteral("csv")) {
        bytes = QByteArray::fromStdString(core::tableToCsv(m_ctx.result->table));
    } else if (suffix == QStringLiteral("bin")) {
        const std::vector<std::uint8_t> image = core::encodeTableImage(m_ctx.result->table, info);
        bytes = QByteArray(reinterpret_cast<const char*>(image.data()), static_cast<qsizetype>(image.size()));
    } else {
        bytes = QByteArray::fromStdString(core::tableToCHeader(m_ctx.result->table, info));
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
    CalibrationProbe* p = m_ctx.probe();
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
                                               std::vector<CalibrationProbe*> probes, storage::CalibrationStore* store,
                                               QWidget* parent)
    : CalibrationWizard(QStringLiteral("probeWizard"), parent),
      m_ctx{&app, &session, std::move(probes), store, std::nullopt} {
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
