#include "config/hydraulic_feed_csv.h"

#include <QTextStream>
#include <cmath>
#include <stdexcept>

namespace tt::config {

QByteArray feedRunsCsv(const QStringList& labels, const std::vector<const core::FeedRun*>& runs) {
    if (runs.empty() || static_cast<std::size_t>(labels.size()) != runs.size())
        throw std::invalid_argument("CSV of feed runs: one label per run, at least one run");
    const std::vector<core::FeedSample>& first = runs.front()->samples;
    for (const core::FeedRun* run : runs) {
        if (run->samples.size() != first.size())
            throw std::invalid_argument("CSV of feed runs: the runs have different sample times");
        for (std::size_t k = 0; k < first.size(); ++k)
            if (std::abs(run->samples[k].timeS - first[k].timeS) > 1e-12)
                throw std::invalid_argument("CSV of feed runs: the runs have different sample times");
    }
    QByteArray csv;
    QTextStream out(&csv);
    out << "time_s,load_n";
    for (const QString& label : labels)
        for (const char* column : {"feed_m_s", "current_a", "spool_m", "opening_m", "regulator_flow_m3_s"})
            out << ',' << column << '[' << QString(label).replace(QLatin1Char(','), QLatin1Char(';')) << ']';
    out << '\n';
    out.setRealNumberPrecision(10);
    for (std::size_t k = 0; k < first.size(); ++k) {
        out << first[k].timeS << ',' << first[k].loadN;
        for (const core::FeedRun* run : runs) {
            const core::FeedSample& s = run->samples[k];
            out << ',' << s.feedMPerS << ',' << s.currentA << ',' << s.spoolM << ',' << s.openingM << ','
                << s.regulatorFlowM3PerS;
        }
        out << '\n';
    }
    out.flush();
    return csv;
}

}  // namespace tt::config
