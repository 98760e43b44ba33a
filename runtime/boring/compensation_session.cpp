#include "runtime/boring/compensation_session.h"

#include <QMetaObject>

namespace tt::runtime {

CompensationSession::CompensationSession(QObject* parent)
    : QObject(parent), m_schedule(std::make_shared<CycleSchedule>()) {
    qRegisterMetaType<core::BoringRunCycle>();
    qRegisterMetaType<QVector<core::BoringRunCycle>>();
    m_thread.setObjectName(QStringLiteral("trueturn-compensation"));
    m_worker = new CompensationWorker(m_schedule);
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &CompensationWorker::cycles, this,
            [this](quint64 runId, const QVector<core::BoringRunCycle>& batch) {
                if (m_running && runId == m_runId) emit cycles(batch);
            });
    connect(m_worker, &CompensationWorker::passFinished, this, [this](quint64 runId) {
        if (!m_running || runId != m_runId) return;
        m_running = false;
        emit passFinished();
    });
    m_thread.start(QThread::TimeCriticalPriority);
}

CompensationSession::~CompensationSession() {
    QMetaObject::invokeMethod(m_worker, &CompensationWorker::stop, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

void CompensationSession::start(std::shared_ptr<core::BoringStation> station, std::unique_ptr<core::BoringRun> run,
                                int speed) {
    const quint64 id = ++m_runId;
    m_running = true;
    std::shared_ptr<core::BoringRun> shared = std::move(run);
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, station, shared, speed, id] { w->start(station, shared, speed, id); },
        Qt::QueuedConnection);
}

void CompensationSession::setSpeed(int speed) {
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, speed] { w->setSpeed(speed); }, Qt::QueuedConnection);
}

void CompensationSession::setSegment(core::SegmentKind kind) {
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, kind] { w->setSegment(kind); }, Qt::QueuedConnection);
}

void CompensationSession::stop() {
    if (!m_running) return;
    m_running = false;
    ++m_runId;
    QMetaObject::invokeMethod(m_worker, &CompensationWorker::stop, Qt::QueuedConnection);
}

}  // namespace tt::runtime
