#pragma once

#include <QGroupBox>
#include <vector>

#include "core/sim/feed_drives/corner_move.h"
#include "core/sim/feed_drives/corrective_pulse.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;

namespace tt::ui {

/// The corner the Corner tool simulates: the motor speeds of X and Z before and after the velocity
/// change (entered, or picked from a list of sample corners), the drive the pulse goes into and its
/// length. Speeds are limited to the paper's 0.5 .. 9 rad/s, the length to 10 .. 200 ms.
class CornerMoveEditor : public QGroupBox {
    Q_OBJECT
public:
    explicit CornerMoveEditor(QWidget* parent = nullptr);

    /// Sets every visible text (also on a language change).
    void retranslate();
    /// The corners offered in the list (after "speeds as entered").
    void setSamples(const std::vector<core::CornerMove>& samples);
    /// Picks sample `index` (0-based) and fills the speeds with it.
    void pickSample(int index);

    /// The corner as entered.
    core::CornerMove move() const;
    /// Fills the speeds.
    void setMove(const core::CornerMove& move);
    /// `base` with the chosen axis and length.
    core::PulseSettings pulse(core::PulseSettings base) const;
    /// Shows the settings of `pulse` (axis, length).
    void setPulse(const core::PulseSettings& pulse);

    QDoubleSpinBox* speedBox(int index) const { return m_speeds[static_cast<std::size_t>(index)]; }
    QComboBox* axisBox() const { return m_axis; }
    QSpinBox* durationBox() const { return m_duration; }
    QComboBox* pickBox() const { return m_pick; }

signals:
    /// The corner or the pulse changed.
    void changed();

private:
    std::vector<core::CornerMove> m_samples;
    QLabel* m_pickLabel;
    QComboBox* m_pick;
    std::vector<QLabel*> m_speedLabels;
    std::vector<QDoubleSpinBox*> m_speeds;
    QLabel* m_axisLabel;
    QComboBox* m_axis;
    QLabel* m_durationLabel;
    QSpinBox* m_duration;
};

}  // namespace tt::ui
