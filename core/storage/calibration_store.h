#pragma once

#include <QByteArray>
#include <QString>
#include <optional>
#include <vector>

#include "core/storage/database.h"

namespace tt::core::auth {
class AccessGuard;
}

namespace tt::storage {

/// The schema module "calibration": versioned linearisation tables of the probe mandrels
/// (probe_tables: the image, its fit and points, who and when, upload and read-back) and the
/// k_p calibrations from known loads (kp_calibrations).
SchemaModule calibrationSchema();

/// One saved linearisation table of a probe and bending plane.
struct ProbeTableRecord {
    qint64 id = 0;
    QString probe;      ///< the probe's name
    int plane = 0;      ///< 0 = X (radial), 1 = Y
    int version = 0;    ///< 1, 2, ... per probe and plane (what the image carries)
    QString createdAt;  ///< ISO 8601 UTC
    QString createdBy;
    int adcBits = 0;
    int degree = 0;
    QString coefficients;  ///< "c0 c1 c2 ..." (code = Σ c_i d_µm^i), 17 digits
    double rmsResidualUm = 0.0;
    double maxTableErrorUm = 0.0;
    QString pointsCsv;     ///< the calibration points (reference_um,adc_code)
    QByteArray image;      ///< the binary table image (docs/protocols/linearisation-table.md)
    qint64 imageCrc = 0;   ///< CRC the image carries (format 2: CRC-32C; format 1: CRC-16)
    qint64 uploadCrc = 0;  ///< CRC-32C of the whole image, kept to check it before an upload
    QString uploadedAt;    ///< empty until uploaded
    QString uploadedBy;
    std::optional<qint64> readbackCrc;  ///< what the mandrel reported (CRC-32C; CRC-16 from a protocol-1 mandrel)
    bool verified = false;              ///< read-back version and CRC matched the image
};

/// One k_p calibration from known loads.
struct KpCalibrationRecord {
    qint64 id = 0;
    QString createdAt;
    QString createdBy;
    QString drive;         ///< which cross-feed drive / machine
    double kpNPerA = 0.0;  ///< fitted current-to-force gain
    double offsetN = 0.0;  ///< fitted force at zero current difference
    double r2 = 0.0;
    QString pointsCsv;  ///< load_n,current_difference_a
    QString appliedTo;  ///< tool ids that received the k_p, comma separated
};

/// Calibration records over SQL. Use from the thread that opened the Database.
class CalibrationStore {
public:
    /// Applies the "calibration" migrations to `database` (which must outlive the store).
    explicit CalibrationStore(Database& database);
    /// With a guard, saving a table, recording an upload and saving a k_p need the EditCalibration
    /// permission (else core::auth::PermissionDenied, nothing stored) and record the logged-in user as
    /// the creator; null = not access-controlled (the command line). The guard must outlive the store.
    void setAccess(const core::auth::AccessGuard* access) { m_access = access; }

    /// The version the next table of this probe and plane gets (1 for the first).
    int nextTableVersion(const QString& probe, int plane);
    /// Stores a table as the next version; fills in id, version and createdAt. Throws
    /// std::invalid_argument for an empty probe name, creator or image.
    ProbeTableRecord saveTable(ProbeTableRecord record);
    /// Records an upload and what the mandrel reported back.
    void recordUpload(qint64 tableId, const QString& who, std::optional<qint64> readbackCrc, bool verified);
    /// Every table of a probe (all probes when empty), newest first.
    std::vector<ProbeTableRecord> tables(const QString& probe = {});

    /// Stores a k_p calibration; fills in id and createdAt.
    KpCalibrationRecord saveKp(KpCalibrationRecord record);
    /// Newest first.
    std::vector<KpCalibrationRecord> kpCalibrations();

private:
    /// `who`, or the logged-in user when guarded (after the permission check).
    QString actor(const QString& who) const;

    Database& m_db;
    const core::auth::AccessGuard* m_access = nullptr;
};

}  // namespace tt::storage
