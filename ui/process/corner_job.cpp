#include "ui/process/corner_job.h"

#include <QMetaObject>
#include <QThread>
#include <chrono>

#include "core/common/operation_cancelled.h"

namespace tt::ui {

namespace {

constexpr auto kReportEvery = std::chrono::milliseconds(50);

}  // namespace

CornerJob::CornerJob(QObject* parent) : QObject(parent) {}

CornerJob::~CornerJob() {
    if (!m_thread) return;
    m_cancel = true;
    m_thread->wait();
    delete m_thread;
}

bool CornerJob::start(Work work) {
    if (m_thread) return false;
    m_cancel = false;
    m_cancelled = false;
    m_error.clear();
    m_thread = QThread::create([this, work = std::move(work)] {
        auto last = std::chrono::steady_clock::now() - kReportEvery;
        const core::CornerProgress report = [this, &last](const std::string& stage, int done, int total) {
            const auto now = std::chrono::steady_clock::now();
            if (now - last >= kReportEvery || done == total) {
                last = now;
                QMetaObject::invokeMethod(
                    this, [this, s = QString::fromStdString(stage), done, total] { emit progress(s, done, total); },
                    Qt::QueuedConnection);
            }
            return !m_cancel.load();
        };
        try {
            work(report);
        } catch (const core::OperationCancelled&) {
            m_cancelled = true;
        } catch (const std::exception& e) {
            m_error = QString::fromStdString(e.what());
        }
    });
    m_thread->setObjectName(QStringLiteral("trueturn-corner"));
    connect(m_thread, &QThread::finished, this, [this] {
        m_thread->deleteLater();
        m_thread = nullptr;
        emit finished(m_cancelled, m_error);
    });
    m_thread->start(QThread::LowPriority);
    return true;
}

void CornerJob::cancel() {
    m_cancel = true;
}

}  // namespace tt::ui
