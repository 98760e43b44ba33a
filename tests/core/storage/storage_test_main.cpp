// Storage tests run inside a QCoreApplication with settings and data in a throw-away folder, so
// they never touch the user's real data folder.
#include <gtest/gtest.h>

#include "tests/support/isolated_home.h"

#include <QCoreApplication>

int main(int argc, char** argv) {
    const tt::test::IsolatedHome home;
    QCoreApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("TrueTurnTests"));
    QCoreApplication::setApplicationName(QStringLiteral("TrueTurnStorageTests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
