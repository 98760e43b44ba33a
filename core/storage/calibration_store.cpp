#include "core/storage/calibration_store.h"

#include <QSqlQuery>
#include <QVariant>
#include <stdexcept>

#include "core/auth/access_guard.h"

namespace tt::storage {

namespace {

const char* kTableColumns =
    "id, probe, plane, version, created_at, created_by, adc_bits, degree, coefficients, rms_residual_um,"
    " max_table_error_um, points_csv, image, image_crc, upload_crc, uploaded_at, uploaded_by, readback_crc, verified";

ProbeTableRecord readTable(const QSqlQuery& q) {
    ProbeTableRecord r;
    r.id = q.value(0).toLongLong();
    r.probe = q.value(1).toString();
    r.plane = q.value(2).toInt();
    r.version = q.value(3).toInt();
    r.createdAt = q.value(4).toString();
    r.createdBy = q.value(5).toString();
    r.adcBits = q.value(6).toInt();
    r.degree = q.value(7).toInt();
    r.coefficients = q.value(8).toString();
    r.rmsResidualUm = q.value(9).toDouble();
    r.maxTableErrorUm = q.value(10).toDouble();
    r.pointsCsv = q.value(11).toString();
    r.image = q.value(12).toByteArray();
    r.imageCrc = q.value(13).toLongLong();
    r.uploadCrc = q.value(14).toLongLong();
    r.uploadedAt = q.value(15).toString();
    r.uploadedBy = q.value(16).toString();
    if (!q.value(17).isNull()) r.readbackCrc = q.value(17).toLongLong();
    r.verified = q.value(18).toInt() != 0;
    return r;
}

}  // namespace

SchemaModule calibrationSchema() {
    SchemaModule module{QStringLiteral("calibration"), {}};
    module.migrations.push_back(
        {1, QStringLiteral("probe linearisation tables, k_p calibrations"), [](Database& db) {
             db.exec(QStringLiteral(
                 "CREATE TABLE probe_tables (id {pk}, probe TEXT NOT NULL, plane INTEGER NOT NULL,"
                 " version INTEGER NOT NULL, created_at TEXT NOT NULL, created_by TEXT NOT NULL,"
                 " adc_bits INTEGER NOT NULL, degree INTEGER NOT NULL, coefficients TEXT NOT NULL,"
                 " rms_residual_um {real} NOT NULL, max_table_error_um {real} NOT NULL, points_csv TEXT NOT NULL,"
                 " image {blob} NOT NULL, image_crc INTEGER NOT NULL, upload_crc INTEGER NOT NULL,"
                 " uploaded_at TEXT NOT NULL, uploaded_by TEXT NOT NULL, readback_crc INTEGER,"
                 " verified INTEGER NOT NULL, UNIQUE (probe, plane, version))"));
             db.exec(QStringLiteral(
                 "CREATE TABLE kp_calibrations (id {pk}, created_at TEXT NOT NULL, created_by TEXT NOT NULL,"
                 " drive TEXT NOT NULL, kp_n_per_a {real} NOT NULL, offset_n {real} NOT NULL, r2 {real} NOT NULL,"
                 " points_csv TEXT NOT NULL, applied_to TEXT NOT NULL)"));
         }});
    // CRC-32C values (table image format 2, probe protocol 2) exceed a 32-bit signed integer.
    // SQLite's INTEGER already holds 64 bits; PostgreSQL's is 32-bit.
    module.migrations.push_back(
        {2, QStringLiteral("64-bit CRC columns for CRC-32C"), [](Database& db) {
             if (!db.isPostgres()) return;
             db.exec(
                 QStringLiteral("ALTER TABLE probe_tables ALTER COLUMN image_crc TYPE BIGINT,"
                                " ALTER COLUMN upload_crc TYPE BIGINT, ALTER COLUMN readback_crc TYPE BIGINT"));
         }});
    return module;
}

CalibrationStore::CalibrationStore(Database& database) : m_db(database) {
    m_db.migrate(calibrationSchema());
}

QString CalibrationStore::actor(const QString& who) const {
    if (!m_access) return who;
    return QString::fromStdString(m_access->require(core::auth::Permission::EditCalibration).name);
}

int CalibrationStore::nextTableVersion(const QString& probe, int plane) {
    QSqlQuery q = m_db.exec(QStringLiteral("SELECT MAX(version) FROM probe_tables WHERE probe = ? AND plane = ?"),
                            {probe, plane});
    return q.next() && !q.value(0).isNull() ? q.value(0).toInt() + 1 : 1;
}

ProbeTableRecord CalibrationStore::saveTable(ProbeTableRecord r) {
    r.createdBy = actor(r.createdBy);
    if (r.probe.trimmed().isEmpty()) throw std::invalid_argument("the table needs the probe's name");
    if (r.createdBy.trimmed().isEmpty())
        throw std::invalid_argument("the operator's name is needed to save a table (Settings → Operator)");
    if (r.image.isEmpty()) throw std::invalid_argument("the table image is empty");
    m_db.transaction([&] {
        r.version = nextTableVersion(r.probe, r.plane);
        r.createdAt = utcNowText();
        QSqlQuery q = m_db.exec(
            QStringLiteral("INSERT INTO probe_tables (probe, plane, version, created_at, created_by, adc_bits, degree,"
                           " coefficients, rms_residual_um, max_table_error_um, points_csv, image, image_crc,"
                           " upload_crc, uploaded_at, uploaded_by, readback_crc, verified)"
                           " VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, '', '', NULL, 0)"),
            {r.probe, r.plane, r.version, r.createdAt, r.createdBy, r.adcBits, r.degree, r.coefficients,
             r.rmsResidualUm, r.maxTableErrorUm, r.pointsCsv, r.image, r.imageCrc, r.uploadCrc});
        r.id = m_db.lastInsertId(q);
    });
    return r;
}

void CalibrationStore::recordUpload(qint64 tableId, const QString& who, std::optional<qint64> readbackCrc,
                                    bool verified) {
    const QString uploader = actor(who);
    m_db.exec(QStringLiteral("UPDATE probe_tables SET uploaded_at = ?, uploaded_by = ?, readback_crc = ?, verified = ?"
                             " WHERE id = ?"),
              {utcNowText(), uploader, nullable<qint64>(readbackCrc), verified ? 1 : 0, tableId});
}

std::vector<ProbeTableRecord> CalibrationStore::tables(const QString& probe) {
    std::vector<ProbeTableRecord> out;
    QSqlQuery q =
        probe.isEmpty()
            ? m_db.exec(
                  QStringLiteral("SELECT %1 FROM probe_tables ORDER BY id DESC").arg(QLatin1String(kTableColumns)))
            : m_db.exec(QStringLiteral("SELECT %1 FROM probe_tables WHERE probe = ? ORDER BY id DESC")
                            .arg(QLatin1String(kTableColumns)),
                        {probe});
    while (q.next())
        out.push_back(readTable(q));
    return out;
}

KpCalibrationRecord CalibrationStore::saveKp(KpCalibrationRecord r) {
    r.createdBy = actor(r.createdBy);
    if (r.createdBy.trimmed().isEmpty())
        throw std::invalid_argument("the operator's name is needed to save a calibration (Settings → Operator)");
    r.createdAt = utcNowText();
    QSqlQuery q = m_db.exec(QStringLiteral("INSERT INTO kp_calibrations (created_at, created_by, drive, kp_n_per_a,"
                                           " offset_n, r2, points_csv, applied_to) VALUES (?, ?, ?, ?, ?, ?, ?, ?)"),
                            {r.createdAt, r.createdBy, r.drive, r.kpNPerA, r.offsetN, r.r2, r.pointsCsv, r.appliedTo});
    r.id = m_db.lastInsertId(q);
    return r;
}

std::vector<KpCalibrationRecord> CalibrationStore::kpCalibrations() {
    std::vector<KpCalibrationRecord> out;
    QSqlQuery q =
        m_db.exec(QStringLiteral("SELECT id, created_at, created_by, drive, kp_n_per_a, offset_n, r2,"
                                 " points_csv, applied_to FROM kp_calibrations ORDER BY id DESC"));
    while (q.next())
        out.push_back({q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(), q.value(3).toString(),
                       q.value(4).toDouble(), q.value(5).toDouble(), q.value(6).toDouble(), q.value(7).toString(),
                       q.value(8).toString()});
    return out;
}

}  // namespace tt::storage
