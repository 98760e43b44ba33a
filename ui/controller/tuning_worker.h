#pragma once

#include <QObject>
#include <QString>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "core/control/run_to_run_setup.h"
#include "core/run/tuning_preview.h"

namespace tt::ui {

/// One finished re-synthesis: the preview of the setup of request `generation`, or the engine's refusal.
struct TuningResult {
    std::uint64_t generation = 0;
    core::RunToRunSetup setup;
    std::optional<core::TuningPreview> preview;
    QString problem;         ///< the engine refused the setup, in its words
    double computeMs = 0.0;  ///< wall time of the re-synthesis
};

/// Re-synthesises the LQG design and its predictions off the GUI thread while the engineer drags a
/// slider. Requests coalesce: only the newest waiting setup is computed, older ones are dropped, so the
/// page stays interactive however fast the slider moves. Results arrive in the GUI thread.
class TuningWorker : public QObject {
    Q_OBJECT
public:
    explicit TuningWorker(QObject* parent = nullptr);
    /// Stops the thread (a running computation finishes first).
    ~TuningWorker() override;

    /// Asks for the preview of `setup`; returns the request's generation.
    std::uint64_t request(const core::RunToRunSetup& setup);
    /// Generation of the newest request.
    std::uint64_t latestGeneration() const;

signals:
    /// A finished request (possibly older than the newest; the newest always follows).
    void finished(std::shared_ptr<const tt::ui::TuningResult> result);

private:
    void loop();

    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::optional<core::RunToRunSetup> m_pending;
    std::uint64_t m_generation = 0;
    bool m_stop = false;
    std::shared_ptr<const TuningResult> m_last;  ///< the worker thread's last success (its EWMA part is reused)
    std::thread m_thread;
};

}  // namespace tt::ui
