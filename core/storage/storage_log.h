#pragma once

#include <QLoggingCategory>

/// Databases opened, schema migrations applied and storage failures ("trueturn.storage").
Q_DECLARE_LOGGING_CATEGORY(lcStorage)
