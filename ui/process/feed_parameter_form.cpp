#include "ui/process/feed_parameter_form.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace tt::ui {

namespace {

/// How one parameter is shown: its block, the factor from SI to the unit on screen, decimals and step.
struct FieldSpec {
    const char* key;
    FeedBlock block;
    double factor;
    int decimals;
    double step;
};

const FieldSpec kFields[] = {
    {"sensor.gain_v_per_n", FeedBlock::Sensor, 1e3, 3, 1.0},
    {"sensor.feed_exponent", FeedBlock::Sensor, 1.0, 2, 0.1},
    {"amplifier.gain", FeedBlock::Amplifier, 1.0, 2, 5.0},
    {"amplifier.bias_v", FeedBlock::Amplifier, 1.0, 2, 0.5},
    {"magnet.turns", FeedBlock::Magnet, 1.0, 0, 5.0},
    {"magnet.gap_permeance_h", FeedBlock::Magnet, 1e6, 2, 0.5},
    {"magnet.gap_area_m2", FeedBlock::Magnet, 1e6, 1, 10.0},
    {"magnet.resistance_ohm", FeedBlock::Magnet, 1.0, 1, 10.0},
    {"spool.time_constant_s", FeedBlock::Spool, 1e3, 2, 0.5},
    {"spool.damping_ratio", FeedBlock::Spool, 1.0, 2, 0.1},
    {"spool.gain_m_per_n", FeedBlock::Spool, 1e6, 2, 5.0},
    {"spool.lap_m", FeedBlock::Spool, 1e3, 4, 0.01},
    {"slot.discharge_coefficient", FeedBlock::Slot, 1.0, 3, 0.01},
    {"slot.plunger_diameter_m", FeedBlock::Slot, 1e3, 2, 0.5},
    {"slot.pressure_drop_pa", FeedBlock::Slot, 1e-6, 3, 0.05},
    {"slot.oil_density_kg_per_m3", FeedBlock::Slot, 1.0, 0, 10.0},
    {"slot.max_opening_m", FeedBlock::Slot, 1e3, 3, 0.05},
    {"cylinder.mass_kg", FeedBlock::Cylinder, 1.0, 1, 5.0},
    {"cylinder.piston_diameter_m", FeedBlock::Cylinder, 1e3, 1, 5.0},
    {"cylinder.leakage_m3_per_s_pa", FeedBlock::Cylinder, 1e9, 3, 1.0},
    {"cylinder.set_feed_m_per_s", FeedBlock::Cylinder, 1e3, 3, 0.1},
};

const FieldSpec* specOf(const QString& key) {
    for (const FieldSpec& f : kFields)
        if (key == QLatin1String(f.key)) return &f;
    return nullptr;
}

QString number(double v, int precision = 3) {
    return QString::number(v, 'g', precision);
}

}  // namespace

FeedParameterForm::FeedParameterForm(QWidget* parent)
    : QWidget(parent), m_box(new QGroupBox(this)), m_pages(new QStackedWidget(this)), m_design(new QPushButton(this)) {
    build();
    setParams(core::HydraulicFeedParams{});
    retranslate();
}

void FeedParameterForm::build() {
    std::array<QFormLayout*, kFeedBlockCount> forms{};
    for (int b = 0; b < kFeedBlockCount; ++b) {
        auto* page = new QWidget(m_pages);
        auto* layout = new QVBoxLayout(page);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->setSpacing(4);
        forms[b] = new QFormLayout;
        forms[b]->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
        forms[b]->setVerticalSpacing(4);
        layout->addLayout(forms[b]);
        m_derived[b] = new QLabel(page);
        m_derived[b]->setWordWrap(true);
        m_derived[b]->setObjectName(QStringLiteral("feedDerived%1").arg(b));
        m_derived[b]->setStyleSheet(QStringLiteral("color: #38434f; font-size: 11pt;"));
        if (static_cast<FeedBlock>(b) == FeedBlock::Amplifier) layout->addWidget(m_design);
        layout->addWidget(m_derived[b]);
        layout->addStretch(1);
        m_pages->addWidget(page);
    }
    for (const FieldSpec& f : kFields) {
        const core::FeedParameterInfo& info = core::feedParameter(f.key);
        auto* spin = new QDoubleSpinBox(this);
        spin->setObjectName(QStringLiteral("feed:%1").arg(QLatin1String(f.key)));
        spin->setDecimals(f.decimals);
        spin->setRange(info.minValue * f.factor, info.maxValue * f.factor);
        spin->setSingleStep(f.step);
        spin->setMinimumWidth(150);
        spin->setKeyboardTracking(false);
        auto* label = new QLabel(this);
        forms[static_cast<int>(f.block)]->addRow(label, spin);
        m_fields.insert(QLatin1String(f.key), spin);
        m_labels.insert(QLatin1String(f.key), label);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this] {
            refreshDerived();
            emit changed();
        });
    }
    m_design->setObjectName(QStringLiteral("feedDesign"));
    connect(m_design, &QPushButton::clicked, this, &FeedParameterForm::designRequested);
    auto* boxLayout = new QVBoxLayout(m_box);
    boxLayout->setContentsMargins(8, 4, 8, 4);
    boxLayout->addWidget(m_pages);
    auto* root = new QVBoxLayout(this);
    root->setContentsMargins(0, 0, 0, 0);
    root->addWidget(m_box);
    m_pages->setCurrentIndex(static_cast<int>(m_block));
}

void FeedParameterForm::setParams(const core::HydraulicFeedParams& params) {
    for (const FieldSpec& f : kFields) {
        QDoubleSpinBox* spin = m_fields.value(QLatin1String(f.key));
        const QSignalBlocker block(spin);
        spin->setValue(params.*(core::feedParameter(f.key).member) * f.factor);
    }
    refreshDerived();
}

core::HydraulicFeedParams FeedParameterForm::params() const {
    core::HydraulicFeedParams p;
    for (const FieldSpec& f : kFields) {
        const core::FeedParameterInfo& info = core::feedParameter(f.key);
        // Back to SI, kept inside the limits the spin box showed (rounding of the factor).
        p.*(info.member) =
            std::clamp(m_fields.value(QLatin1String(f.key))->value() / f.factor, info.minValue, info.maxValue);
    }
    return p;
}

void FeedParameterForm::showBlock(FeedBlock block) {
    m_block = block;
    m_pages->setCurrentIndex(static_cast<int>(block));
    m_box->setTitle(blockTitle(block));
}

QDoubleSpinBox* FeedParameterForm::field(const QString& key) const {
    return m_fields.value(key, nullptr);
}

QString FeedParameterForm::blockTitle(FeedBlock block) const {
    switch (block) {
        case FeedBlock::Sensor:
            return tr("Sensor: the tool's elastic displacement");
        case FeedBlock::Amplifier:
            return tr("Amplifier");
        case FeedBlock::Magnet:
            return tr("Electromagnet and armature");
        case FeedBlock::Spool:
            return tr("Spool of the flow regulator");
        case FeedBlock::Slot:
            return tr("Slot of the flow regulator");
        case FeedBlock::Cylinder:
            return tr("Cylinder and carriage");
    }
    return QString();
}

std::pair<QString, QString> FeedParameterForm::labelAndUnit(const QString& key) const {
    if (key == QLatin1String("sensor.gain_v_per_n")) return {tr("Signal per newton"), tr("mV/N")};
    if (key == QLatin1String("sensor.feed_exponent")) return {tr("Feed exponent y"), QString()};
    if (key == QLatin1String("amplifier.gain")) return {tr("Gain K_a"), tr("V/V")};
    if (key == QLatin1String("amplifier.bias_v")) return {tr("Bias U₀"), tr("V")};
    if (key == QLatin1String("magnet.turns")) return {tr("Coil turns"), QString()};
    if (key == QLatin1String("magnet.gap_permeance_h")) return {tr("Gap permeance"), tr("µH")};
    if (key == QLatin1String("magnet.gap_area_m2")) return {tr("Gap section"), tr("mm²")};
    if (key == QLatin1String("magnet.resistance_ohm")) return {tr("Coil circuit r"), tr("Ω")};
    if (key == QLatin1String("spool.time_constant_s")) return {tr("Time constant T_z"), tr("ms")};
    if (key == QLatin1String("spool.damping_ratio")) return {tr("Damping ratio ξ"), QString()};
    if (key == QLatin1String("spool.gain_m_per_n")) return {tr("Gain K_z"), tr("µm/N")};
    if (key == QLatin1String("spool.lap_m")) return {tr("Lap"), tr("mm")};
    if (key == QLatin1String("slot.discharge_coefficient")) return {tr("Discharge coeff. μ"), QString()};
    if (key == QLatin1String("slot.plunger_diameter_m")) return {tr("Plunger d₁"), tr("mm")};
    if (key == QLatin1String("slot.pressure_drop_pa")) return {tr("Pressure drop"), tr("MPa")};
    if (key == QLatin1String("slot.oil_density_kg_per_m3")) return {tr("Oil density"), tr("kg/m³")};
    if (key == QLatin1String("slot.max_opening_m")) return {tr("Full opening"), tr("mm")};
    if (key == QLatin1String("cylinder.mass_kg")) return {tr("Carriage mass"), tr("kg")};
    if (key == QLatin1String("cylinder.piston_diameter_m")) return {tr("Piston D"), tr("mm")};
    if (key == QLatin1String("cylinder.leakage_m3_per_s_pa")) return {tr("Leakage k_y"), tr("mm³/(s·Pa)")};
    if (key == QLatin1String("cylinder.set_feed_m_per_s")) return {tr("Set feed S"), tr("mm/s")};
    return {key, QString()};
}

void FeedParameterForm::retranslate() {
    for (auto it = m_fields.cbegin(); it != m_fields.cend(); ++it) {
        const auto [label, unit] = labelAndUnit(it.key());
        m_labels.value(it.key())->setText(label);
        it.value()->setSuffix(unit.isEmpty() ? QString() : QStringLiteral(" ") + unit);
        const core::FeedParameterInfo& info = core::feedParameter(it.key().toStdString());
        const double factor = specOf(it.key())->factor;
        it.value()->setToolTip(
            tr("%1 .. %2 %3").arg(number(info.minValue * factor, 4), number(info.maxValue * factor, 4), unit));
    }
    m_design->setText(tr("Design gain for the load"));
    showBlock(m_block);
    refreshDerived();
}

void FeedParameterForm::refreshDerived() {
    const core::HydraulicFeedParams p = params();
    const core::HydraulicFeedDerived d = core::deriveFeedQuantities(p);
    auto set = [this](FeedBlock b, const QString& text) { m_derived[static_cast<int>(b)]->setText(text); };
    set(FeedBlock::Sensor,
        tr("The radial force follows the chip: P_y = P (v/S)^y; y = 0 is the paper's constant force."));
    set(FeedBlock::Amplifier, tr("Bias current %1 mA; the lap that keeps the slot shut at the bias: %2 mm.")
                                  .arg(number(d.biasCurrentA * 1e3), number(d.biasSpoolM * 1e3)));
    set(FeedBlock::Magnet,
        tr("L = %1 H, T_k = %2 ms, K_e = %3 N/A²")
            .arg(number(d.coilInductanceH), number(d.magnetTimeConstantS * 1e3), number(d.armatureGainNPerA2, 4)));
    set(FeedBlock::Spool, p.spoolDampingRatio < 1.0
                              ? tr("ξ < 1: the spool oscillates (the paper recommends ξ slightly above 1).")
                              : tr("ξ ≥ 1: aperiodic, settles in about 3T."));
    set(FeedBlock::Slot, tr("k_s = %1 m²/s; full flow %2 cm³/s")
                             .arg(number(d.slotGainM2PerS), number(d.slotGainM2PerS * p.maxOpeningM * 1e6)));
    set(FeedBlock::Cylinder, tr("F = %1 cm², k₀ = %2 m⁻², T_c = %3 ms, pump %4 cm³/s")
                                 .arg(number(d.pistonAreaM2 * 1e4, 4), number(d.cylinderGainPerM2, 5),
                                      number(d.cylinderTimeConstantS * 1e3), number(d.pumpFlowM3PerS * 1e6)));
}

}  // namespace tt::ui
