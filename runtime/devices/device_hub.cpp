#include "runtime/devices/device_hub.h"

#include <QMetaObject>
#include <QSettings>

#include "devices/simulator/simulator_registration.h"
#include "runtime/devices/calibration_link.h"
#include "runtime/devices/device_host.h"

namespace tt::runtime {

namespace {

QString stateWord(core::DeviceState state) {
    switch (state) {
        case core::DeviceState::Ready:
            return DeviceHub::tr("ready");
        case core::DeviceState::Connecting:
            return DeviceHub::tr("connecting");
        case core::DeviceState::Error:
            return DeviceHub::tr("error");
        case core::DeviceState::Disconnected:
            break;
    }
    return DeviceHub::tr("closed");
}

}  // namespace

DeviceHub::DeviceHub(const core::Clock* clock, QObject* parent) : QObject(parent) {
    qRegisterMetaType<DeviceView>();
    qRegisterMetaType<QList<DeviceView>>();
    devices::registerBuiltInSimulator();
    m_thread.setObjectName(QStringLiteral("trueturn-devices"));
    m_anchor = new QObject;
    m_anchor->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_anchor, &QObject::deleteLater);
    m_thread.start();
    onDeviceThread([this, clock] {
        m_host = new DeviceHost(clock);
        m_clock = &m_host->manager().clock();
        m_plugins = m_host->manager().plugins();
    });
    connect(m_host, &DeviceHost::viewsChanged, this, &DeviceHub::takeChanges);
    // A list that changed in the device thread is fetched fresh when the news arrives: an older copy queued
    // behind a newer one must not bring back instances that are gone.
    connect(m_host, &DeviceHost::listChanged, this, &DeviceHub::sync);
}

DeviceHub::~DeviceHub() {
    onDeviceThread([this] {
        delete m_host;
        m_host = nullptr;
    });
    m_thread.quit();
    m_thread.wait();
}

void DeviceHub::onDeviceThread(const std::function<void()>& work) {
    if (QThread::currentThread() == &m_thread) {
        work();
        return;
    }
    std::exception_ptr error;
    QMetaObject::invokeMethod(
        m_anchor,
        [&work, &error] {
            try {
                work();
            } catch (...) {
                error = std::current_exception();
            }
        },
        Qt::BlockingQueuedConnection);
    if (error) std::rethrow_exception(error);
}

void DeviceHub::takeList(const QList<DeviceView>& views) {
    // The same instances as before (a late copy of a list already taken, a sync): only their snapshots changed.
    auto identity = [](const QList<DeviceView>& list) {
        QList<QPair<QString, quintptr>> ids;
        for (const DeviceView& v : list)
            ids.append({v.id, v.instance});
        return ids;
    };
    if (identity(views) == identity(m_views)) {
        takeChanges(views);
        return;
    }
    m_views = views;
    emit devicesChanged();
}

void DeviceHub::takeChanges(const QList<DeviceView>& views) {
    for (const DeviceView& v : views) {
        for (DeviceView& mine : m_views)
            if (mine.id == v.id) mine = v;
        emit deviceChanged(v.id);
    }
}

// ---- plugins and instances ----------------------------------------------------------------------------------

int DeviceHub::loadPlugins(const QString& folder) {
    int loaded = 0;
    onDeviceThread([&] {
        loaded = m_host->manager().loadPlugins(folder);
        m_plugins = m_host->manager().plugins();
    });
    return loaded;
}

QStringList DeviceHub::pluginErrors() const {
    QStringList errors;
    const_cast<DeviceHub*>(this)->onDeviceThread([&] { errors = m_host->manager().pluginErrors(); });
    return errors;
}

devices::DevicePlugin* DeviceHub::plugin(const QString& pluginId) const {
    for (devices::DevicePlugin* p : m_plugins)
        if (p->pluginId() == pluginId) return p;
    return nullptr;
}

QList<devices::ShaftMachineOffer> DeviceHub::shaftMachineOffers() const {
    QList<devices::ShaftMachineOffer> offers;
    for (const devices::DevicePlugin* p : m_plugins)
        offers << p->shaftMachines();
    for (const DeviceView& view : m_views)
        if (const devices::DevicePlugin* p = plugin(view.pluginId); p && view.id != kTrialDeviceId)
            offers << p->deviceMachines(view.kind, view.settings);
    return offers;
}

QString DeviceHub::addDevice(const QString& pluginId, devices::DeviceKind kind, const QString& name,
                             const QVariantMap& settings) {
    QString id;
    QList<DeviceView> views;
    onDeviceThread([&] {
        id = m_host->manager().addDevice(pluginId, kind, name, settings);
        views = m_host->views();
    });
    takeList(views);
    return id;
}

void DeviceHub::updateDevice(const QString& id, const QString& name, const QVariantMap& settings) {
    QList<DeviceView> views;
    onDeviceThread([&] {
        m_host->manager().updateDevice(id, name, settings);
        views = m_host->views();
    });
    takeList(views);
}

void DeviceHub::removeDevice(const QString& id) {
    QList<DeviceView> views;
    onDeviceThread([&] {
        m_host->manager().removeDevice(id);
        views = m_host->views();
    });
    takeList(views);
}

void DeviceHub::save(QSettings& settings) {
    onDeviceThread([&] { m_host->manager().save(settings); });
}

QStringList DeviceHub::restore(QSettings& settings) {
    QStringList problems;
    QList<DeviceView> views;
    onDeviceThread([&] {
        problems = m_host->manager().restore(settings);
        views = m_host->views();
    });
    takeList(views);
    return problems;
}

void DeviceHub::openAll() {
    QList<DeviceView> views;
    onDeviceThread([&] {
        m_host->manager().openAll();
        views = m_host->views();
    });
    takeChanges(views);
}

void DeviceHub::commandDevice(const QString& id, const std::function<void()>& command) {
    std::optional<DeviceView> view;
    onDeviceThread([&] {
        command();
        view = m_host->view(id);
    });
    if (view) takeChanges({*view});
}

void DeviceHub::open(const QString& id) {
    commandDevice(id, [this, id] {
        if (devices::Device* d = m_host->manager().device(id)) d->open();
    });
}

void DeviceHub::testConnection(const QString& id) {
    commandDevice(id, [this, id] { m_host->testConnection(id); });
}

void DeviceHub::requestReading(const QString& id) {
    commandDevice(id, [this, id] { m_host->requestReading(id); });
}

void DeviceHub::setFaults(const QString& id, const devices::FaultSwitches& faults) {
    commandDevice(id, [&] { m_host->setFaults(id, faults); });
}

void DeviceHub::startTrial(const QString& pluginId, devices::DeviceKind kind, const QVariantMap& settings,
                           const QString& closeId) {
    QList<DeviceView> views;
    onDeviceThread([&] {
        m_host->startTrial(pluginId, kind, settings, closeId);
        views = m_host->views();
    });
    takeList(views);
}

void DeviceHub::endTrial() {
    QList<DeviceView> views;
    onDeviceThread([&] {
        m_host->endTrial();
        views = m_host->views();
    });
    takeList(views);
}

// ---- snapshots ------------------------------------------------------------------------------------------------

QStringList DeviceHub::deviceIds() const {
    QStringList ids;
    for (const DeviceView& v : m_views)
        if (v.id != kTrialDeviceId) ids << v.id;
    return ids;
}

const DeviceView* DeviceHub::view(const QString& id) const {
    for (const DeviceView& v : m_views)
        if (v.id == id) return &v;
    return nullptr;
}

QStringList DeviceHub::devicesOfKind(devices::DeviceKind kind) const {
    QStringList ids;
    for (const DeviceView& v : m_views)
        if (v.kind == kind && v.id != kTrialDeviceId) ids << v.id;
    return ids;
}

DeviceSummary DeviceHub::summary() const {
    DeviceSummary s;
    const QStringList ids = deviceIds();
    if (ids.isEmpty()) return s;
    int ready = 0;
    int errors = 0;
    const DeviceView* firstError = nullptr;
    const DeviceView* firstWaiting = nullptr;
    for (const QString& id : ids) {
        const DeviceView* v = view(id);
        if (v->health.state == core::DeviceState::Ready) ++ready;
        if (v->health.state == core::DeviceState::Error) {
            ++errors;
            if (!firstError) firstError = v;
        } else if (v->health.state != core::DeviceState::Ready && !firstWaiting) {
            firstWaiting = v;
        }
    }
    if (firstError) {
        s.tone = DeviceSummary::Tone::Fault;
        s.text = QStringLiteral("%1: %2").arg(firstError->name, QString::fromStdString(firstError->health.message));
        if (errors > 1) s.text += tr(" (%1 more in error)").arg(errors - 1);
    } else if (firstWaiting) {
        s.tone = DeviceSummary::Tone::Warning;
        s.text = tr("%1 of %2 ready; %3 %4")
                     .arg(ready)
                     .arg(ids.size())
                     .arg(firstWaiting->name, stateWord(firstWaiting->health.state));
    } else {
        s.tone = DeviceSummary::Tone::Ok;
        s.text = tr("%n ready", nullptr, static_cast<int>(ids.size()));
    }
    return s;
}

// ---- the runs' links --------------------------------------------------------------------------------------------

std::shared_ptr<core::RelayedLathe> DeviceHub::connectLathe(const QString& outputId, const QString& gaugeId) {
    std::shared_ptr<core::RelayedLathe> lathe;
    onDeviceThread([&] { lathe = m_host->connectLathe(outputId, gaugeId); });
    return lathe;
}

void DeviceHub::disconnectLathe(const QString& reason) {
    onDeviceThread([&] { m_host->disconnectLathe(reason); });
}

bool DeviceHub::latheConnected() {
    bool connected = false;
    onDeviceThread([&] { connected = m_host->latheConnected(); });
    return connected;
}

std::shared_ptr<core::RelayedBoringStation> DeviceHub::connectBoring(const QString& sourceId, core::BoringMethod method,
                                                                     const QString& outputId, double plcCycleS) {
    std::shared_ptr<core::RelayedBoringStation> station;
    onDeviceThread([&] { station = m_host->connectBoring(sourceId, method, outputId, plcCycleS); });
    return station;
}

void DeviceHub::disconnectBoring() {
    onDeviceThread([this] { m_host->disconnectBoring(); });
}

std::vector<std::chrono::steady_clock::time_point> DeviceHub::boringWriteTimes() {
    std::vector<std::chrono::steady_clock::time_point> times;
    onDeviceThread([&] { times = m_host->boringWriteTimes(); });
    return times;
}

std::shared_ptr<core::BoringStation> DeviceHub::beginBoringPass(const QString& sourceId,
                                                                const core::BoringScenario& scenario) {
    std::shared_ptr<core::BoringStation> pass;
    onDeviceThread([&] { pass = m_host->beginBoringPass(sourceId, scenario); });
    return pass;
}

core::OutputResult DeviceHub::writeOffset(const QString& outputId, double xOffsetMm) {
    core::OutputResult result;
    onDeviceThread([&] { result = m_host->writeOffset(outputId, xOffsetMm); });
    return result;
}

// ---- calibration ---------------------------------------------------------------------------------------------

std::shared_ptr<CalibrationLink> DeviceHub::calibrationLink(const QString& id) {
    std::shared_ptr<CalibrationLink> link;
    onDeviceThread([&] { link = m_host->calibrationLink(id); });
    return link;
}

void DeviceHub::bendBar(const QString& id, int plane, double tipDeflectionMm) {
    onDeviceThread([&] { m_host->bendBar(id, plane, tipDeflectionMm); });
}

void DeviceHub::applyLoadN(const QString& id, double loadN) {
    onDeviceThread([&] { m_host->applyLoadN(id, loadN); });
}

void DeviceHub::releaseJack(const QString& id) {
    onDeviceThread([&] { m_host->releaseJack(id); });
}

void DeviceHub::uploadTable(const QString& id, const std::vector<std::uint8_t>& image, std::uint16_t version,
                            std::uint32_t crc32c) {
    onDeviceThread([&] { m_host->uploadTable(id, image, version, crc32c); });
}

bool DeviceHub::withDevice(const QString& id, const std::function<void(devices::Device&)>& work) {
    bool found = false;
    commandDevice(id, [&] {
        devices::Device* d = m_host->manager().device(id);
        if (!d) return;
        found = true;
        work(*d);
    });
    return found;
}

void DeviceHub::sync() {
    QList<DeviceView> views;
    onDeviceThread([&] { views = m_host->views(); });
    takeList(views);
}

}  // namespace tt::runtime
