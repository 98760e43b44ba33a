#include "ui/controller/tuning_worker.h"

#include <QMetaObject>
#include <chrono>
#include <exception>

namespace tt::ui {

TuningWorker::TuningWorker(QObject* parent) : QObject(parent) {
    m_thread = std::thread([this] { loop(); });
}

TuningWorker::~TuningWorker() {
    {
        const std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_one();
    m_thread.join();
}

std::uint64_t TuningWorker::request(const core::RunToRunSetup& setup) {
    std::uint64_t generation = 0;
    {
        const std::lock_guard lock(m_mutex);
        m_pending = setup;  // replaces a request not started yet: drags coalesce
        generation = ++m_generation;
    }
    m_wake.notify_one();
    return generation;
}

std::uint64_t TuningWorker::latestGeneration() const {
    const std::lock_guard lock(m_mutex);
    return m_generation;
}

void TuningWorker::loop() {
    for (;;) {
        auto result = std::make_shared<TuningResult>();
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [this] { return m_stop || m_pending.has_value(); });
            if (m_stop) return;
            result->setup = std::move(*m_pending);
            result->generation = m_generation;
            m_pending.reset();
        }
        const auto start = std::chrono::steady_clock::now();
        try {
            const bool reuse = m_last && core::samePlantSpec(core::designPlantSpec(m_last->setup),
                                                             core::designPlantSpec(result->setup));
            result->preview = core::computeTuningPreview(result->setup, reuse ? &*m_last->preview : nullptr);
            m_last = result;
        } catch (const std::exception& e) {
            result->problem = QString::fromStdString(e.what());
        }
        result->computeMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::shared_ptr<const TuningResult> done = std::move(result);
        QMetaObject::invokeMethod(
            this, [this, done] { emit finished(done); }, Qt::QueuedConnection);
    }
}

}  // namespace tt::ui
