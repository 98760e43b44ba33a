#include "devices/api/device_manager.h"

#include <QDir>
#include <QPluginLoader>
#include <QSettings>
#include <stdexcept>

namespace tt::devices {

namespace {

/// A device's state in a word of the user's language, for the summary ("connecting").
QString stateWord(core::DeviceState state) {
    switch (state) {
        case core::DeviceState::Ready:
            return DeviceManager::tr("ready");
        case core::DeviceState::Connecting:
            return DeviceManager::tr("connecting");
        case core::DeviceState::Error:
            return DeviceManager::tr("error");
        case core::DeviceState::Disconnected:
            break;
    }
    return DeviceManager::tr("closed");
}

}  // namespace

DeviceManager::DeviceManager(const core::Clock* clock, QObject* parent)
    : QObject(parent), m_clock(clock ? clock : &m_ownClock) {
    // The plugins linked into the program (the built-in simulator) come first, found like the others.
    for (QObject* root : QPluginLoader::staticInstances())
        if (auto* plugin = qobject_cast<DevicePlugin*>(root); plugin && !this->plugin(plugin->pluginId()))
            m_static << plugin;
}

DeviceManager::~DeviceManager() {
    // Instances first: their code lives in the plugin libraries (which stay loaded).
    for (DeviceEntry& e : m_entries) {
        e.device->setChangeListener({});
        e.device->close();
    }
    m_entries.clear();
}

int DeviceManager::loadPlugins(const QString& folder) {
    const QDir dir(folder);
    int loaded = 0;
    if (!dir.exists()) {
        m_pluginErrors << tr("plugin folder %1 does not exist").arg(QDir::toNativeSeparators(folder));
        return 0;
    }
    for (const QString& file : dir.entryList(QDir::Files, QDir::Name)) {
        const QString path = dir.absoluteFilePath(file);
        if (!QLibrary::isLibrary(path) || m_loadedFiles.contains(path)) continue;
        auto* loader = new QPluginLoader(path, this);
        QObject* root = loader->instance();
        auto* plugin = root ? qobject_cast<DevicePlugin*>(root) : nullptr;
        if (!plugin) {
            m_pluginErrors << (root ? tr("%1: not a TrueTurn device plugin").arg(file)
                                    : tr("%1: %2").arg(file, loader->errorString()));
            delete loader;
            continue;
        }
        if (this->plugin(plugin->pluginId())) {
            m_pluginErrors << tr("%1: a plugin with id %2 is already loaded").arg(file, plugin->pluginId());
            continue;
        }
        m_loaders << loader;
        m_loaded << plugin;
        m_loadedFiles << path;
        ++loaded;
    }
    return loaded;
}

QList<DevicePlugin*> DeviceManager::plugins() const {
    QList<DevicePlugin*> all = m_static;
    all << m_loaded;
    return all;
}

QList<ShaftMachineOffer> DeviceManager::shaftMachineOffers() const {
    QList<ShaftMachineOffer> offers;
    for (const DevicePlugin* p : plugins())
        offers << p->shaftMachines();
    return offers;
}

DevicePlugin* DeviceManager::plugin(const QString& pluginId) const {
    for (DevicePlugin* p : plugins())
        if (p->pluginId() == pluginId) return p;
    return nullptr;
}

std::unique_ptr<Device> DeviceManager::make(const QString& pluginId, DeviceKind kind, const QVariantMap& settings,
                                            QVariantMap& completed, Validation depth) const {
    DevicePlugin* p = plugin(pluginId);
    if (!p) throw std::invalid_argument(tr("the device plugin %1 is not installed").arg(pluginId).toStdString());
    if (!p->kinds().contains(kind))
        throw std::invalid_argument(
            tr("the plugin %1 does not provide a %2").arg(p->displayName(), kindName(kind)).toStdString());
    completed = withDefaults(p->settingsSchema(kind), settings);
    const QList<SettingIssue> issues = p->validate(kind, completed, depth);
    if (!issues.isEmpty()) throw std::invalid_argument(joinIssues(issues).toStdString());
    return p->create(kind, completed, DeviceContext{m_clock});
}

void DeviceManager::watch(const QString& id, Device& device) {
    device.setChangeListener([this, id] { emit deviceChanged(id); });
}

QString DeviceManager::insert(const QString& id, const QString& pluginId, DeviceKind kind, const QString& name,
                              const QVariantMap& settings, Validation depth) {
    QVariantMap completed;
    std::unique_ptr<Device> device = make(pluginId, kind, settings, completed, depth);
    DeviceEntry entry;
    entry.id = id;
    entry.name = name.trimmed().isEmpty() ? kindName(kind) : name.trimmed();
    entry.pluginId = pluginId;
    entry.kind = kind;
    entry.settings = completed;
    entry.device = std::move(device);
    watch(entry.id, *entry.device);
    m_entries.push_back(std::move(entry));
    return id;
}

QString DeviceManager::addDevice(const QString& pluginId, DeviceKind kind, const QString& name,
                                 const QVariantMap& settings) {
    const QString id = insert(QStringLiteral("dev-%1").arg(m_nextId), pluginId, kind, name, settings, Validation::Full);
    ++m_nextId;
    emit devicesChanged();
    return id;
}

DeviceEntry* DeviceManager::find(const QString& id) {
    for (DeviceEntry& e : m_entries)
        if (e.id == id) return &e;
    return nullptr;
}

void DeviceManager::updateDevice(const QString& id, const QString& name, const QVariantMap& settings) {
    DeviceEntry* e = find(id);
    if (!e) throw std::invalid_argument(tr("no device with id %1").arg(id).toStdString());
    QVariantMap completed;
    std::unique_ptr<Device> device = make(e->pluginId, e->kind, settings, completed, Validation::Full);
    e->device->setChangeListener({});
    e->device->close();
    e->device = std::move(device);
    e->settings = completed;
    if (!name.trimmed().isEmpty()) e->name = name.trimmed();
    watch(e->id, *e->device);
    emit devicesChanged();
}

void DeviceManager::removeDevice(const QString& id) {
    for (auto it = m_entries.begin(); it != m_entries.end(); ++it) {
        if (it->id != id) continue;
        it->device->setChangeListener({});
        it->device->close();
        m_entries.erase(it);
        emit devicesChanged();
        return;
    }
}

QStringList DeviceManager::deviceIds() const {
    QStringList ids;
    for (const DeviceEntry& e : m_entries)
        ids << e.id;
    return ids;
}

const DeviceEntry* DeviceManager::entry(const QString& id) const {
    for (const DeviceEntry& e : m_entries)
        if (e.id == id) return &e;
    return nullptr;
}

Device* DeviceManager::device(const QString& id) const {
    const DeviceEntry* e = entry(id);
    return e ? e->device.get() : nullptr;
}

QStringList DeviceManager::devicesOfKind(DeviceKind kind) const {
    QStringList ids;
    for (const DeviceEntry& e : m_entries)
        if (e.kind == kind) ids << e.id;
    return ids;
}

void DeviceManager::openAll() {
    for (DeviceEntry& e : m_entries)
        e.device->open();
}

DeviceSummary DeviceManager::summary() const {
    DeviceSummary s;
    if (m_entries.empty()) return s;
    int ready = 0;
    const DeviceEntry* firstError = nullptr;
    const DeviceEntry* firstWaiting = nullptr;
    int errors = 0;
    for (const DeviceEntry& e : m_entries) {
        const core::DeviceHealth h = e.device->health();
        if (h.state == core::DeviceState::Ready) ++ready;
        if (h.state == core::DeviceState::Error) {
            ++errors;
            if (!firstError) firstError = &e;
        } else if (h.state != core::DeviceState::Ready && !firstWaiting) {
            firstWaiting = &e;
        }
    }
    const int total = static_cast<int>(m_entries.size());
    if (firstError) {
        s.tone = DeviceSummary::Tone::Fault;
        s.text = QStringLiteral("%1: %2").arg(firstError->name,
                                              QString::fromStdString(firstError->device->health().message));
        if (errors > 1) s.text += tr(" (%1 more in error)").arg(errors - 1);
    } else if (firstWaiting) {
        s.tone = DeviceSummary::Tone::Warning;
        s.text = tr("%1 of %2 ready; %3 %4")
                     .arg(ready)
                     .arg(total)
                     .arg(firstWaiting->name, stateWord(firstWaiting->device->health().state));
    } else {
        s.tone = DeviceSummary::Tone::Ok;
        s.text = tr("%n ready", nullptr, total);
    }
    return s;
}

void DeviceManager::save(QSettings& settings) const {
    settings.beginGroup(QStringLiteral("devices"));
    settings.remove(QString());
    settings.beginWriteArray(QStringLiteral("instances"), static_cast<int>(m_entries.size()));
    for (int i = 0; i < static_cast<int>(m_entries.size()); ++i) {
        const DeviceEntry& e = m_entries[static_cast<std::size_t>(i)];
        settings.setArrayIndex(i);
        settings.setValue(QStringLiteral("id"), e.id);
        settings.setValue(QStringLiteral("name"), e.name);
        settings.setValue(QStringLiteral("plugin"), e.pluginId);
        settings.setValue(QStringLiteral("kind"), kindKey(e.kind));
        settings.setValue(QStringLiteral("settings"), e.settings);
    }
    settings.endArray();
    settings.setValue(QStringLiteral("unavailable"), m_unavailable);
    settings.setValue(QStringLiteral("nextId"), m_nextId);
    settings.endGroup();
}

QStringList DeviceManager::restore(QSettings& settings) {
    for (DeviceEntry& e : m_entries) {
        e.device->setChangeListener({});
        e.device->close();
    }
    m_entries.clear();
    m_unavailable.clear();
    QStringList problems;
    settings.beginGroup(QStringLiteral("devices"));
    // Entries that could not be restored before are tried again (their plugin may be back).
    QVariantList saved;
    const QVariantList previouslyUnavailable = settings.value(QStringLiteral("unavailable")).toList();
    const int count = settings.beginReadArray(QStringLiteral("instances"));
    for (int i = 0; i < count; ++i) {
        settings.setArrayIndex(i);
        QVariantMap raw;
        for (const QString& key : {QStringLiteral("id"), QStringLiteral("name"), QStringLiteral("plugin"),
                                   QStringLiteral("kind"), QStringLiteral("settings")})
            raw.insert(key, settings.value(key));
        saved << raw;
    }
    settings.endArray();
    saved << previouslyUnavailable;
    for (const QVariant& item : saved) {
        const QVariantMap raw = item.toMap();
        const QString id = raw.value(QStringLiteral("id")).toString();
        const QString name = raw.value(QStringLiteral("name")).toString();
        const auto kind = kindFromKey(raw.value(QStringLiteral("kind")).toString());
        if (!kind || id.isEmpty() || entry(id)) {
            problems << tr("device %1: the saved entry is incomplete").arg(name);
            continue;
        }
        try {
            insert(id, raw.value(QStringLiteral("plugin")).toString(), *kind, name,
                   raw.value(QStringLiteral("settings")).toMap(), Validation::Structure);
        } catch (const std::invalid_argument& e) {
            // Kept as saved (and saved again), so nothing the user configured is lost.
            m_unavailable << raw;
            problems << tr("%1: %2").arg(name, QString::fromStdString(e.what()));
        }
    }
    m_nextId = std::max(settings.value(QStringLiteral("nextId"), 1).toInt(), static_cast<int>(m_entries.size()) + 1);
    settings.endGroup();
    emit devicesChanged();
    return problems;
}

}  // namespace tt::devices
