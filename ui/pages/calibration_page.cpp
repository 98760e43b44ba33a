#include "ui/pages/calibration_page.h"

#include <QDateTime>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QStackedWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include "core/calibration/linearisation_image.h"
#include "core/storage/calibration_store.h"
#include "core/storage/tool_store.h"
#include "runtime/devices/device_hub.h"
#include "ui/calibration/device_calibration_probe.h"
#include "ui/calibration/device_kp_drive.h"
#include "ui/calibration/kp_wizard.h"
#include "ui/calibration/probe_wizard.h"
#include "ui/pages/planned_page.h"
#include "ui/prompt.h"

namespace tt::ui {

namespace {

QTableWidget* listView(QWidget* parent, const char* name, int columns) {
    auto* t = new QTableWidget(0, columns, parent);
    t->setObjectName(QLatin1String(name));
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setSelectionBehavior(QAbstractItemView::SelectRows);
    t->verticalHeader()->setVisible(false);
    t->verticalHeader()->setDefaultSectionSize(40);
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->horizontalHeader()->setStretchLastSection(true);
    return t;
}

QString localTime(const QString& iso) {
    const QDateTime t = QDateTime::fromString(iso, Qt::ISODateWithMs);
    return t.isValid() ? t.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm")) : iso;
}

/// A stored CRC: 4 hex digits for a CRC-16 (protocol-1 mandrels), 8 for a CRC-32C.
QString crcText(qint64 v) {
    return QString::fromStdString(core::crcText(static_cast<std::uint32_t>(v), v <= 0xFFFF ? 16 : 32));
}

}  // namespace

CalibrationPage::CalibrationPage(AppContext& context, QWidget* parent)
    : Page(PageId::Calibration, context, parent),
      m_stack(new QStackedWidget(this)),
      m_overview(new QWidget(this)),
      m_probeTitle(new QLabel(m_overview)),
      m_probeText(new QLabel(m_overview)),
      m_probeStart(new QPushButton(m_overview)),
      m_probeStartOver(new QPushButton(m_overview)),
      m_tables(listView(m_overview, "probeTables", 8)),
      m_kpTitle(new QLabel(m_overview)),
      m_kpText(new QLabel(m_overview)),
      m_kpStart(new QPushButton(m_overview)),
      m_kpList(listView(m_overview, "kpCalibrations", 6)),
      m_storeProblem(new QLabel(m_overview)),
      m_deviceNotice(new QLabel(m_overview)) {
    buildOverview();
    m_stack->addWidget(m_overview);
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(24, 16, 24, 16);
    outer->addWidget(m_stack);

    connect(m_probeStart, &QPushButton::clicked, this, &CalibrationPage::startProbeCalibration);
    connect(m_probeStartOver, &QPushButton::clicked, this, &CalibrationPage::startOver);
    connect(m_kpStart, &QPushButton::clicked, this, &CalibrationPage::startKpCalibration);
    openStores();
    watchDevices();
    adoptDevices();
    retranslate();
}

void CalibrationPage::buildOverview() {
    m_probeTitle->setObjectName(QStringLiteral("SectionTitle"));
    m_kpTitle->setObjectName(QStringLiteral("SectionTitle"));
    m_probeStart->setObjectName(QStringLiteral("startProbeWizard"));
    m_probeStart->setProperty("role", QStringLiteral("primary"));
    m_probeStartOver->setObjectName(QStringLiteral("probeStartOver"));
    m_kpStart->setObjectName(QStringLiteral("startKpWizard"));
    m_kpStart->setProperty("role", QStringLiteral("primary"));
    m_storeProblem->setObjectName(QStringLiteral("calibrationStoreProblem"));
    m_storeProblem->setStyleSheet(QStringLiteral("color: #b71c1c; font-weight: bold;"));
    m_storeProblem->setWordWrap(true);
    m_deviceNotice->setObjectName(QStringLiteral("calibrationDeviceNotice"));
    m_deviceNotice->setStyleSheet(QStringLiteral("color: #9a5b00; font-weight: bold;"));
    m_deviceNotice->setWordWrap(true);
    m_deviceNotice->hide();
    for (QLabel* l : {m_probeText, m_kpText})
        l->setWordWrap(true);

    auto* probeButtons = new QHBoxLayout;
    probeButtons->addWidget(m_probeStart);
    probeButtons->addWidget(m_probeStartOver);
    probeButtons->addStretch(1);
    auto* kpButtons = new QHBoxLayout;
    kpButtons->addWidget(m_kpStart);
    kpButtons->addStretch(1);
    auto* layout = new QVBoxLayout(m_overview);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_storeProblem);
    layout->addWidget(m_deviceNotice);
    layout->addWidget(m_probeTitle);
    layout->addWidget(m_probeText);
    layout->addLayout(probeButtons);
    layout->addWidget(m_tables, 3);
    layout->addSpacing(12);
    layout->addWidget(m_kpTitle);
    layout->addWidget(m_kpText);
    layout->addLayout(kpButtons);
    layout->addWidget(m_kpList, 2);
}

CalibrationPage::~CalibrationPage() {
    // The wizards refer to the stores and the probes: destroy them first.
    delete m_probeWizard;
    delete m_kpWizard;
    releaseJacks();
}

QString CalibrationPage::title() const {
    return pageTitle(PageId::Calibration);
}

void CalibrationPage::showEvent(QShowEvent* event) {
    Page::showEvent(event);
    if (context().devices != m_devices) {
        watchDevices();
        adoptDevices();
    }
}

void CalibrationPage::watchDevices() {
    if (m_devices) disconnect(m_devices, nullptr, this, nullptr);
    m_devices = context().devices;
    if (m_devices) connect(m_devices, &runtime::DeviceHub::devicesChanged, this, &CalibrationPage::adoptDevices);
}

void CalibrationPage::adoptDevices() {
    // Only the probes and drives matter: a changed gauge or CNC output leaves the wizards alone.
    QList<QPair<QString, quintptr>> now;  // id and instance of every probe and drive
    if (m_devices)
        for (devices::DeviceKind kind : {devices::DeviceKind::Probe, devices::DeviceKind::DriveCurrent})
            for (const QString& id : m_devices->devicesOfKind(kind))
                now.append({id, m_devices->view(id)->instance});
    if (now == m_adopted) return;
    const bool wizardOpen = !overviewShown();
    releaseJacks();
    closeWizards();  // the wizards refer to the adapters: drop them first
    m_deviceProbes.clear();
    m_deviceDrives.clear();
    m_adopted = now;
    for (const auto& adopted : now) {
        const QString& id = adopted.first;
        const runtime::DeviceView* e = m_devices->view(id);
        if (!e) continue;
        if (e->kind == devices::DeviceKind::Probe)
            m_deviceProbes.push_back(std::make_unique<DeviceCalibrationProbe>(*m_devices, id, e->name));
        else if (e->kind == devices::DeviceKind::DriveCurrent)
            m_deviceDrives.push_back(std::make_unique<DeviceKpDrive>(*m_devices, id, e->name));
    }
    if (wizardOpen) {
        showOverview();
        m_deviceNotice->setText(
            tr("The devices changed while a calibration was open, so it was closed; the captured "
               "points are kept. Open it again to continue."));
        m_deviceNotice->show();
    }
}

void CalibrationPage::closeWizards() {
    delete m_probeWizard;  // rebuilt with the new lists on the next start
    m_probeWizard = nullptr;
    delete m_kpWizard;
    m_kpWizard = nullptr;
}

QString CalibrationPage::deviceNotice() const {
    return m_deviceNotice->isHidden() ? QString() : m_deviceNotice->text();
}

void CalibrationPage::openStores() {
    m_calibrations = context().data().calibration();
    m_tools = context().data().tools();
    if (!m_calibrations || !m_tools) m_storeError = context().data().problem();
}

std::vector<DeviceCalibrationProbe*> CalibrationPage::offeredProbes() const {
    std::vector<DeviceCalibrationProbe*> out;
    for (const auto& p : m_deviceProbes)
        out.push_back(p.get());
    return out;
}

std::vector<DeviceKpDrive*> CalibrationPage::offeredDrives() const {
    std::vector<DeviceKpDrive*> out;
    for (const auto& d : m_deviceDrives)
        out.push_back(d.get());
    return out;
}

bool CalibrationPage::overviewShown() const {
    return m_stack->currentWidget() == m_overview;
}

void CalibrationPage::releaseJacks() {
    // Only of the devices still there: a removed one took its stand with it.
    const QStringList present = m_devices ? m_devices->deviceIds() : QStringList();
    for (const auto& p : m_deviceProbes)
        if (present.contains(p->deviceId())) p->releaseJack();
    for (const auto& d : m_deviceDrives)
        if (present.contains(d->deviceId())) d->releaseJack();
}

void CalibrationPage::showOverview() {
    releaseJacks();  // the devices follow their simulation inputs again
    m_stack->setCurrentWidget(m_overview);
    refreshLists();
    retranslate();
}

void CalibrationPage::startProbeCalibration() {
    m_deviceNotice->hide();
    if (!m_probeWizard) {
        m_probeWizard = new ProbeCalibrationWizard(context(), m_probeSession, offeredProbes(), m_calibrations, this);
        m_probeWizard->setWindowFlags(Qt::Widget);  // a page of the main window, not a dialog
        m_stack->addWidget(m_probeWizard);
        connect(m_probeWizard, &QWizard::accepted, this, [this] {
            m_probeSession.clear();  // saved and done
            showOverview();
        });
        connect(m_probeWizard, &QWizard::rejected, this, [this] { showOverview(); });  // points kept
    }
    m_probeWizard->restart();
    m_stack->setCurrentWidget(m_probeWizard);
    m_probeWizard->show();
}

void CalibrationPage::startKpCalibration() {
    m_deviceNotice->hide();
    if (!m_kpWizard) {
        m_kpWizard = new KpCalibrationWizard(context(), m_kpSession, offeredDrives(), m_calibrations, m_tools, this);
        m_kpWizard->setWindowFlags(Qt::Widget);
        m_stack->addWidget(m_kpWizard);
        connect(m_kpWizard, &QWizard::accepted, this, [this] {
            m_kpSession.clear();
            showOverview();
        });
        connect(m_kpWizard, &QWizard::rejected, this, [this] { showOverview(); });
    }
    m_kpWizard->restart();
    m_stack->setCurrentWidget(m_kpWizard);
    m_kpWizard->show();
}

void CalibrationPage::startOver() {
    if (m_probeSession.procedure.points().empty()) return;
    if (context().prompt &&
        context().prompt->ask(this, tr("Start over"),
                              tr("Forget the %1 captured points of the unfinished calibration?")
                                  .arg(m_probeSession.procedure.points().size())) != Prompt::Answer::Yes)
        return;
    m_probeSession.clear();
    retranslate();
}

void CalibrationPage::refreshLists() {
    m_tables->setRowCount(0);
    m_kpList->setRowCount(0);
    if (!m_calibrations) return;
    const std::vector<storage::ProbeTableRecord> tables = m_calibrations->tables();
    m_tables->setRowCount(static_cast<int>(tables.size()));
    for (std::size_t i = 0; i < tables.size(); ++i) {
        const storage::ProbeTableRecord& t = tables[i];
        const QString upload = !t.readbackCrc ? tr("not uploaded")
                               : t.verified   ? tr("verified, CRC %1").arg(crcText(*t.readbackCrc))
                                              : tr("read-back CRC %1 does not match").arg(crcText(*t.readbackCrc));
        const QStringList cells = {t.probe,
                                   t.plane == 0 ? QStringLiteral("X") : QStringLiteral("Y"),
                                   QString::number(t.version),
                                   localTime(t.createdAt),
                                   t.createdBy,
                                   QString::number(t.degree),
                                   QString::number(t.maxTableErrorUm, 'f', 2),
                                   upload};
        for (int c = 0; c < cells.size(); ++c)
            m_tables->setItem(static_cast<int>(i), c, new QTableWidgetItem(cells[c]));
    }
    const std::vector<storage::KpCalibrationRecord> kps = m_calibrations->kpCalibrations();
    m_kpList->setRowCount(static_cast<int>(kps.size()));
    for (std::size_t i = 0; i < kps.size(); ++i) {
        const storage::KpCalibrationRecord& k = kps[i];
        const QStringList cells = {localTime(k.createdAt),
                                   k.createdBy,
                                   k.drive,
                                   QString::number(k.kpNPerA, 'f', 2),
                                   QString::number(k.r2, 'f', 5),
                                   k.appliedTo.isEmpty() ? QStringLiteral("—") : k.appliedTo};
        for (int c = 0; c < cells.size(); ++c)
            m_kpList->setItem(static_cast<int>(i), c, new QTableWidgetItem(cells[c]));
    }
}

void CalibrationPage::retranslate() {
    m_probeTitle->setText(tr("Probe mandrel linearisation"));
    m_probeText->setText(
        tr("Builds the table ADC code → deflection that the mandrel's microcontroller uses: "
           "capture points against a dial indicator, fit the sensor's characteristic, save a new "
           "table version and upload it with read-back of its CRC."));
    const std::size_t kept = m_probeSession.procedure.points().size();
    m_probeStart->setText(kept > 0 ? tr("Continue the calibration (%1 points kept)…").arg(kept)
                                   : tr("Linearise a probe mandrel…"));
    m_probeStartOver->setText(tr("Start over"));
    m_probeStartOver->setVisible(kept > 0);
    m_tables->setHorizontalHeaderLabels({tr("Probe"), tr("Plane"), tr("Version"), tr("Saved"), tr("By"), tr("Degree"),
                                         tr("Table error, µm"), tr("In the mandrel")});
    m_kpTitle->setText(tr("Current-to-force gain k_p"));
    m_kpText->setText(
        tr("Known loads on the cross slide against the motor current difference with dither; the "
           "result is written into the tool table."));
    m_kpStart->setText(tr("Calibrate k_p from known loads…"));
    m_kpList->setHorizontalHeaderLabels({tr("When"), tr("By"), tr("Drive"), tr("k_p, N/A"), tr("R²"), tr("Tools")});
    m_storeProblem->setVisible(!m_storeError.isEmpty());
    m_storeProblem->setText(tr("The calibration database cannot be opened: %1. Tables can still be built and "
                               "exported, not saved.")
                                .arg(m_storeError));
    if (m_probeWizard) m_probeWizard->retranslate();
    if (m_kpWizard) m_kpWizard->retranslate();
    refreshLists();
}

}  // namespace tt::ui
