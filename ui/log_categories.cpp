#include "ui/log_categories.h"

Q_LOGGING_CATEGORY(lcUi, "trueturn.ui", QtWarningMsg)
Q_LOGGING_CATEGORY(lcLoop, "trueturn.loop", QtWarningMsg)
