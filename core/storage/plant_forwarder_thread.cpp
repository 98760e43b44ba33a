#include "core/storage/plant_forwarder_thread.h"

#include <QDateTime>
#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <algorithm>
#include <cmath>

#include "core/storage/storage_log.h"

namespace tt::storage {

namespace {

/// How often an idle forwarder looks for new entries when nobody wakes it, s.
constexpr double kIdlePollS = 0.2;
/// How often an offline forwarder refreshes the backlog it shows, s.
constexpr double kOfflineRefreshS = 1.0;

}  // namespace

PlantForwarderThread::PlantForwarderThread(ForwarderOptions options, QObject* parent)
    : QThread(parent), m_options(std::move(options)) {
    qRegisterMetaType<ForwarderStatus>();
    m_status.journalLimitBytes = m_options.journalLimitBytes;
    setObjectName(QStringLiteral("plant-forwarder"));
}

PlantForwarderThread::~PlantForwarderThread() {
    requestStop();
    wait();
}

ForwarderStatus PlantForwarderThread::status() const {
    const QMutexLocker lock(&m_mutex);
    return m_status;
}

void PlantForwarderThread::setStatusCallback(std::function<void(const ForwarderStatus&)> callback) {
    const QMutexLocker lock(&m_mutex);
    m_callback = std::move(callback);
}

void PlantForwarderThread::wake() {
    const QMutexLocker lock(&m_mutex);
    m_woken = true;
    m_wakeUp.wakeAll();
}

void PlantForwarderThread::requestStop() {
    const QMutexLocker lock(&m_mutex);
    m_stop = true;
    m_wakeUp.wakeAll();
}

bool PlantForwarderThread::stopping() const {
    const QMutexLocker lock(&m_mutex);
    return m_stop;
}

bool PlantForwarderThread::drainAndStop(double timeoutS) {
    {
        const QMutexLocker lock(&m_mutex);
        m_finishing = true;
        m_wakeUp.wakeAll();
    }
    if (!wait(deadlineAfter(timeoutS))) {
        requestStop();
        wait();
    }
    const ForwarderStatus s = status();
    return s.drained && s.backlogParts == 0;
}

QDeadlineTimer PlantForwarderThread::deadlineAfter(double seconds) {
    // QDeadlineTimer takes a negative time as "never expires".
    if (!(seconds > 0.0)) return QDeadlineTimer(0);
    return QDeadlineTimer(static_cast<qint64>(std::ceil(std::min(seconds, 86400.0) * 1000.0)));
}

bool PlantForwarderThread::pause(double seconds, bool wakeable) {
    QMutexLocker lock(&m_mutex);
    const QDeadlineTimer deadline = deadlineAfter(seconds);
    while (!m_stop && !(wakeable && (m_woken || m_finishing)) && !deadline.hasExpired())
        m_wakeUp.wait(&m_mutex, deadline);
    m_woken = false;
    return !m_stop;
}

void PlantForwarderThread::publish(ForwarderStatus status, bool linkChanged) {
    std::function<void(const ForwarderStatus&)> callback;
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    {
        const QMutexLocker lock(&m_mutex);
        m_status = status;
        if (!linkChanged && m_lastPublishMs >= 0 && now - m_lastPublishMs < 250) return;
        m_lastPublishMs = now;
        callback = m_callback;
    }
    if (callback) callback(status);
    emit statusChanged(status);
}

void PlantForwarderThread::sendRound(PlantForwarder& forwarder, ForwarderStatus& s, double& retryS) {
    const ForwarderStatus::Link before = s.link;
    const bool wasDrained = s.drained;
    try {
        const std::optional<std::int64_t> sent = forwarder.sendBatch();
        s.link = ForwarderStatus::Link::Online;
        s.offlineSince = QDateTime();
        s.reason.clear();
        s.retryInS = 0.0;
        retryS = m_options.settings.firstRetryS;
        s.sentParts += sent.value_or(0);
        s.backlogParts = forwarder.backlogParts();
        s.drained = !sent && s.backlogParts == 0;
        const JournalUsage usage = forwarder.usage();
        s.journalBytes = usage.usedBytes;
        if (before == ForwarderStatus::Link::Offline)
            qCInfo(lcStorage).noquote() << "plant database back;" << s.backlogParts << "parts still to send";
        publish(s, before != s.link || s.drained != wasDrained);
        if (!sent) {
            if (!m_sinceReport.isValid() || m_sinceReport.elapsed() >= m_options.settings.reportEveryS * 1000.0) {
                forwarder.report();
                m_sinceReport.restart();
            }
            const bool finishing = [this] {
                const QMutexLocker lock(&m_mutex);
                return m_finishing;
            }();
            if (finishing) {
                requestStop();
                return;
            }
            pause(kIdlePollS, true);
        }
    } catch (const std::exception& e) {
        forwarder.disconnect();
        if (s.link != ForwarderStatus::Link::Offline) s.offlineSince = QDateTime::currentDateTime();
        s.link = ForwarderStatus::Link::Offline;
        s.drained = false;
        s.reason = QString::fromUtf8(e.what()).simplified();
        s.retryInS = retryS;
        if (before != s.link) qCWarning(lcStorage).noquote() << "plant database offline:" << s.reason;
        publish(s, before != s.link);
        // Wait for the retry in slices, refreshing the backlog the operator sees (the journal is local).
        QElapsedTimer waited;
        waited.start();
        while (!stopping() && waited.elapsed() < retryS * 1000.0) {
            try {
                s.backlogParts = forwarder.backlogParts();
                s.journalBytes = forwarder.usage().usedBytes;
            } catch (const std::exception&) {
                // The journal is busy: the figure is refreshed at the next slice.
            }
            s.retryInS = std::max(0.0, retryS - static_cast<double>(waited.elapsed()) / 1000.0);
            publish(s, false);
            pause(std::min(kOfflineRefreshS, retryS - static_cast<double>(waited.elapsed()) / 1000.0), false);
        }
        retryS = std::min(2.0 * retryS, m_options.settings.maxRetryS);
    }
}

void PlantForwarderThread::run() {
    ForwarderStatus s;
    s.journalLimitBytes = m_options.journalLimitBytes;
    std::unique_ptr<PlantForwarder> forwarder;
    try {
        forwarder = std::make_unique<PlantForwarder>(m_options.journalPath, m_options.plant, m_options.machine,
                                                     m_options.journalLimitBytes, m_options.settings);
        s.backlogParts = forwarder->backlogParts();
    } catch (const std::exception& e) {
        s.link = ForwarderStatus::Link::Offline;
        s.offlineSince = QDateTime::currentDateTime();
        s.reason = QStringLiteral("the journal cannot be read: ") + QString::fromUtf8(e.what());
        publish(s, true);
        return;
    }
    publish(s, true);
    double retryS = m_options.settings.firstRetryS;
    while (!stopping())
        sendRound(*forwarder, s, retryS);
    publish(s, true);
}

}  // namespace tt::storage
