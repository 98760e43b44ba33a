#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>

#include "core/calibration/settled_average.h"
#include "core/ports/deflection_probe.h"

namespace tt::core {

/// One calibration point of the probe mandrel as captured: the reference read on the instrument,
/// the mean ADC code of the bending plane, and whether the ADC clipped while it was read.
struct ProbePoint {
    double referenceUm = 0.0;     ///< reference deflection (dial indicator, micrometer), µm
    double adcCode = 0.0;         ///< mean ADC code
    int samples = 0;              ///< live samples averaged; 0 when typed
    bool saturated = false;       ///< a raw code reached 0 or 2^bits − 1: the mean is not the deflection's
    std::int32_t lowestCode = 0;  ///< smallest raw code read (typed: the code, rounded)
    std::int32_t highestCode = 0;
};

/// True when `code` is at the limits of an ADC of `adcBits` bits (0 or 2^bits − 1, or beyond):
/// the bridge may be further out than the code says.
bool saturatedCode(double code, int adcBits);

/// Why a capture ended without a point.
enum class CaptureProblem {
    None,
    NotReady,     ///< the probe reports a problem (its message comes with it)
    NoSamples,    ///< no sample arrived for the timeout
    LoadChanged,  ///< the load changed while it was read
    Aborted,      ///< the operator stopped it
};

/// Timing of a probe capture.
struct ProbeCaptureConfig {
    double settleS = 0.1;           ///< hold still: samples within this time of the start are not used, s
    int samplesPerPoint = 50;       ///< samples averaged per point
    int liveWindow = 50;            ///< samples in the live mean shown between captures
    int minLiveSamples = 10;        ///< fewer: no live mean yet
    double noSampleTimeoutS = 3.0;  ///< a capture without a sample for this long fails, s (wall time)
};

/// What a finished capture gave: the point read (complete when problem is None).
struct ProbeCaptureResult {
    ProbePoint point;
    CaptureProblem problem = CaptureProblem::None;
    std::string deviceMessage;  ///< NotReady: the probe's own words
};

/// The capture state machine of one probe plane: Idle (a live mean of the latest samples for the
/// operator) → start() → HoldStill (the bar settles; samples are dropped for settleS of sample
/// time) → Averaging (samplesPerPoint codes averaged, their extremes kept to flag a clipping ADC)
/// → Idle with a result. Samples arrive through the engine's port (core::DeflectionProbe).
class ProbeCapture {
public:
    using Phase = HoldPhase;

    /// Throws std::invalid_argument for a plane other than 0/1, bits outside 10..16 or timing out of range.
    ProbeCapture(const ProbeCaptureConfig& config, int plane, int adcBits);

    /// Starts reading a point at the reference the operator read, µm.
    void start(double referenceUm);
    /// Stops a running capture; returns its result (Aborted), or nullopt when none ran.
    std::optional<ProbeCaptureResult> abort();
    /// The load was changed (a jack moved): the live mean restarts; a running capture ends (LoadChanged).
    std::optional<ProbeCaptureResult> loadChanged();
    /// Takes every sample the port holds (`elapsedS` of wall time since the last call, for the
    /// timeout); returns the result when a capture ended.
    std::optional<ProbeCaptureResult> pump(DeflectionProbe& port, double elapsedS);

    Phase phase() const { return m_average.holdPhase(); }
    bool running() const { return phase() != Phase::Idle; }
    /// 0..1 of the running capture.
    double progress() const { return m_average.progress(); }
    /// Mean of the latest live codes, nullopt with fewer than minLiveSamples.
    std::optional<double> liveCode() const;
    int liveSamples() const { return static_cast<int>(m_live.size()); }
    /// A live code of the window is at an ADC limit.
    bool liveSaturated() const;
    /// The reference of the running capture, µm.
    double referenceUm() const { return m_point.referenceUm; }
    int plane() const { return m_plane; }
    int adcBits() const { return m_bits; }

private:
    std::optional<ProbeCaptureResult> finish(CaptureProblem problem, std::string message = {});

    ProbeCaptureConfig m_config;
    int m_plane;
    int m_bits;
    SettledAverage m_average;
    ProbePoint m_point;
    double m_quietS = 0.0;
    std::deque<std::int32_t> m_live;
};

}  // namespace tt::core
