#include "core/sim/hydraulic/feed_load_profile.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tt::core {

namespace {

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

void checkRange(const char* what, double v, double lo, double hi, const char* unit) {
    if (!std::isfinite(v) || v < lo || v > hi)
        throw std::invalid_argument(std::string("load ") + what + " " + number(v) + " " + unit + " is outside " +
                                    number(lo) + " .. " + number(hi) + " " + unit);
}

}  // namespace

FeedLoadProfile FeedLoadProfile::step(double timeS, double forceN) {
    FeedLoadProfile p;
    p.addStep(timeS, forceN);
    return p;
}

void FeedLoadProfile::addStep(double timeS, double forceN) {
    add({timeS, 0.0, forceN});
}

void FeedLoadProfile::addRamp(double timeS, double durationS, double forceN) {
    if (!(durationS > 0.0)) throw std::invalid_argument("load ramp duration " + number(durationS) + " s: must be > 0");
    add({timeS, durationS, forceN});
}

void FeedLoadProfile::add(const FeedLoadEvent& e) {
    checkRange("time", e.timeS, 0.0, kMaxTimeS, "s");
    checkRange("duration", e.durationS, 0.0, kMaxTimeS, "s");
    checkRange("force", e.forceN, 0.0, kMaxForceN, "N");
    std::vector<FeedLoadEvent> events = m_events;
    events.push_back(e);
    std::stable_sort(events.begin(), events.end(),
                     [](const FeedLoadEvent& a, const FeedLoadEvent& b) { return a.timeS < b.timeS; });
    for (std::size_t k = 1; k < events.size(); ++k) {
        const FeedLoadEvent& before = events[k - 1];
        if (events[k].timeS < before.timeS + before.durationS || events[k].timeS == before.timeS)
            throw std::invalid_argument("load change at " + number(events[k].timeS) +
                                        " s falls on another change (at " + number(before.timeS) + " s, lasting " +
                                        number(before.durationS) + " s)");
    }
    m_events = std::move(events);
}

double FeedLoadProfile::forceAt(double timeS) const {
    double level = 0.0;
    for (const FeedLoadEvent& e : m_events) {
        if (timeS < e.timeS) break;
        if (e.durationS > 0.0 && timeS < e.timeS + e.durationS)
            return level + (e.forceN - level) * (timeS - e.timeS) / e.durationS;
        level = e.forceN;
    }
    return level;
}

std::vector<double> FeedLoadProfile::breakpoints() const {
    std::vector<double> out;
    for (const FeedLoadEvent& e : m_events) {
        out.push_back(e.timeS);
        if (e.durationS > 0.0) out.push_back(e.timeS + e.durationS);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

double FeedLoadProfile::lastEventS() const {
    return m_events.empty() ? 0.0 : m_events.back().timeS;
}

double FeedLoadProfile::maxForceN() const {
    double m = 0.0;
    for (const FeedLoadEvent& e : m_events)
        m = std::max(m, e.forceN);
    return m;
}

}  // namespace tt::core
