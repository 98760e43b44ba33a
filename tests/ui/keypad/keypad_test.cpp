// The on-screen numeric keypad (issue 17, item 7): it opens for a number field on a touch, or on a click
// with View > On-screen keypad on; its keys type the number, it shows the field's unit and limits, refuses
// a number outside them and writes an accepted one into the field. Screenshot:
// screenshots/terminal_keypad_<en|ru>.png.
#include <QAction>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPointingDevice>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

#include "screenshots.h"
#include "support/terminal_window.h"
#include "ui/keypad.h"

namespace tt::ui {
namespace {

using Keypad = test::TerminalWindowTest;

void clickKey(NumericKeypad* keypad, const char* name) {
    auto* key = keypad->findChild<QPushButton*>(QString::fromLatin1(name));
    ASSERT_NE(key, nullptr) << name;
    ASSERT_TRUE(key->isEnabled()) << name;
    key->click();
}

TEST_F(Keypad, TypesADoubleWithSignAndPointWithinTheLimits) {
    QDoubleSpinBox field;
    field.setRange(-5.0, 12.5);
    field.setDecimals(2);
    field.setSuffix(QStringLiteral(" mm"));
    field.setValue(1.0);
    NumericKeypad keypad(&field);
    keypad.show();
    EXPECT_EQ(keypad.findChild<QLabel*>(QStringLiteral("keypadLimits"))->text(),
              QStringLiteral("Limits: -5.00 … 12.50 mm"));
    clickKey(&keypad, "keyClear");
    for (const char* k : {"key1", "key3", "keyPoint", "key2", "key5", "key7"})  // the third decimal is refused
        clickKey(&keypad, k);
    EXPECT_EQ(keypad.typed(), QStringLiteral("13.25"));
    EXPECT_FALSE(keypad.value().has_value()) << "13.25 mm is above 12.5 mm";
    keypad.accept();
    EXPECT_TRUE(keypad.isVisible()) << "stays open with the reason";
    EXPECT_TRUE(keypad.findChild<QLabel*>(QStringLiteral("keypadProblem"))->text().contains(QStringLiteral("outside")));
    EXPECT_DOUBLE_EQ(field.value(), 1.0) << "the field keeps its value";
    clickKey(&keypad, "keyBack");
    clickKey(&keypad, "keyBack");
    clickKey(&keypad, "keyBack");
    clickKey(&keypad, "keySign");
    EXPECT_EQ(keypad.typed(), QStringLiteral("-13"));
    clickKey(&keypad, "keyBack");
    EXPECT_EQ(keypad.typed(), QStringLiteral("-1"));
    ASSERT_TRUE(keypad.value().has_value());
    EXPECT_DOUBLE_EQ(*keypad.value(), -1.0);
    QSignalSpy finished(&field, &QAbstractSpinBox::editingFinished);
    clickKey(&keypad, "keyOk");
    EXPECT_FALSE(keypad.isVisible());
    EXPECT_DOUBLE_EQ(field.value(), -1.0);
    EXPECT_EQ(finished.count(), 1) << "the page reacts as to a typed value";
}

TEST_F(Keypad, AnIntegerFieldWithoutNegativesHasNoSignOrPoint) {
    QSpinBox field;
    field.setRange(1, 8);
    field.setValue(2);
    NumericKeypad keypad(&field);
    EXPECT_FALSE(keypad.findChild<QPushButton*>(QStringLiteral("keySign"))->isEnabled());
    EXPECT_FALSE(keypad.findChild<QPushButton*>(QStringLiteral("keyPoint"))->isEnabled());
    keypad.press(QStringLiteral("."));
    keypad.press(QStringLiteral("+/-"));
    EXPECT_EQ(keypad.typed(), QStringLiteral("2"));
    keypad.press(QStringLiteral("clear"));
    keypad.accept();
    EXPECT_TRUE(keypad.findChild<QLabel*>(QStringLiteral("keypadProblem"))->text().contains(QStringLiteral("number")));
    keypad.press(QStringLiteral("5"));
    keypad.accept();
    EXPECT_EQ(field.value(), 5);
}

TEST_F(Keypad, OpensFromTheWindowWithTheSettingOrOnATouch) {
    auto window = openWindow();
    window->showPage(PageId::Run);
    auto* delay = window->findChild<QSpinBox*>(QStringLiteral("delaySpin"));
    ASSERT_NE(delay, nullptr);
    KeypadLauncher* launcher = window->keypad();
    ASSERT_NE(launcher, nullptr);
    QSignalSpy opened(launcher, &KeypadLauncher::keypadOpened);
    QLineEdit* edit = delay->findChild<QLineEdit*>();
    ASSERT_NE(edit, nullptr);
    // A mouse click with the setting off: the field is typed into as usual.
    QTest::mouseClick(edit, Qt::LeftButton);
    EXPECT_EQ(opened.count(), 0);
    // A touch: the mouse release Qt synthesises from a finger on a touch screen.
    static QPointingDevice* screen = QTest::createTouchDevice(QInputDevice::DeviceType::TouchScreen);
    QMouseEvent touch(QEvent::MouseButtonRelease, QPointF(5, 5), edit->mapToGlobal(QPointF(5, 5)), Qt::LeftButton,
                      Qt::NoButton, Qt::NoModifier, screen);
    QApplication::sendEvent(edit, &touch);
    ASSERT_EQ(opened.count(), 1);
    launcher->openKeypad()->reject();
    QApplication::processEvents();
    // View > On-screen keypad: every click on a number field opens it; the setting is kept.
    auto* action = window->findChild<QAction*>(QStringLiteral("keypadAction"));
    ASSERT_NE(action, nullptr);
    action->setChecked(true);
    EXPECT_TRUE(QSettings().value(QStringLiteral("ui/onScreenKeypad")).toBool());
    QTest::mouseClick(edit, Qt::LeftButton);
    ASSERT_EQ(opened.count(), 2);
    NumericKeypad* keypad = launcher->openKeypad();
    ASSERT_NE(keypad, nullptr);
    EXPECT_TRUE(keypad->limitsText().contains(QStringLiteral("1 … 8"))) << keypad->limitsText().toStdString();
    keypad->press(QStringLiteral("clear"));
    keypad->press(QStringLiteral("4"));
    QApplication::processEvents();
    EXPECT_TRUE(test::saveScreenshot(*keypad, QStringLiteral("terminal_keypad_en")));
    keypad->accept();
    EXPECT_EQ(delay->value(), 4);
    // In Russian, with a decimal field of the process tools: the keypad speaks Russian.
    ASSERT_TRUE(language.apply(QStringLiteral("ru")));
    QDoubleSpinBox field;
    field.setRange(0.0, 0.5);
    field.setDecimals(3);
    field.setSuffix(QStringLiteral(" мм/об"));
    NumericKeypad russian(&field);
    russian.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&russian));
    russian.adjustSize();
    EXPECT_TRUE(russian.limitsText().startsWith(QStringLiteral("Пределы"))) << russian.limitsText().toStdString();
    EXPECT_TRUE(test::saveScreenshot(russian, QStringLiteral("terminal_keypad_ru")));
}

}  // namespace
}  // namespace tt::ui
