#pragma once

#include <QLoggingCategory>

/// The window: pages shown, language, prompts ("trueturn.ui").
Q_DECLARE_LOGGING_CATEGORY(lcUi)
/// The closed loops run from the GUI: starts, stops, states and alarms ("trueturn.loop").
Q_DECLARE_LOGGING_CATEGORY(lcLoop)
