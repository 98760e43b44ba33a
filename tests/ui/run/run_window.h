#pragma once

#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTest>
#include <functional>

#include "runtime/devices/device_hub.h"
#include "scripted_prompt.h"
#include "tests/support/patient_wait.h"
#include "ui/app_state.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/pages/run_page.h"

namespace tt::ui::test {

/// The services of a main window for the Run page tests: a scratch history, a scripted prompt, the
/// device manager with the built-in simulator.
class RunWindowTest : public ::testing::Test {
protected:
    /// The window at 1280 x 800 showing the Run page; the page, or null.
    RunPage* showRunPage(MainWindow& window) {
        window.resize(1280, 800);
        window.show();
        window.showPage(PageId::Run);
        return qobject_cast<RunPage*>(window.page(PageId::Run));
    }

    QTemporaryDir dir;
    ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    runtime::DeviceHub devices;
    AppContext context{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite")), &devices};
};

/// Serves the event loop until `done` holds (true) or `timeoutMs` has passed (false).
inline bool waitFor(const std::function<bool()>& done, int timeoutMs = tt::test::kPatientWaitMs) {
    QElapsedTimer timer;
    timer.start();
    while (!done()) {
        if (timer.elapsed() > timeoutMs) return false;
        QTest::qWait(20);
    }
    return true;
}

/// Types `text` into `field` as the operator does and presses Enter.
inline void typeAndEnter(QLineEdit* field, const QString& text) {
    field->setFocus();
    field->selectAll();
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Return);
}

}  // namespace tt::ui::test
