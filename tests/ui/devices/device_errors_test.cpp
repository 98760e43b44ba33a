// The Devices page tells the truth about a device's errors (issue 17, item 10): a Modbus drive whose
// connection is refused shows the reason as its last error (not "none"), and a simulated device unplugged
// after a successful test no longer says "Connected" anywhere on the page.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
#include <QCheckBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTest>

#include "runtime/devices/device_hub.h"
#include "screenshots.h"
#include "support/terminal_window.h"
#include "tests/support/patient_wait.h"
#include "ui/pages/devices_page.h"

namespace tt::ui {
namespace {

using DeviceErrors = test::TerminalWindowTest;

/// Selects the device in the page's list, as the operator does.
void select(MainWindow& window, const QString& id) {
    auto* list = window.findChild<QListWidget*>(QStringLiteral("deviceList"));
    ASSERT_NE(list, nullptr);
    for (int row = 0; row < list->count(); ++row)
        if (list->item(row)->data(Qt::UserRole).toString() == id) list->setCurrentRow(row);
    ASSERT_EQ(list->currentItem()->data(Qt::UserRole).toString(), id);
}

QStringList visibleTexts(QWidget* root) {
    QStringList texts;
    for (QLabel* l : root->findChildren<QLabel*>())
        if (l->isVisible()) texts << l->text();
    return texts;
}

TEST_F(DeviceErrors, ARefusedModbusConnectionIsTheLastError) {
    // A port nobody listens on: a free one the kernel gives a bound socket, closed again.
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    ASSERT_GE(fd, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    socklen_t length = sizeof address;
    ASSERT_EQ(::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length), 0);
    const int port = ntohs(address.sin_port);
    ::close(fd);
    runtime::DeviceHub& manager = devices->hub();
    const QString id =
        manager.addDevice(QStringLiteral("modbus"), devices::DeviceKind::DriveCurrent, QStringLiteral("Spindle drive"),
                          {{QStringLiteral("transport"), QStringLiteral("tcp")},
                           {QStringLiteral("host"), QStringLiteral("127.0.0.1")},
                           {QStringLiteral("tcpPort"), port}});
    manager.open(id);
    auto window = openWindow();
    window->showPage(PageId::Devices);
    select(*window, id);
    ASSERT_TRUE(QTest::qWaitFor([&] { return manager.view(id)->health.state == core::DeviceState::Error; }, tt::test::kPatientWaitMs))
        << manager.view(id)->health.message;
    QApplication::processEvents();
    auto* lastError = window->findChild<QLabel*>(QStringLiteral("LastError"));
    ASSERT_NE(lastError, nullptr);
    EXPECT_NE(lastError->text(), QStringLiteral("none"));
    EXPECT_EQ(lastError->text(), QString::fromStdString(manager.view(id)->health.message));
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("terminal_devices_modbus_refused")));
}

TEST_F(DeviceErrors, AnUnpluggedSimulatorNoLongerSaysConnected) {
    runtime::DeviceHub& manager = devices->hub();
    const QString id = manager.devicesOfKind(devices::DeviceKind::Gauge).value(0);
    ASSERT_FALSE(id.isEmpty()) << "the first start's simulated gauge";
    auto window = openWindow();
    window->showPage(PageId::Devices);
    auto* page = static_cast<DevicesPage*>(window->page(PageId::Devices));
    select(*window, id);
    ASSERT_TRUE(QTest::qWaitFor([&] { return manager.view(id)->health.state == core::DeviceState::Ready; }, tt::test::kPatientWaitMs));
    window->findChild<QPushButton*>(QStringLiteral("testConnection"))->click();
    auto* result = window->findChild<QLabel*>(QStringLiteral("TestResult"));
    ASSERT_NE(result, nullptr);
    ASSERT_TRUE(QTest::qWaitFor([&] { return result->text().startsWith(QStringLiteral("Connected")); },
                                tt::test::kPatientWaitMs))
        << result->text().toStdString();
    QCheckBox* unplug = nullptr;
    for (QCheckBox* box : page->findChildren<QCheckBox*>())
        if (box->text() == QStringLiteral("Unplugged")) unplug = box;
    ASSERT_NE(unplug, nullptr);
    unplug->click();
    ASSERT_TRUE(QTest::qWaitFor([&] { return manager.view(id)->health.state == core::DeviceState::Error; }, tt::test::kPatientWaitMs));
    QApplication::processEvents();
    for (const QString& text : visibleTexts(page))
        EXPECT_FALSE(text.startsWith(QStringLiteral("Connected"))) << text.toStdString();
    EXPECT_TRUE(window->findChild<QLabel*>(QStringLiteral("LastError"))->text().contains(QStringLiteral("unplugged")));
    EXPECT_TRUE(test::saveScreenshot(*window, QStringLiteral("terminal_devices_unplugged")));
}

}  // namespace
}  // namespace tt::ui
