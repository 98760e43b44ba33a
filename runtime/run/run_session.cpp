#include "runtime/run/run_session.h"

#include <QMetaObject>

namespace tt::runtime {

RunSession::RunSession(QObject* parent) : QObject(parent) {
    qRegisterMetaType<RunStart>();
    qRegisterMetaType<LoopSnapshot>();
    qRegisterMetaType<RunLayout>();
    qRegisterMetaType<core::LoopEvent>();
    m_thread.setObjectName(QStringLiteral("trueturn-loop"));
    m_worker = new LoopWorker;
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &LoopWorker::started, this, &RunSession::started);
    connect(m_worker, &LoopWorker::startFailed, this, &RunSession::startFailed);
    connect(m_worker, &LoopWorker::snapshot, this, [this](const LoopSnapshot& s) {
        m_snapshot = s;
        emit snapshotChanged(s);
    });
    connect(m_worker, &LoopWorker::loopEvent, this, &RunSession::loopEvent);
    connect(m_worker, &LoopWorker::partProfile, this, &RunSession::partProfile);
    connect(m_worker, &LoopWorker::notice, this, &RunSession::notice);
    connect(m_worker, &LoopWorker::tuningTaken, this, &RunSession::tuningTaken);
    connect(m_worker, &LoopWorker::plantStatus, this, &RunSession::plantStatus);
    connect(m_worker, &LoopWorker::machineIncident, this, &RunSession::machineIncident);
    m_thread.start();
}

RunSession::~RunSession() {
    QMetaObject::invokeMethod(m_worker, &LoopWorker::shutdown, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

void RunSession::start(const RunStart& run) {
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, run] { w->start(run); }, Qt::QueuedConnection);
}

void RunSession::resume(const RunStart& run, qint64 runId) {
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, run, runId] { w->resume(run, runId); }, Qt::QueuedConnection);
}

void RunSession::confirmPartFinished() {
    QMetaObject::invokeMethod(m_worker, &LoopWorker::confirmPartFinished, Qt::QueuedConnection);
}

void RunSession::pause() {
    QMetaObject::invokeMethod(m_worker, &LoopWorker::pause, Qt::QueuedConnection);
}

void RunSession::continueRun() {
    QMetaObject::invokeMethod(m_worker, &LoopWorker::continueRun, Qt::QueuedConnection);
}

void RunSession::stop() {
    QMetaObject::invokeMethod(m_worker, &LoopWorker::stop, Qt::QueuedConnection);
}

void RunSession::setSpeed(double speed) {
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, speed] { w->setSpeed(speed); }, Qt::QueuedConnection);
}

void RunSession::setManualEntry(bool manual) {
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, manual] { w->setManualEntry(manual); }, Qt::QueuedConnection);
}

void RunSession::submitDiameters(qint64 partNumber, const QVector<double>& diametersMm) {
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, partNumber, diametersMm] { w->submitDiameters(partNumber, diametersMm); },
        Qt::QueuedConnection);
}

void RunSession::skipMeasurement() {
    QMetaObject::invokeMethod(m_worker, &LoopWorker::skipMeasurement, Qt::QueuedConnection);
}

void RunSession::silenceGauge(double seconds) {
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, seconds] { w->silenceGauge(seconds); }, Qt::QueuedConnection);
}

void RunSession::applyTuning(const core::RunToRunSetup& tuning) {
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, tuning] { w->applyTuning(tuning); }, Qt::QueuedConnection);
}

}  // namespace tt::runtime
