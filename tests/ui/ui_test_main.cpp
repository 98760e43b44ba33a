// UI test main: a QApplication on the offscreen platform with the operator style, QSettings
// and QStandardPaths in a throw-away location, so tests never block and never touch user data.
#include <gtest/gtest.h>

#include <QApplication>
#include <QStandardPaths>
#include <QTemporaryDir>

#include "ui/style.h"

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QTemporaryDir home;
    qputenv("XDG_CONFIG_HOME", home.filePath(QStringLiteral("config")).toUtf8());
    qputenv("XDG_DATA_HOME", home.filePath(QStringLiteral("data")).toUtf8());
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("TrueTurnTests"));
    QApplication::setApplicationName(QStringLiteral("TrueTurnUiTests"));
    QStandardPaths::setTestModeEnabled(true);
    tt::ui::applyOperatorStyle(app);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
