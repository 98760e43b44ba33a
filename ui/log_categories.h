#pragma once

#include <QLoggingCategory>

/// The window: pages shown, language, prompts ("trueturn.ui").
Q_DECLARE_LOGGING_CATEGORY(lcUi)
