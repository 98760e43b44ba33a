#pragma once

#include <QObject>

class QSlider;
class QDoubleSpinBox;

namespace tt::ui {

/// A weight edited by a logarithmic slider and a number field kept in step (R1 or R2 of one point).
class WeightEditor : public QObject {
    Q_OBJECT
public:
    /// `minValue` .. `maxValue` (> 0) on a log scale; the field shows `decimals` decimals.
    WeightEditor(double minValue, double maxValue, int decimals, QObject* parent = nullptr);

    QSlider* slider() const { return m_slider; }
    QDoubleSpinBox* field() const { return m_field; }
    double value() const;
    /// Sets the value without emitting changed().
    void setValue(double value);

signals:
    /// The engineer moved the slider or typed a value.
    void changed();

private:
    int toSlider(double value) const;
    double fromSlider(int position) const;

    double m_logMin, m_logMax;
    QSlider* m_slider;
    QDoubleSpinBox* m_field;
    bool m_syncing = false;
};

}  // namespace tt::ui
