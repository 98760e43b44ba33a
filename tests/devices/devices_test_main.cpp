// Device test main: a QCoreApplication (serial ports, Modbus and timers need an event loop),
// QSettings in a throw-away location, so tests never touch user data.
#include <gtest/gtest.h>

#include "devices/simulator/simulator_registration.h"
#include "tests/support/isolated_home.h"

#include <QCoreApplication>

int main(int argc, char** argv) {
    const tt::test::IsolatedHome home;
    QCoreApplication app(argc, argv);
    tt::devices::registerBuiltInSimulator();  // the built-in simulator, found like any plugin
    QCoreApplication::setOrganizationName(QStringLiteral("TrueTurnTests"));
    QCoreApplication::setApplicationName(QStringLiteral("TrueTurnDeviceTests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
