#include "ui/process/corner_move_editor.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QSpinBox>
#include <algorithm>
#include <cmath>

namespace tt::ui {

namespace {

QString speed(double v) {
    return QLocale().toString(v, 'f', 2);
}

}  // namespace

CornerMoveEditor::CornerMoveEditor(QWidget* parent)
    : QGroupBox(parent),
      m_pickLabel(new QLabel(this)),
      m_pick(new QComboBox(this)),
      m_axisLabel(new QLabel(this)),
      m_axis(new QComboBox(this)),
      m_durationLabel(new QLabel(this)),
      m_duration(new QSpinBox(this)) {
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(6, 2, 6, 4);
    grid->setVerticalSpacing(3);
    m_pick->setObjectName(QStringLiteral("cornerPick"));
    m_pick->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_pick->setMinimumContentsLength(6);
    grid->addWidget(m_pickLabel, 0, 0);
    grid->addWidget(m_pick, 0, 1);
    const core::CornerMove initial{7.0, 2.5, 1.5, 7.0};
    const double values[] = {initial.x1RadPerS, initial.z1RadPerS, initial.x2RadPerS, initial.z2RadPerS};
    for (int i = 0; i < 4; ++i) {
        auto* label = new QLabel(this);
        auto* box = new QDoubleSpinBox(this);
        box->setObjectName(QStringLiteral("cornerSpeed%1").arg(i));
        box->setRange(core::kMinCornerSpeedRadPerS, core::kMaxCornerSpeedRadPerS);
        box->setDecimals(2);
        box->setSingleStep(0.25);
        box->setValue(values[i]);
        grid->addWidget(label, i + 1, 0);
        grid->addWidget(box, i + 1, 1);
        m_speedLabels.push_back(label);
        m_speeds.push_back(box);
        connect(box, &QDoubleSpinBox::valueChanged, this, [this] {
            if (m_pick->currentIndex() > 0) {
                const QSignalBlocker block(m_pick);
                m_pick->setCurrentIndex(0);
            }
            emit changed();
        });
    }
    m_axis->setObjectName(QStringLiteral("cornerAxis"));
    m_axis->addItem(QString(), static_cast<int>(core::FeedAxis::X));
    m_axis->addItem(QString(), static_cast<int>(core::FeedAxis::Z));
    m_duration->setObjectName(QStringLiteral("cornerDuration"));
    m_duration->setRange(10, 200);
    m_duration->setSingleStep(5);
    m_duration->setValue(50);
    grid->addWidget(m_axisLabel, 5, 0);
    grid->addWidget(m_axis, 5, 1);
    grid->addWidget(m_durationLabel, 6, 0);
    grid->addWidget(m_duration, 6, 1);
    grid->setColumnStretch(1, 1);
    connect(m_pick, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (index > 0) pickSample(index - 1);
    });
    connect(m_axis, &QComboBox::currentIndexChanged, this, &CornerMoveEditor::changed);
    connect(m_duration, &QSpinBox::valueChanged, this, &CornerMoveEditor::changed);
    retranslate();
}

void CornerMoveEditor::retranslate() {
    setTitle(tr("Corner between two moves"));
    m_pickLabel->setText(tr("Corner"));
    const QString names[] = {tr("X before"), tr("Z before"), tr("X after"), tr("Z after")};
    for (int i = 0; i < 4; ++i) {
        m_speedLabels[static_cast<std::size_t>(i)]->setText(names[i]);
        m_speeds[static_cast<std::size_t>(i)]->setSuffix(tr(" rad/s"));
    }
    m_axisLabel->setText(tr("Pulse on"));
    m_axis->setItemText(0, tr("X, cross slide"));
    m_axis->setItemText(1, tr("Z, carriage"));
    m_durationLabel->setText(tr("Pulse length"));
    m_duration->setSuffix(tr(" ms"));
    setSamples(m_samples);
}

void CornerMoveEditor::setSamples(const std::vector<core::CornerMove>& samples) {
    m_samples = samples;
    const QSignalBlocker block(m_pick);
    const int current = m_pick->currentIndex();
    m_pick->clear();
    m_pick->addItem(tr("Speeds as entered"));
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const core::CornerMove& m = samples[i];
        m_pick->addItem(tr("%1: X %2 → %3, Z %4 → %5")
                            .arg(i + 1)
                            .arg(speed(m.x1RadPerS), speed(m.x2RadPerS), speed(m.z1RadPerS), speed(m.z2RadPerS)));
    }
    m_pick->setCurrentIndex(std::clamp(current, 0, m_pick->count() - 1));
}

void CornerMoveEditor::pickSample(int index) {
    if (index < 0 || index >= static_cast<int>(m_samples.size())) return;
    setMove(m_samples[static_cast<std::size_t>(index)]);
    const QSignalBlocker block(m_pick);
    m_pick->setCurrentIndex(index + 1);
    emit changed();
}

core::CornerMove CornerMoveEditor::move() const {
    return {m_speeds[0]->value(), m_speeds[1]->value(), m_speeds[2]->value(), m_speeds[3]->value()};
}

void CornerMoveEditor::setMove(const core::CornerMove& move) {
    const double values[] = {move.x1RadPerS, move.z1RadPerS, move.x2RadPerS, move.z2RadPerS};
    for (int i = 0; i < 4; ++i) {
        const QSignalBlocker block(m_speeds[static_cast<std::size_t>(i)]);
        m_speeds[static_cast<std::size_t>(i)]->setValue(values[i]);
    }
}

core::PulseSettings CornerMoveEditor::pulse(core::PulseSettings base) const {
    base.axis = static_cast<core::FeedAxis>(m_axis->currentData().toInt());
    base.durationS = m_duration->value() / 1000.0;
    return base;
}

void CornerMoveEditor::setPulse(const core::PulseSettings& pulse) {
    const QSignalBlocker blockAxis(m_axis);
    const QSignalBlocker blockDuration(m_duration);
    m_axis->setCurrentIndex(pulse.axis == core::FeedAxis::X ? 0 : 1);
    m_duration->setValue(static_cast<int>(std::lround(pulse.durationS * 1000.0)));
}

}  // namespace tt::ui
