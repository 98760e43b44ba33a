// UI test main: a QApplication on the offscreen platform with the operator style, QSettings
// and QStandardPaths in a throw-away location, so tests never block and never touch user data.
#include <gtest/gtest.h>

#include "tests/support/isolated_home.h"

#include <QApplication>

#include "ui/style.h"

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    const tt::test::IsolatedHome home;
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("TrueTurnTests"));
    QApplication::setApplicationName(QStringLiteral("TrueTurnUiTests"));
    tt::ui::applyOperatorStyle(app);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
