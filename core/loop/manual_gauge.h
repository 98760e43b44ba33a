#pragma once

#include <atomic>
#include <deque>
#include <mutex>
#include <optional>

#include "core/ports/diameter_gauge.h"

namespace tt::core {

/// Diameters typed in by the operator (a shop with a hand micrometer), as a gauge: the UI pushes
/// readings in point order, the loop takes them like any gauge's. Thread-safe.
class ManualGauge final : public DiameterGauge {
public:
    DeviceHealth health() const override { return {DeviceState::Ready, "diameters are entered by hand"}; }
    bool handEntry() const override { return true; }
    void requestReading() override {}
    std::optional<GaugeReading> takeReading() override;
    /// Queues one reading (diameter, mm; time, s).
    void push(const GaugeReading& reading);

private:
    mutable std::mutex m_mutex;
    std::deque<GaugeReading> m_readings;
};

/// The loop's gauge when readings may come from an automatic gauge or by hand: readings typed in are
/// always taken; the automatic gauge's only while it is selected. Its health is the selected source's,
/// so a silent automatic gauge pauses the loop at once. Thread-safe selection.
class SelectableGauge final : public DiameterGauge {
public:
    /// Switches between the two gauges (both outlive it); starts automatic.
    SelectableGauge(DiameterGauge& automatic, ManualGauge& manual) : m_automatic(automatic), m_manual(manual) {}
    DeviceHealth health() const override;
    void requestReading() override;
    std::optional<GaugeReading> takeReading() override;
    /// true: diameters come by hand; false: from the automatic gauge.
    void setManual(bool manual) { m_isManual = manual; }
    bool handEntry() const override { return m_isManual; }
    /// Whether diameters come by hand.
    bool manual() const { return m_isManual; }

private:
    DiameterGauge& m_automatic;
    ManualGauge& m_manual;
    std::atomic<bool> m_isManual{false};
};

}  // namespace tt::core
