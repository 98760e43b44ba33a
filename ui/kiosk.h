#pragma once

class QWidget;

namespace tt::ui {

class Prompt;

/// The one gate before the terminal quits in kiosk mode (`trueturn --kiosk`): true when an engineer
/// allows it. Today it asks for a confirmation through `prompt` (no prompt: refused); the log-in with
/// roles plugs in here, so every way to quit in kiosk mode goes through this function.
bool engineerMayQuit(QWidget* parent, Prompt* prompt);

/// Shows `window` as a kiosk: full screen, no window decorations (title bar, close button).
void showAsKiosk(QWidget* window);

}  // namespace tt::ui
