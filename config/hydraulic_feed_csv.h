#pragma once

#include <QByteArray>
#include <QStringList>
#include <vector>

#include "core/sim/hydraulic/feed_simulation.h"

namespace tt::config {

/// The curves of simulated feed runs as CSV, one row per sample time: time_s, load_n, then for each run
/// feed_m_s, current_a, spool_m, opening_m and regulator_flow_m3_s, each suffixed with the run's label in
/// brackets ("feed_m_s[without regulator]", "feed_m_s[xi=0.8]"). The runs must share their sample
/// times (one scenario); throws std::invalid_argument otherwise or when labels and runs differ in number.
QByteArray feedRunsCsv(const QStringList& labels, const std::vector<const core::FeedRun*>& runs);

}  // namespace tt::config
