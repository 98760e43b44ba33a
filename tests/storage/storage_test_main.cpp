// Storage tests run inside a QCoreApplication with QStandardPaths in test mode, so they never
// touch the user's real data folder.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QStandardPaths>

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("TrueTurnTests"));
    QCoreApplication::setApplicationName(QStringLiteral("TrueTurnStorageTests"));
    QStandardPaths::setTestModeEnabled(true);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
