#include "ui/kiosk.h"

#include <QCoreApplication>
#include <QWidget>

#include "ui/prompt.h"

namespace tt::ui {

bool engineerMayQuit(QWidget* parent, Prompt* prompt) {
    if (!prompt) return false;
    const QString title = QCoreApplication::translate("tt::ui::Kiosk", "Quit the terminal");
    const QString question = QCoreApplication::translate(
        "tt::ui::Kiosk",
        "This terminal runs in kiosk mode: only an engineer may quit it.\n\nAre you an engineer, and do you want "
        "to quit TrueTurn?");
    return prompt->ask(parent, title, question) == Prompt::Answer::Yes;
}

void showAsKiosk(QWidget* window) {
    window->setWindowFlags(window->windowFlags() | Qt::FramelessWindowHint);
    window->showFullScreen();
}

}  // namespace tt::ui
