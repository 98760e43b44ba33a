#pragma once

#include <gtest/gtest.h>

#include <QSettings>
#include <QTemporaryDir>
#include <memory>

#include "scripted_prompt.h"
#include "ui/app_state.h"
#include "runtime/devices/terminal_devices.h"
#include "ui/language.h"
#include "ui/main_window.h"

namespace tt::ui::test {

/// The operator terminal as app/gui.cpp makes it: the devices of a first start (the built-in
/// simulators, TerminalDevices over the build's plugin folder), a scratch history, a scripted prompt.
/// Settings start empty; the language is English again after each test.
class TerminalWindowTest : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().clear();
        devices = std::make_unique<runtime::TerminalDevices>(QStringLiteral(TRUETURN_BINARY_DIR "/lib/trueturn/plugins"));
        context =
            AppContext{&prompt, &state, &language, dir.filePath(QStringLiteral("history.sqlite")), &devices->hub()};
    }
    void TearDown() override { language.apply(QStringLiteral("en")); }

    /// A window of the terminal's size (1280 x 800), shown.
    std::unique_ptr<MainWindow> openWindow() {
        auto window = std::make_unique<MainWindow>(context);
        window->resize(1280, 800);
        window->show();
        return window;
    }

    QTemporaryDir dir;
    ScriptedPrompt prompt;
    AppState state;
    LanguageSwitcher language;
    std::unique_ptr<runtime::TerminalDevices> devices;
    AppContext context;
};

}  // namespace tt::ui::test
