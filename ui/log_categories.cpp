#include "ui/log_categories.h"

Q_LOGGING_CATEGORY(lcUi, "trueturn.ui", QtWarningMsg)
