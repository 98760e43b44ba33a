#pragma once

#include <QVariantMap>
#include <deque>
#include <optional>

#include "devices/parsers/gauge_decoder.h"
#include "devices/simulator/micrometer_emulator.h"
#include "devices/simulator/simulated_device.h"

namespace tt::devices {

/// The simulator's gauge micrometer. Each reading goes through the real path: the emulated
/// instrument formats it on the wire (ASCII or Digimatic, at its resolution and unit), the
/// gauge decoder parses and checks it. True diameters come from the injectable source
/// (setDiameterSource, e.g. the lathe simulator) or, stand-alone, the nominal diameter.
/// Settings: format, instrumentUnit, jobUnit, nominalDiameterMm, decimals, replyTimeoutMs.
class SimulatedGauge final : public SimulatedDevice, public core::DiameterGauge {
public:
    SimulatedGauge(const QVariantMap& settings, const DeviceContext& context);

    core::DeviceHealth health() const override { return DeviceBase::health(); }
    void requestReading() override;
    std::optional<core::GaugeReading> takeReading() override;
    void testConnection() override;
    core::DiameterGauge* diameterGauge() override { return this; }
    QList<DeviceStatistic> statistics() const override;
    void setDiameterSource(std::function<double()> source) override;

protected:
    void tick() override;
    void connected() override;

private:
    std::function<double()> m_source;
    MicrometerEmulator m_instrument;
    GaugeDecoder m_decoder;
    double m_replyTimeoutS;
    std::optional<double> m_requestedAtS;
    std::optional<double> m_lastTrueMm;
    std::deque<core::GaugeReading> m_readings;
};

}  // namespace tt::devices
