#include "ui/calibration/probe_save_page.h"

#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include "core/calibration/calibration_csv.h"
#include "core/calibration/linearisation_image.h"
#include "core/storage/calibration_store.h"
#include "ui/calibration/probe_wizard_context.h"
#include "ui/calibration/procedure_words.h"
#include "ui/prompt.h"

namespace tt::ui {

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
    storage::ProbeTableRecord r = tableRecord(who);
    try {
        attachImage(r);
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
    DeviceCalibrationProbe* p = m_ctx.probe();
    showResult(p && p->canUpload() ? tr("Now upload it to the mandrel.") : QString(), false);
    m_save->setEnabled(false);
    m_upload->setEnabled(p && p->canUpload());
    emit completeChanged();
    return true;
}

storage::ProbeTableRecord ProbeSavePage::tableRecord(const QString& who) const {
    const core::ProbeLinearisationProcedure& proc = m_ctx.procedure();
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
    return r;
}

void ProbeSavePage::attachImage(storage::ProbeTableRecord& r) const {
    const core::Linearisation& lin = *m_ctx.procedure().fitOutcome().linearisation;
    DeviceCalibrationProbe* p = m_ctx.probe();
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

}  // namespace tt::ui
