#include "ui/controller/weight_row.h"

#include <QDoubleSpinBox>
#include <QSignalBlocker>
#include <QSlider>
#include <cmath>

namespace tt::ui {

namespace {
constexpr int kSteps = 200;
}

WeightEditor::WeightEditor(double minValue, double maxValue, int decimals, QObject* parent)
    : QObject(parent),
      m_logMin(std::log10(minValue)),
      m_logMax(std::log10(maxValue)),
      m_slider(new QSlider(Qt::Horizontal)),
      m_field(new QDoubleSpinBox) {
    m_slider->setRange(0, kSteps);
    m_slider->setFixedWidth(48);
    m_field->setMinimumWidth(116);  // "0.0100" and the arrows of the house style (tests/ui/terminal)
    m_field->setRange(minValue, maxValue);
    m_field->setDecimals(decimals);
    m_field->setKeyboardTracking(false);
    connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
        if (m_syncing) return;
        m_syncing = true;
        m_field->setValue(fromSlider(position));
        m_syncing = false;
        emit changed();
    });
    connect(m_field, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (m_syncing) return;
        m_syncing = true;
        m_slider->setValue(toSlider(v));
        m_syncing = false;
        emit changed();
    });
}

double WeightEditor::value() const {
    return m_field->value();
}

void WeightEditor::setValue(double value) {
    const QSignalBlocker a(m_slider), b(m_field);
    m_field->setValue(value);
    m_slider->setValue(toSlider(value));
}

int WeightEditor::toSlider(double value) const {
    const double t = (std::log10(std::max(value, 1e-300)) - m_logMin) / (m_logMax - m_logMin);
    return static_cast<int>(std::lround(std::clamp(t, 0.0, 1.0) * kSteps));
}

double WeightEditor::fromSlider(int position) const {
    return std::pow(10.0, m_logMin + (m_logMax - m_logMin) * position / kSteps);
}

}  // namespace tt::ui
