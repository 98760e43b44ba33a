#include "runtime/log_categories.h"

Q_LOGGING_CATEGORY(lcLoop, "trueturn.loop", QtWarningMsg)
Q_LOGGING_CATEGORY(lcRuntime, "trueturn.runtime", QtWarningMsg)
