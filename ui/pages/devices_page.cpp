#include "ui/pages/devices_page.h"

#include <QAbstractItemView>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPainter>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QStackedWidget>
#include <QStyle>
#include <QVBoxLayout>
#include <stdexcept>

#include "devices/api/settings_schema.h"
#include "runtime/devices/device_hub.h"
#include "ui/app_state.h"
#include "ui/auth/audit_trail.h"
#include "ui/devices/device_status_bridge.h"
#include "ui/devices/settings_form.h"
#include "ui/empty_state.h"
#include "ui/pages/planned_page.h"
#include "ui/prompt.h"

namespace tt::ui {

using core::DeviceState;
using devices::DeviceKind;

namespace {

constexpr int kTestTimeoutMs = 4000;
constexpr int kPushGaugeSettleMs = 1500;

QString toneOf(DeviceState state) {
    switch (state) {
        case DeviceState::Ready:
            return QStringLiteral("ok");
        case DeviceState::Connecting:
            return QStringLiteral("warn");
        case DeviceState::Error:
            return QStringLiteral("fault");
        case DeviceState::Disconnected:
            break;
    }
    return QStringLiteral("idle");
}

QIcon toneIcon(const QString& tone) {
    QPixmap pixmap(28, 28);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    const QColor color = tone == QLatin1String("ok")      ? QColor(0x2e, 0x7d, 0x32)
                         : tone == QLatin1String("warn")  ? QColor(0xb2, 0x6a, 0x00)
                         : tone == QLatin1String("fault") ? QColor(0xc6, 0x28, 0x28)
                                                          : QColor(0x6b, 0x77, 0x85);
    painter.setBrush(color);
    painter.setPen(Qt::NoPen);
    painter.drawEllipse(3, 3, 22, 22);
    return QIcon(pixmap);
}

void setTone(QWidget* w, const QString& tone) {
    w->setProperty("tone", tone);
    w->style()->unpolish(w);
    w->style()->polish(w);
}

}  // namespace

DevicesPage::DevicesPage(AppContext& context, QWidget* parent)
    : Page(PageId::Devices, context, parent),
      m_listTitle(new QLabel(this)),
      m_list(new QListWidget(this)),
      m_newTypeLabel(new QLabel(this)),
      m_newType(new QComboBox(this)),
      m_add(new QPushButton(this)),
      m_remove(new QPushButton(this)),
      m_detailStack(new QStackedWidget(this)),
      m_empty(new EmptyState(this)),
      m_detailTitle(new QLabel(this)),
      m_typeText(new QLabel(this)),
      m_stateLabel(new QLabel(this)),
      m_stateBadge(new QLabel(this)),
      m_stateMessage(new QLabel(this)),
      m_liveLabel(new QLabel(this)),
      m_live(new QLabel(this)),
      m_lastErrorLabel(new QLabel(this)),
      m_lastError(new QLabel(this)),
      m_nameLabel(new QLabel(this)),
      m_name(new QLineEdit(this)),
      m_settingsTitle(new QLabel(this)),
      m_form(new SettingsForm(this)),
      m_problems(new QLabel(this)),
      m_test(new QPushButton(this)),
      m_apply(new QPushButton(this)),
      m_revert(new QPushButton(this)),
      m_testResult(new QLabel(this)),
      m_faults(new QGroupBox(this)),
      m_faultSilent(new QCheckBox(this)),
      m_faultNoisy(new QCheckBox(this)),
      m_faultStuck(new QCheckBox(this)),
      m_faultMalformed(new QCheckBox(this)),
      m_faultUnplugged(new QCheckBox(this)),
      m_statsTitle(new QLabel(this)),
      m_stats(new QLabel(this)) {
    m_hub = context.devices;
    if (!m_hub) throw std::invalid_argument("the Devices page needs the application's devices (AppContext::devices)");
    if (context.state) m_bridge = new DeviceStatusBridge(*m_hub, *context.state, this);

    buildUi();
    fillTypes();
    reloadList();

    connectControls();
    connectFaultSwitches();

    retranslate();
    if (m_list->count() > 0) m_list->setCurrentRow(0);
    showSelection();
}

DevicesPage::~DevicesPage() {
    m_testTimer.stop();
    if (m_testTarget == runtime::kTrialDeviceId) m_hub->endTrial();
}

void DevicesPage::connectControls() {
    connect(m_hub, &runtime::DeviceHub::devicesChanged, this, &DevicesPage::reloadList);
    connect(m_hub, &runtime::DeviceHub::deviceChanged, this, [this] {
        updateListTones();
        refreshStatus();
    });
    connect(m_list, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row < 0) return;
        const QString id = m_list->item(row)->data(Qt::UserRole).toString();
        if (!id.isEmpty() && (!m_selection || m_selection->deviceId != id)) selectDevice(id);
    });
    connect(m_add, &QPushButton::clicked, this, &DevicesPage::startDraft);
    connect(m_remove, &QPushButton::clicked, this, &DevicesPage::removeSelected);
    connect(m_apply, &QPushButton::clicked, this, &DevicesPage::apply);
    connect(m_revert, &QPushButton::clicked, this, &DevicesPage::revert);
    connect(m_test, &QPushButton::clicked, this, &DevicesPage::testConnection);
    connect(m_form, &SettingsForm::edited, this, &DevicesPage::validateForm);
    connect(m_name, &QLineEdit::textEdited, this, &DevicesPage::validateForm);
    m_testTimer.setInterval(50);
    connect(&m_testTimer, &QTimer::timeout, this, &DevicesPage::pollTest);
    m_refresh.setInterval(500);  // counters change without notifications
    connect(&m_refresh, &QTimer::timeout, this, &DevicesPage::refreshStatus);
    m_refresh.start();
}

void DevicesPage::connectFaultSwitches() {
    auto bindFault = [this](QCheckBox* box, bool devices::FaultSwitches::*flag) {
        connect(box, &QCheckBox::toggled, this, [this, flag](bool on) {
            const runtime::DeviceView* d = selectedDevice();
            if (!d || !d->faults) return;
            devices::FaultSwitches faults = *d->faults;
            faults.*flag = on;
            m_hub->setFaults(d->id, faults);
        });
    };
    bindFault(m_faultSilent, &devices::FaultSwitches::silent);
    bindFault(m_faultNoisy, &devices::FaultSwitches::noisy);
    bindFault(m_faultStuck, &devices::FaultSwitches::stuck);
    bindFault(m_faultMalformed, &devices::FaultSwitches::malformed);
    bindFault(m_faultUnplugged, &devices::FaultSwitches::disconnected);
}

QString DevicesPage::title() const {
    return pageTitle(PageId::Devices);
}

void DevicesPage::buildUi() {
    setStyleSheet(QStringLiteral(
        "QLabel#DeviceStateBadge { font-size: 14pt; font-weight: bold; border-radius: 6px; padding: 6px 14px; "
        "color: #ffffff; background: #6b7785; }"
        "QLabel#DeviceStateBadge[tone=\"ok\"] { background: #2e7d32; }"
        "QLabel#DeviceStateBadge[tone=\"warn\"] { background: #9a5b00; }"
        "QLabel#DeviceStateBadge[tone=\"fault\"] { background: #c62828; }"
        "QLabel#LiveValue { font-size: 24pt; font-weight: bold; color: #1f2a36; }"
        "QLabel#LiveValue[tone=\"stale\"] { color: #8a96a3; }"
        "QLabel#LastError { color: #8e0000; }"
        "QLabel#TestResult { font-size: 14pt; font-weight: bold; }"
        "QLabel#TestResult[tone=\"ok\"] { color: #2e7d32; }"
        "QLabel#TestResult[tone=\"fault\"] { color: #c62828; }"
        "QLabel#TestResult[tone=\"warn\"] { color: #9a5b00; }"
        "QLabel#FormProblems { color: #c62828; font-weight: bold; }"
        "QListWidget#deviceList { font-size: 14pt; }"
        "QGroupBox QCheckBox { min-height: 40px; }"
        "QGroupBox QCheckBox::indicator { width: 26px; height: 26px; }"
        "QListWidget#deviceList::item { min-height: 56px; padding: 4px; }"));
    for (QLabel* title : {m_listTitle, m_detailTitle, m_settingsTitle, m_statsTitle})
        title->setObjectName(QStringLiteral("SectionTitle"));
    m_list->setObjectName(QStringLiteral("deviceList"));
    m_list->setIconSize(QSize(28, 28));
    m_newType->setObjectName(QStringLiteral("newDeviceType"));
    m_newType->view()->setMinimumWidth(520);
    m_add->setObjectName(QStringLiteral("addDevice"));
    m_remove->setObjectName(QStringLiteral("removeDevice"));
    m_remove->setProperty("role", QStringLiteral("danger"));
    m_stateBadge->setObjectName(QStringLiteral("DeviceStateBadge"));
    m_stateMessage->setObjectName(QStringLiteral("stateMessage"));
    m_stateMessage->setWordWrap(true);
    m_live->setObjectName(QStringLiteral("LiveValue"));
    m_live->setWordWrap(true);
    m_lastError->setObjectName(QStringLiteral("LastError"));
    m_lastError->setWordWrap(true);
    m_name->setObjectName(QStringLiteral("deviceName"));
    m_name->setMaxLength(60);
    m_problems->setObjectName(QStringLiteral("FormProblems"));
    m_problems->setWordWrap(true);
    m_test->setObjectName(QStringLiteral("testConnection"));
    m_apply->setObjectName(QStringLiteral("applyDevice"));
    m_apply->setProperty("role", QStringLiteral("primary"));
    m_revert->setObjectName(QStringLiteral("revertDevice"));
    m_testResult->setObjectName(QStringLiteral("TestResult"));
    m_testResult->setWordWrap(true);
    m_stats->setObjectName(QStringLiteral("deviceCounters"));
    m_stats->setTextFormat(Qt::RichText);
    m_stats->setWordWrap(true);
    m_typeText->setWordWrap(true);

    // Left: the instances and adding one.
    auto* left = new QVBoxLayout;
    left->addWidget(m_listTitle);
    left->addWidget(m_list, 1);
    left->addWidget(m_newTypeLabel);
    left->addWidget(m_newType);
    auto* leftButtons = new QHBoxLayout;
    leftButtons->addWidget(m_add, 1);
    leftButtons->addWidget(m_remove, 1);
    left->addLayout(leftButtons);
    auto* leftWidget = new QWidget(this);
    leftWidget->setLayout(left);
    leftWidget->setFixedWidth(380);

    // Right: the selected device.
    auto* detail = new QWidget(this);
    auto* d = new QVBoxLayout(detail);
    d->setContentsMargins(8, 0, 16, 16);
    d->addWidget(m_detailTitle);
    d->addWidget(m_typeText);
    auto* status = new QGridLayout;
    status->setHorizontalSpacing(16);
    status->addWidget(m_stateLabel, 0, 0);
    auto* stateLine = new QHBoxLayout;
    m_stateBadge->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    stateLine->setSpacing(12);
    stateLine->addWidget(m_stateBadge, 0, Qt::AlignTop);
    stateLine->addWidget(m_stateMessage, 1);
    status->addLayout(stateLine, 0, 1);
    status->addWidget(m_liveLabel, 1, 0);
    status->addWidget(m_live, 1, 1);
    status->addWidget(m_lastErrorLabel, 2, 0);
    status->addWidget(m_lastError, 2, 1);
    status->setColumnStretch(1, 1);
    d->addLayout(status);
    d->addSpacing(8);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_test);
    buttons->addWidget(m_apply);
    buttons->addWidget(m_revert);
    buttons->addStretch(1);
    d->addLayout(buttons);
    d->addWidget(m_testResult);
    d->addWidget(m_problems);
    d->addSpacing(8);
    d->addWidget(m_settingsTitle);
    auto* nameLine = new QFormLayout;
    nameLine->setHorizontalSpacing(16);
    nameLine->addRow(m_nameLabel, m_name);
    d->addLayout(nameLine);
    d->addWidget(m_form);
    auto* faults = new QGridLayout(m_faults);
    int slot = 0;
    for (QCheckBox* box : {m_faultSilent, m_faultNoisy, m_faultStuck, m_faultMalformed, m_faultUnplugged}) {
        faults->addWidget(box, slot / 2, slot % 2);
        ++slot;
    }
    d->addWidget(m_faults);
    d->addWidget(m_statsTitle);
    d->addWidget(m_stats);
    d->addStretch(1);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(detail);
    m_detailStack->addWidget(m_empty);
    m_detailStack->addWidget(scroll);

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(24, 16, 8, 8);
    layout->setSpacing(16);
    layout->addWidget(leftWidget);
    layout->addWidget(m_detailStack, 1);
}

QString DevicesPage::typeName(const QString& pluginId, DeviceKind kind) const {
    const devices::DevicePlugin* plugin = m_hub->plugin(pluginId);
    return tr("%1 — %2").arg(devices::kindName(kind), plugin ? plugin->displayName() : pluginId);
}

void DevicesPage::fillTypes() {
    const int current = m_newType->currentIndex();
    m_newType->clear();
    for (DeviceKind kind : devices::allDeviceKinds())
        for (devices::DevicePlugin* plugin : m_hub->plugins())
            if (plugin->kinds().contains(kind))
                m_newType->addItem(typeName(plugin->pluginId(), kind),
                                   QStringList{plugin->pluginId(), devices::kindKey(kind)});
    m_newType->setCurrentIndex(std::max(0, current));
}

void DevicesPage::reloadList() {
    const QString keep = m_selection ? m_selection->deviceId : QString();
    m_list->blockSignals(true);
    m_list->clear();
    for (const QString& id : m_hub->deviceIds()) {
        auto* item = new QListWidgetItem(m_list);
        item->setData(Qt::UserRole, id);
    }
    if (m_selection && m_selection->deviceId.isEmpty()) {
        auto* draft = new QListWidgetItem(m_list);
        draft->setData(Qt::UserRole, QString());
    }
    updateListTones();
    for (int i = 0; i < m_list->count(); ++i)
        if (m_list->item(i)->data(Qt::UserRole).toString() == keep && m_selection) m_list->setCurrentRow(i);
    m_list->blockSignals(false);
    if (m_selection && !m_selection->deviceId.isEmpty() && !m_hub->view(m_selection->deviceId)) {
        m_selection.reset();
        showSelection();
    }
}

void DevicesPage::updateListTones() {
    for (int i = 0; i < m_list->count(); ++i) {
        QListWidgetItem* item = m_list->item(i);
        const QString id = item->data(Qt::UserRole).toString();
        if (id.isEmpty()) {
            item->setText(tr("New: %1\n(not added yet)").arg(devices::kindName(m_selection->kind)));
            item->setIcon(toneIcon(QStringLiteral("idle")));
            continue;
        }
        const runtime::DeviceView* e = m_hub->view(id);
        if (!e) continue;
        const DeviceState state = e->health.state;
        item->setText(QStringLiteral("%1\n%2 · %3").arg(e->name, devices::kindName(e->kind), [&] {
            switch (state) {
                case DeviceState::Ready:
                    return tr("ready");
                case DeviceState::Connecting:
                    return tr("connecting");
                case DeviceState::Error:
                    return tr("error");
                case DeviceState::Disconnected:
                    break;
            }
            return tr("closed");
        }()));
        item->setIcon(toneIcon(toneOf(state)));
    }
}

const runtime::DeviceView* DevicesPage::selectedDevice() const {
    if (!m_selection || m_selection->deviceId.isEmpty()) return nullptr;
    return m_hub->view(m_selection->deviceId);
}

void DevicesPage::selectDevice(const QString& id) {
    const runtime::DeviceView* e = m_hub->view(id);
    if (!e) return;
    const bool hadDraft = m_selection && m_selection->deviceId.isEmpty();
    m_selection = Selection{id, e->pluginId, e->kind};
    m_savedValues = e->settings;
    m_savedName = e->name;
    if (hadDraft) reloadList();
    showSelection();
}

void DevicesPage::startDraft() {
    const QStringList type = m_newType->currentData().toStringList();
    if (type.size() != 2) return;
    const auto kind = devices::kindFromKey(type[1]);
    if (!kind) return;
    m_selection = Selection{QString(), type[0], *kind};
    m_savedValues.clear();
    m_savedName = devices::kindName(*kind);
    reloadList();
    m_list->setCurrentRow(m_list->count() - 1);
    showSelection();
}

void DevicesPage::showSelection() {
    m_testTimer.stop();
    m_testResult->clear();
    m_testResult->hide();
    m_problems->clear();
    m_problems->hide();
    if (!m_selection) {
        m_detailStack->setCurrentIndex(0);
        m_remove->setEnabled(false);
        return;
    }
    m_detailStack->setCurrentIndex(1);
    m_remove->setEnabled(true);
    const devices::DevicePlugin* plugin = m_hub->plugin(m_selection->pluginId);
    m_form->setSchema(plugin ? plugin->settingsSchema(m_selection->kind) : devices::SettingsSchema{}, m_savedValues);
    m_name->setText(m_savedName);
    m_typeText->setText(typeName(m_selection->pluginId, m_selection->kind));
    const runtime::DeviceView* device = selectedDevice();
    m_faults->setVisible(device && device->faults);
    if (device && device->faults) {
        const devices::FaultSwitches f = *device->faults;
        const QList<std::pair<QCheckBox*, bool>> boxes{{m_faultSilent, f.silent},
                                                       {m_faultNoisy, f.noisy},
                                                       {m_faultStuck, f.stuck},
                                                       {m_faultMalformed, f.malformed},
                                                       {m_faultUnplugged, f.disconnected}};
        for (const auto& [box, on] : boxes) {
            const QSignalBlocker block(box);
            box->setChecked(on);
        }
    }
    retranslate();
    validateForm();
}

void DevicesPage::validateForm() {
    if (!m_selection) return;
    const devices::DevicePlugin* plugin = m_hub->plugin(m_selection->pluginId);
    if (!plugin) return;
    const QList<devices::SettingIssue> issues =
        plugin->validate(m_selection->kind, m_form->values(), devices::Validation::Full);
    m_form->showIssues(issues);
    m_problems->setText(issues.isEmpty() ? QString()
                                         : tr("Settings to correct: %1 (marked in red).").arg(issues.size()));
    m_problems->setVisible(!issues.isEmpty());
    const bool edited =
        m_form->values() != devices::withDefaults(plugin->settingsSchema(m_selection->kind), m_savedValues) ||
        m_name->text().trimmed() != m_savedName;
    m_apply->setEnabled(issues.isEmpty() && (edited || m_selection->deviceId.isEmpty()));
    m_revert->setEnabled(edited);
}

QString DevicesPage::unappliedEdits() const {
    return m_selection && m_revert->isEnabled() ? tr("changed settings of a device on the Devices page") : QString();
}

void DevicesPage::apply() {
    if (!m_selection) return;
    const QVariantMap values = m_form->values();
    // Device settings are the engineer's (enforced here and audited with old and new values).
    AuditTrail trail(context());
    QVariantMap before = m_selection->deviceId.isEmpty() ? QVariantMap() : m_savedValues;
    if (!m_selection->deviceId.isEmpty()) before.insert(QStringLiteral("name"), m_savedName);
    QVariantMap after = values;
    after.insert(QStringLiteral("name"), m_name->text());
    try {
        trail.require(core::auth::Permission::EditSettings);
        if (m_selection->deviceId.isEmpty()) {
            const QString id = m_hub->addDevice(m_selection->pluginId, m_selection->kind, m_name->text(), values);
            m_selection->deviceId = id;
            reloadList();
            selectDevice(id);
        } else {
            m_hub->updateDevice(m_selection->deviceId, m_name->text(), values);
            selectDevice(m_selection->deviceId);
        }
    } catch (const std::exception& e) {  // a refused value, or a role without EditSettings
        m_problems->setText(QString::fromStdString(e.what()));
        m_problems->setVisible(true);
        return;
    }
    trail.recordValues(QStringLiteral("setting"), QStringLiteral("device ") + m_selection->deviceId, before, after);
    if (const runtime::DeviceView* d = selectedDevice()) m_hub->open(d->id);
    saveSettings();
    refreshStatus();
}

void DevicesPage::revert() {
    if (!m_selection) return;
    m_form->setValues(m_savedValues);
    m_name->setText(m_savedName);
    validateForm();
}

void DevicesPage::removeSelected() {
    if (!m_selection) return;
    if (m_selection->deviceId.isEmpty()) {
        m_selection.reset();
        reloadList();
        showSelection();
        return;
    }
    const runtime::DeviceView* view = m_hub->view(m_selection->deviceId);
    if (!view) return;
    const runtime::DeviceView e = *view;  // the snapshot may be replaced while the question is asked
    AuditTrail trail(context());
    try {
        trail.require(core::auth::Permission::EditSettings);
    } catch (const std::exception& refused) {
        m_problems->setText(QString::fromStdString(refused.what()));
        m_problems->setVisible(true);
        return;
    }
    QVariantMap before = e.settings;
    before.insert(QStringLiteral("name"), e.name);
    if (context().prompt &&
        context().prompt->ask(this, tr("Remove device"),
                              tr("Remove %1? Its settings are deleted; the loop can no longer use it.").arg(e.name)) !=
            Prompt::Answer::Yes)
        return;
    const QString id = m_selection->deviceId;
    m_selection.reset();
    m_hub->removeDevice(id);
    trail.recordValues(QStringLiteral("setting"), QStringLiteral("device ") + id, before, {});
    saveSettings();
    if (m_list->count() > 0) m_list->setCurrentRow(0);
    showSelection();
}

void DevicesPage::testConnection() {
    if (!m_selection) return;
    devices::DevicePlugin* plugin = m_hub->plugin(m_selection->pluginId);
    if (!plugin) return;
    const QVariantMap values = m_form->values();
    const QList<devices::SettingIssue> issues = plugin->validate(m_selection->kind, values, devices::Validation::Full);
    if (!issues.isEmpty()) {
        m_form->showIssues(issues);
        setTone(m_testResult, QStringLiteral("fault"));
        m_testResult->setText(tr("Not tested: correct the settings marked in red first."));
        m_testResult->show();
        return;
    }
    const runtime::DeviceView* live = selectedDevice();
    const QVariantMap saved = devices::withDefaults(plugin->settingsSchema(m_selection->kind), m_savedValues);
    if (const QString refusal = testRefusedByTheLoop(live && values == saved); !refusal.isEmpty()) {
        setTone(m_testResult, QStringLiteral("fault"));
        m_testResult->setText(refusal);
        m_testResult->show();
        return;
    }
    endTest();
    if (live && values == saved) {
        m_testTarget = live->id;  // the device as it runs
    } else {
        // The settings as typed, on a trial instance of their own; the running one lets go of the port.
        try {
            m_hub->startTrial(m_selection->pluginId, m_selection->kind, values, live ? live->id : QString());
        } catch (const std::invalid_argument& e) {
            finishTest(false, QString::fromStdString(e.what()));
            return;
        }
        m_testTarget = runtime::kTrialDeviceId;
    }
    setTone(m_testResult, QStringLiteral("warn"));
    m_testResult->setText(tr("Testing the connection…"));
    m_testResult->show();
    m_test->setEnabled(false);
    const runtime::DeviceView* target = m_hub->view(m_testTarget);
    m_testStartValue = target ? target->liveValue : QString();
    m_hub->testConnection(m_testTarget);
    m_testClock.start();
    m_testTimer.start();
}

void DevicesPage::endTest() {
    if (m_testTarget == runtime::kTrialDeviceId) m_hub->endTrial();
    m_testTarget.clear();
}

QString DevicesPage::testRefusedByTheLoop(bool testsTheRunningDevice) const {
    const AppState* state = context().state;
    if (!state || (state->loop() != AppState::Loop::Running && state->loop() != AppState::Loop::Paused)) return {};
    // A gauge's test reading would be taken as the next part's diameter; other settings than
    // the saved ones close the device the run is using.
    if (m_selection->kind == DeviceKind::Gauge)
        return tr(
            "Not tested: a run is going on the Run page and would take the test reading as a diameter. "
            "Stop the run first.");
    if (!testsTheRunningDevice)
        return tr(
            "Not tested: a run is going on the Run page and these settings would close the device it uses. "
            "Stop the run first, or test with the applied settings.");
    return {};
}

void DevicesPage::pollTest() {
    const runtime::DeviceView* target = m_testTarget.isEmpty() ? nullptr : m_hub->view(m_testTarget);
    if (!target) return;
    const core::DeviceHealth h = target->health;
    const QString message = QString::fromStdString(h.message);
    const QString value = target->liveValue;
    if (h.state == DeviceState::Error) {
        finishTest(false, tr("No connection: %1").arg(message));
    } else if (h.state == DeviceState::Ready &&
               ((!value.isEmpty() && value != m_testStartValue) || m_testClock.elapsed() > kPushGaugeSettleMs)) {
        finishTest(true, value.isEmpty() ? tr("Connected: %1").arg(message) : tr("Connected — %1").arg(value));
    } else if (m_testClock.elapsed() > kTestTimeoutMs) {
        finishTest(false, tr("No answer within %1 s: %2").arg(kTestTimeoutMs / 1000).arg(message));
    }
}

void DevicesPage::finishTest(bool ok, const QString& text) {
    m_testTimer.stop();
    m_test->setEnabled(true);
    setTone(m_testResult, ok ? QStringLiteral("ok") : QStringLiteral("fault"));
    m_testResult->setText(text);
    m_testResult->show();
    endTest();
}

void DevicesPage::refreshStatus() {
    const runtime::DeviceView* device = selectedDevice();
    if (!device) {
        setTone(m_stateBadge, QStringLiteral("idle"));
        m_stateBadge->setText(m_selection ? tr("Not added") : QString());
        m_stateMessage->setText(m_selection ? tr("Fill in the settings, test the connection, then add the device.")
                                            : QString());
        m_live->setText(QStringLiteral("—"));
        m_lastError->setText(tr("none"));
        m_stats->clear();
        m_statsTitle->setVisible(false);
        return;
    }
    const core::DeviceHealth h = device->health;
    setTone(m_stateBadge, toneOf(h.state));
    switch (h.state) {
        case DeviceState::Ready:
            m_stateBadge->setText(tr("Ready"));
            break;
        case DeviceState::Connecting:
            m_stateBadge->setText(tr("Connecting"));
            break;
        case DeviceState::Error:
            m_stateBadge->setText(tr("Error"));
            break;
        case DeviceState::Disconnected:
            m_stateBadge->setText(tr("Closed"));
            break;
    }
    m_stateMessage->setText(QString::fromStdString(h.message));
    // A "Connected" from an earlier test is stale once the device is not ready (unplugged, refused).
    if (m_testTarget.isEmpty() && h.state != DeviceState::Ready && m_testResult->property("tone").toString() == u"ok")
        m_testResult->hide();
    const QString value = device->liveValue;
    setTone(m_live, h.state == DeviceState::Ready ? QStringLiteral("ok") : QStringLiteral("stale"));
    m_live->setText(value.isEmpty()                 ? QStringLiteral("—")
                    : h.state == DeviceState::Ready ? value
                                                    : tr("%1 (last value)").arg(value));
    m_lastError->setText(device->lastError.isEmpty() ? tr("none") : device->lastError);
    QString table = QStringLiteral("<table cellspacing='0' cellpadding='3'>");
    for (const devices::DeviceStatistic& s : device->statistics)
        table += QStringLiteral("<tr><td>%1</td><td align='right'><b>%2</b></td></tr>")
                     .arg(s.label.toHtmlEscaped(), s.value.toHtmlEscaped());
    table += QStringLiteral("</table>");
    m_stats->setText(table);
    m_statsTitle->setVisible(!device->statistics.isEmpty());
}

void DevicesPage::saveSettings() {
    QSettings settings;
    m_hub->save(settings);
}

void DevicesPage::retranslate() {
    m_listTitle->setText(tr("Device instances"));
    m_newTypeLabel->setText(tr("Add a device of type"));
    m_add->setText(tr("Add"));
    m_remove->setText(tr("Remove"));
    m_empty->setTexts(tr("No device selected"),
                      tr("Add a gauge micrometer, probe mandrel, drive-current readout or correction output to the "
                         "CNC. The built-in simulator provides every kind, with fault switches."));
    m_stateLabel->setText(tr("State"));
    m_liveLabel->setText(tr("Live value"));
    m_lastErrorLabel->setText(tr("Last error"));
    m_nameLabel->setText(tr("Name"));
    m_settingsTitle->setText(tr("Settings"));
    m_test->setText(tr("Test connection"));
    m_apply->setText(m_selection && m_selection->deviceId.isEmpty() ? tr("Add device") : tr("Apply"));
    m_revert->setText(tr("Revert"));
    m_faults->setTitle(tr("Simulator fault switches"));
    m_faultSilent->setText(tr("Silent"));
    m_faultNoisy->setText(tr("Noisy"));
    m_faultStuck->setText(tr("Stuck value"));
    m_faultMalformed->setText(tr("Malformed frames"));
    m_faultUnplugged->setText(tr("Unplugged"));
    m_statsTitle->setText(tr("Counters"));
    m_detailTitle->setText(m_selection ? (m_name->text().isEmpty() ? m_savedName : m_name->text()) : QString());
    fillTypes();
    updateListTones();
    refreshStatus();
    // The plugins' texts come translated when asked for: the schema again for the form (what is
    // typed stays), the type line, the form's messages and the status bar's device summary.
    if (m_selection) {
        if (const devices::DevicePlugin* plugin = m_hub->plugin(m_selection->pluginId)) {
            m_form->setTexts(plugin->settingsSchema(m_selection->kind));
            m_typeText->setText(typeName(m_selection->pluginId, m_selection->kind));
            validateForm();
        }
    }
    if (m_bridge) m_bridge->update();
}

}  // namespace tt::ui
