#include "runtime/devices/device_host.h"

#include <algorithm>
#include <stdexcept>

#include "devices/api/simulated_instrument.h"
#include "runtime/devices/boring_link.h"
#include "runtime/devices/calibration_link.h"
#include "runtime/devices/lathe_link.h"
#include "runtime/log_categories.h"
#include "runtime/thread_priority.h"

namespace tt::runtime {

namespace {

/// How often the calibration wizards' instruments are pumped while a wizard reads one, ms.
constexpr int kCalibrationPumpMs = 10;

/// Passes what a source port took (null: the device is gone) into its relay, with its health.
template <class Port, class Relay>
void pass(Port* port, Relay& relay) {
    if (port)
        while (const auto sample = port->takeSample())
            relay.deliver(*sample);
    relay.publishHealth(port ? port->health() : core::DeviceHealth{core::DeviceState::Disconnected, {}});
}

/// What a simulated instrument or a probe mandrel can do, into the snapshot.
void addCapabilities(DeviceView& v, devices::Device& device) {
    if (devices::SimulatedInstrument* sim = devices::simulatedInstrument(device)) {
        v.faults = sim->faultSwitches();
        v.runsBoringPass = sim->boringTruth() != nullptr;
        if (devices::CalibrationStand* stand = sim->calibrationStand()) {
            v.standBendsBar = stand->bendsBar();
            v.standAppliesLoad = stand->appliesLoad();
        }
    }
    if (const devices::TableUploadTarget* target = device.tableUploadTarget()) {
        v.uploadsTable = true;
        v.mandrel = target->mandrelInfo();
        v.table = target->tableInfo();
        v.upload = target->uploadStatus();
    }
}

}  // namespace

DeviceHost::DeviceHost(const core::Clock* clock) : m_manager(std::make_unique<devices::DeviceManager>(clock)) {
    preferThisThread();  // the pumps of the runs' devices: a busy terminal delays none of them
    m_flush.setSingleShot(true);
    m_flush.setInterval(kViewFlushMs);
    connect(&m_flush, &QTimer::timeout, this, &DeviceHost::flushViews);
    connect(m_manager.get(), &devices::DeviceManager::deviceChanged, this, &DeviceHost::onDeviceChanged);
    connect(m_manager.get(), &devices::DeviceManager::devicesChanged, this, [this] {
        pumpCalibration();
        emit listChanged(views());
    });
    m_calibrationPump.setInterval(kCalibrationPumpMs);
    connect(&m_calibrationPump, &QTimer::timeout, this, &DeviceHost::pumpCalibration);
    m_statisticsRefresh.setInterval(kStatisticsRefreshMs);
    connect(&m_statisticsRefresh, &QTimer::timeout, this, &DeviceHost::refreshStatistics);
    m_statisticsRefresh.start();
    m_lathe = new LatheLink(m_manager.get(), this);
    m_boring = new BoringLink(m_manager.get(), this);
}

DeviceHost::~DeviceHost() {
    disconnectLathe(tr("TrueTurn is closing"));
    disconnectBoring();
    endTrial();
}

DeviceView DeviceHost::snapshot(const QString& id, const QString& name, const QString& pluginId,
                                devices::DeviceKind kind, const QVariantMap& settings, devices::Device& device) const {
    DeviceView v;
    v.id = id;
    v.name = name;
    v.pluginId = pluginId;
    v.kind = kind;
    v.settings = settings;
    v.instance = reinterpret_cast<quintptr>(&device);
    v.health = device.health();
    v.liveValue = device.liveValue();
    v.lastError = device.lastError();
    v.statistics = device.statistics();
    addCapabilities(v, device);
    return v;
}

std::optional<DeviceView> DeviceHost::view(const QString& id) const {
    if (id == kTrialDeviceId && m_trial) return snapshot(id, id, m_trialPlugin, m_trialKind, m_trialSettings, *m_trial);
    const devices::DeviceEntry* e = m_manager->entry(id);
    if (!e) return std::nullopt;
    return snapshot(e->id, e->name, e->pluginId, e->kind, e->settings, *e->device);
}

QList<DeviceView> DeviceHost::views() const {
    QList<DeviceView> all;
    for (const QString& id : m_manager->deviceIds())
        if (std::optional<DeviceView> v = view(id)) all << *v;
    if (m_trial) all << *view(kTrialDeviceId);
    return all;
}

void DeviceHost::onDeviceChanged(const QString& id) {
    pumpCalibration();
    m_dirty.insert(id);
    if (!m_flush.isActive()) m_flush.start();
}

void DeviceHost::refreshStatistics() {
    auto sameAs = [](const QList<devices::DeviceStatistic>& a, const QList<devices::DeviceStatistic>& b) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                          [](const auto& x, const auto& y) { return x.label == y.label && x.value == y.value; });
    };
    for (const QString& id : m_manager->deviceIds()) {
        devices::Device* d = m_manager->device(id);
        if (!d) continue;
        QList<devices::DeviceStatistic> now = d->statistics();
        if (sameAs(now, m_statisticsShown.value(id))) continue;
        m_statisticsShown.insert(id, std::move(now));
        m_dirty.insert(id);
    }
    if (!m_dirty.isEmpty() && !m_flush.isActive()) m_flush.start();
}

void DeviceHost::flushViews() {
    QList<DeviceView> changed;
    for (const QString& id : std::as_const(m_dirty))
        if (std::optional<DeviceView> v = view(id)) changed << *v;
    m_dirty.clear();
    if (!changed.isEmpty()) emit viewsChanged(changed);
}

devices::Device* DeviceHost::deviceOrTrial(const QString& id) const {
    if (id == kTrialDeviceId) return m_trial.get();
    return m_manager->device(id);
}

// ---- the Devices page's commands ----------------------------------------------------------------------------

void DeviceHost::startTrial(const QString& pluginId, devices::DeviceKind kind, const QVariantMap& settings,
                            const QString& closeId) {
    endTrial();
    devices::DevicePlugin* plugin = m_manager->plugin(pluginId);
    if (!plugin) throw std::invalid_argument(tr("the device plugin %1 is not installed").arg(pluginId).toStdString());
    if (devices::Device* live = m_manager->device(closeId)) {
        live->close();
        m_reopenAfterTrial = closeId;
    }
    try {
        m_trial = plugin->create(kind, settings, devices::DeviceContext{&m_manager->clock()});
    } catch (const std::invalid_argument&) {
        endTrial();
        throw;
    }
    m_trialPlugin = pluginId;
    m_trialKind = kind;
    m_trialSettings = settings;
    m_trial->setChangeListener([this] { onDeviceChanged(kTrialDeviceId); });
    emit listChanged(views());
}

void DeviceHost::endTrial() {
    if (m_trial) {
        m_trial->setChangeListener({});
        m_trial->close();
        m_trial.reset();
        emit listChanged(views());
    }
    if (!m_reopenAfterTrial.isEmpty()) {
        if (devices::Device* d = m_manager->device(m_reopenAfterTrial)) d->open();
        m_reopenAfterTrial.clear();
    }
}

void DeviceHost::testConnection(const QString& id) {
    if (devices::Device* d = deviceOrTrial(id)) d->testConnection();
}

void DeviceHost::requestReading(const QString& id) {
    devices::Device* d = m_manager->device(id);
    if (core::DiameterGauge* gauge = d ? d->diameterGauge() : nullptr) gauge->requestReading();
}

void DeviceHost::setFaults(const QString& id, const devices::FaultSwitches& faults) {
    devices::Device* d = deviceOrTrial(id);
    if (devices::SimulatedInstrument* sim = d ? devices::simulatedInstrument(*d) : nullptr) {
        sim->faultSwitches() = faults;
        onDeviceChanged(id);
    }
}

// ---- the runs' links ------------------------------------------------------------------------------------------

std::shared_ptr<core::RelayedLathe> DeviceHost::connectLathe(const QString& outputId, const QString& gaugeId) {
    return m_lathe->connectDevices(outputId, gaugeId);
}

void DeviceHost::disconnectLathe(const QString& reason) {
    m_lathe->disconnectDevices(reason);
}

bool DeviceHost::latheConnected() const {
    return m_lathe->isConnected();
}

std::shared_ptr<core::RelayedBoringStation> DeviceHost::connectBoring(const QString& sourceId,
                                                                      core::BoringMethod method,
                                                                      const QString& outputId, double plcCycleS) {
    return m_boring->connectDevices(sourceId, method, outputId, plcCycleS);
}

void DeviceHost::disconnectBoring() {
    m_boring->disconnectDevices();
}

std::vector<std::chrono::steady_clock::time_point> DeviceHost::boringWriteTimes() const {
    return m_boring->writeTimes();
}

std::shared_ptr<core::BoringStation> DeviceHost::beginBoringPass(const QString& sourceId,
                                                                 const core::BoringScenario& scenario) {
    devices::Device* d = m_manager->device(sourceId);
    devices::SimulatedInstrument* sim = d ? devices::simulatedInstrument(*d) : nullptr;
    devices::BoringTruth* truth = sim ? sim->boringTruth() : nullptr;
    if (!truth) throw std::invalid_argument(tr("this source runs no boring pass of its own").toStdString());
    return truth->beginPass(scenario);
}

core::OutputResult DeviceHost::writeOffset(const QString& outputId, double xOffsetMm) {
    devices::Device* d = m_manager->device(outputId);
    core::CorrectionOutput* output = d ? d->correctionOutput() : nullptr;
    if (!output) return {false, tr("the CNC output is no longer on the Devices page").toStdString()};
    return output->sendDynamicOffset(xOffsetMm);
}

std::shared_ptr<CalibrationLink> DeviceHost::calibrationLink(const QString& id) {
    devices::Device* d = m_manager->device(id);
    auto link = std::make_shared<CalibrationLink>(id);
    if (d) {  // samples taken before the wizard asked belong to no step of it
        if (core::DeflectionProbe* p = d->deflectionProbe())
            while (p->takeSample()) {
            }
        if (core::DriveCurrentReadout* r = d->driveCurrentReadout())
            while (r->takeSample()) {
            }
    }
    std::erase_if(m_calibration, [](const std::weak_ptr<CalibrationLink>& w) { return w.expired(); });
    m_calibration.push_back(link);
    pumpCalibration();
    m_calibrationPump.start();
    return link;
}

devices::CalibrationStand& DeviceHost::stand(const QString& id) const {
    devices::Device* d = m_manager->device(id);
    devices::SimulatedInstrument* sim = d ? devices::simulatedInstrument(*d) : nullptr;
    devices::CalibrationStand* stand = sim ? sim->calibrationStand() : nullptr;
    if (!stand) throw std::invalid_argument(tr("this instrument is not on a calibration stand").toStdString());
    return *stand;
}

void DeviceHost::bendBar(const QString& id, int plane, double tipDeflectionMm) {
    devices::CalibrationStand& s = stand(id);
    if (!s.bendsBar()) throw std::invalid_argument(tr("this stand has no screw jack").toStdString());
    s.bendBar(plane, tipDeflectionMm);
}

void DeviceHost::applyLoadN(const QString& id, double loadN) {
    devices::CalibrationStand& s = stand(id);
    if (!s.appliesLoad()) throw std::invalid_argument(tr("this stand has no hydraulic jack").toStdString());
    s.applyLoadN(loadN);
}

void DeviceHost::releaseJack(const QString& id) {
    devices::Device* d = m_manager->device(id);
    devices::SimulatedInstrument* sim = d ? devices::simulatedInstrument(*d) : nullptr;
    if (devices::CalibrationStand* s = sim ? sim->calibrationStand() : nullptr) s->release();
}

void DeviceHost::uploadTable(const QString& id, const std::vector<std::uint8_t>& image, std::uint16_t version,
                             std::uint32_t crc32c) {
    devices::Device* d = m_manager->device(id);
    devices::TableUploadTarget* target = d ? d->tableUploadTarget() : nullptr;
    if (!target) throw std::invalid_argument(tr("this probe cannot take a table upload").toStdString());
    target->uploadTable(image, version, crc32c);
}

void DeviceHost::pumpCalibration() {
    std::erase_if(m_calibration, [](const std::weak_ptr<CalibrationLink>& w) { return w.expired(); });
    if (m_calibration.empty()) m_calibrationPump.stop();
    for (const std::weak_ptr<CalibrationLink>& weak : m_calibration) {
        const std::shared_ptr<CalibrationLink> link = weak.lock();
        if (!link) continue;
        devices::Device* d = m_manager->device(link->deviceId());
        if (!d || d->deflectionProbe()) pass(d ? d->deflectionProbe() : nullptr, link->probe());
        if (!d || d->driveCurrentReadout()) pass(d ? d->driveCurrentReadout() : nullptr, link->drive());
        if (d) showUploadProgress(link->deviceId(), *d);
    }
}

void DeviceHost::showUploadProgress(const QString& id, devices::Device& device) {
    const devices::TableUploadTarget* target = device.tableUploadTarget();
    if (!target) return;
    const devices::TableUploadStatus now = target->uploadStatus();
    const devices::TableUploadStatus shown = m_uploadShown.value(id);
    if (now.phase == shown.phase && now.progress == shown.progress && now.message == shown.message) return;
    m_uploadShown.insert(id, now);
    m_dirty.insert(id);
    if (!m_flush.isActive()) m_flush.start();
}

}  // namespace tt::runtime
