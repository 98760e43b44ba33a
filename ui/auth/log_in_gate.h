#pragma once

class QWidget;

namespace tt::ui {

struct AppContext;

/// Before the main window is shown: the first-start dialog when the database has no user yet, the
/// log-in dialog otherwise (`context.session` required). Returns false when the person chose Quit.
/// When the database cannot be opened nobody is logged in and true is returned: the stores are then
/// missing, so nothing can be changed (the history check at start tells why).
bool logInAtStart(AppContext& context, QWidget* parent = nullptr);

/// From now on, whenever the session logs out (idle time, or Log out on the Settings page), the log-in
/// dialog covers `window` until someone logs in (no Quit: the kiosk stays locked).
void logInAgainAfterLogOut(AppContext& context, QWidget* window);

}  // namespace tt::ui
