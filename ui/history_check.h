#pragma once

class QWidget;

namespace tt::ui {

struct AppContext;
class Prompt;

/// Opens the run history named by the context (SQLite file or PostgreSQL URL) when the terminal
/// starts and brings its schema up to date, so a damaged, foreign or unreachable database is
/// reported at once (status bar, and a warning through `prompt` when one is given) instead of
/// when the first part is stored. The file is never changed when it cannot be used. Returns
/// whether the history is usable.
bool checkHistoryAtStart(AppContext& context, QWidget* parent, Prompt* prompt);

}  // namespace tt::ui
