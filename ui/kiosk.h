#pragma once

class QWidget;

namespace tt::ui {

class Prompt;
struct AppContext;

/// The one gate before the terminal quits in kiosk mode (`trueturn --kiosk`): true when an engineer
/// allows it. Today it asks for a confirmation through `prompt` (no prompt: refused); the log-in with
/// roles plugs in here, so every way to quit in kiosk mode goes through this function.
bool engineerMayQuit(QWidget* parent, Prompt* prompt);

/// The kiosk's gate with users and roles: an engineer (or administrator) logged in confirms through
/// `context.prompt`; anyone else is asked to log in as one first (ui/auth/login_dialog.h: the engineer then
/// stays logged in), and Cancel keeps the terminal running. Without a session (tests that log nobody in)
/// it is the confirmation above.
bool engineerMayQuit(AppContext& context, QWidget* parent);

/// Shows `window` as a kiosk: full screen, no window decorations (title bar, close button).
void showAsKiosk(QWidget* window);

}  // namespace tt::ui
