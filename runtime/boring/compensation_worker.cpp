#include "runtime/boring/compensation_worker.h"

#include <QTimer>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "runtime/thread_priority.h"

namespace tt::runtime {

namespace {

constexpr int kMaxSpeed = 100;

}  // namespace

CycleSchedule::CycleSchedule(std::size_t capacity) : m_capacity(capacity) {
    if (capacity == 0) throw std::invalid_argument("a cycle schedule must keep at least one start");
}

void CycleSchedule::clear() {
    std::lock_guard lock(m_mutex);
    m_starts.clear();
}

void CycleSchedule::record(std::chrono::steady_clock::time_point start) {
    std::lock_guard lock(m_mutex);
    if (m_starts.size() == m_capacity) m_starts.erase(m_starts.begin(), m_starts.begin() + m_capacity / 10 + 1);
    m_starts.push_back(start);
}

std::vector<std::chrono::steady_clock::time_point> CycleSchedule::starts() const {
    std::lock_guard lock(m_mutex);
    return m_starts;
}

CompensationWorker::CompensationWorker(std::shared_ptr<CycleSchedule> schedule)
    : m_schedule(std::move(schedule)), m_timer(new QTimer(this)) {
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &CompensationWorker::tick);
}

CompensationWorker::~CompensationWorker() = default;

void CompensationWorker::start(std::shared_ptr<core::BoringStation> station, std::shared_ptr<core::BoringRun> run,
                               int speed, quint64 runId) {
    stop();
    if (!m_preferred) {
        preferThisThread();
        m_preferred = true;
    }
    m_station = std::move(station);
    m_run = std::move(run);
    m_runId = runId;
    setSpeed(speed);
    m_schedule->clear();
    m_timer->start(std::max(1, static_cast<int>(std::lround(m_run->plcCycleS() * 1000.0))));
}

void CompensationWorker::setSpeed(int speed) {
    m_speed = std::clamp(speed, 1, kMaxSpeed);
}

void CompensationWorker::setSegment(core::SegmentKind kind) {
    if (m_run) m_run->setSegment(kind);
}

void CompensationWorker::stop() {
    m_timer->stop();
    m_run.reset();
    m_station.reset();
}

void CompensationWorker::tick() {
    if (!m_run) return;
    m_schedule->record(std::chrono::steady_clock::now());
    const int n = m_station->runsAheadOfTime() ? m_speed : 1;
    QVector<core::BoringRunCycle> batch;
    batch.reserve(n);
    for (int i = 0; i < n && !m_run->finished(); ++i)
        batch.push_back(m_run->cycle());
    emit cycles(m_runId, batch);
    if (m_run->finished()) {
        const quint64 id = m_runId;
        stop();
        emit passFinished(id);
    }
}

}  // namespace tt::runtime
