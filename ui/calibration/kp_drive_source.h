#pragma once

#include <QString>

#include "core/ports/drive_current.h"
#include "core/sim/rigs/known_load_rig.h"

namespace tt::ui {

/// The cross-feed drive as the k_p wizard sees it: its current read-out (the engine's port) while
/// the cross feed dithers, and, on the simulator, the hydraulic jack that applies the known load.
class KpDriveSource {
public:
    virtual ~KpDriveSource() = default;
    virtual QString name() const = 0;
    virtual core::DriveCurrentReadout& readout() = 0;
    /// Lets the drive work for `seconds` (the simulator advances its clock; a device ignores it).
    virtual void poll(double seconds) { (void)seconds; }
    /// Simulator only: the jack applies `loadN` (on a machine the operator applies the load).
    virtual bool canApplyLoad() const { return false; }
    virtual void applyLoadN(double loadN) { (void)loadN; }
};

/// The built-in simulated cross feed on the k_p stand (core::KnownLoadRig with the heavy-boring
/// drive and dither: true k_p 150 N/A, Coulomb friction 975 N, current noise 0.3 A).
class SimulatedKpDrive final : public KpDriveSource {
public:
    explicit SimulatedKpDrive(const QString& name, unsigned long long seed = 3)
        : m_name(name), m_rig(core::CrossFeedDriveConfig{}, core::DitherConfig{0.01, 0.5, 0.6}, 0.02, seed) {}
    QString name() const override { return m_name; }
    core::DriveCurrentReadout& readout() override { return m_rig; }
    void poll(double seconds) override { m_rig.advance(seconds); }
    bool canApplyLoad() const override { return true; }
    void applyLoadN(double loadN) override { m_rig.setLoadN(loadN); }

private:
    QString m_name;
    core::KnownLoadRig m_rig;
};

}  // namespace tt::ui
