#include "core/storage/storage_log.h"

Q_LOGGING_CATEGORY(lcStorage, "trueturn.storage", QtWarningMsg)
