#pragma once

#include <QLoggingCategory>

/// The closed loops the runtime runs: starts, stops, states and alarms ("trueturn.loop").
Q_DECLARE_LOGGING_CATEGORY(lcLoop)
/// The device thread: plugins, instances, links to the runs ("trueturn.runtime").
Q_DECLARE_LOGGING_CATEGORY(lcRuntime)
