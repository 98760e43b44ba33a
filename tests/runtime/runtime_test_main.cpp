// The runtime tests run with a QCoreApplication (the device thread's hub and the loop's session need an event
// loop) and a settings folder of their own.
#include <gtest/gtest.h>

#include <QCoreApplication>

#include "tests/support/isolated_home.h"

int main(int argc, char** argv) {
    tt::test::IsolatedHome home;
    QCoreApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("TrueTurnTests"));
    QCoreApplication::setApplicationName(QStringLiteral("runtime"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
