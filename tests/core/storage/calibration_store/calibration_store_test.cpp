// Versioned probe tables and k_p calibrations over SQL, on SQLite and PostgreSQL.
#include "core/storage/calibration_store.h"

#include <gtest/gtest.h>

#include "scratch_database.h"

namespace tt::storage {
namespace {

ProbeTableRecord table(const QString& probe, int plane) {
    ProbeTableRecord r;
    r.probe = probe;
    r.plane = plane;
    r.createdBy = QStringLiteral("Anna");
    r.adcBits = 12;
    r.degree = 3;
    r.coefficients = QStringLiteral("2047.5 3 0.0002 3e-06");
    r.rmsResidualUm = 0.35;
    r.maxTableErrorUm = 0.8;
    r.pointsCsv = QStringLiteral("reference_um,adc_code\n-500,200\n");
    r.image = QByteArray("TTLT\x01 binary\x00\xff", 14);
    r.imageCrc = 0x1234;
    r.uploadCrc = 0xBEEF;
    return r;
}

class CalibrationStoreTest : public ::testing::TestWithParam<std::string> {};

TEST_P(CalibrationStoreTest, VersionsTablesPerProbeAndPlaneAndRecordsTheUpload) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    CalibrationStore store(db);
    EXPECT_EQ(store.nextTableVersion(QStringLiteral("Mandrel 1"), 0), 1);
    const ProbeTableRecord first = store.saveTable(table(QStringLiteral("Mandrel 1"), 0));
    const ProbeTableRecord second = store.saveTable(table(QStringLiteral("Mandrel 1"), 0));
    const ProbeTableRecord other = store.saveTable(table(QStringLiteral("Mandrel 1"), 1));
    EXPECT_EQ(first.version, 1);
    EXPECT_EQ(second.version, 2);
    EXPECT_EQ(other.version, 1);
    EXPECT_FALSE(first.createdAt.isEmpty());
    store.recordUpload(second.id, QStringLiteral("Boris"), 0xBEEF, true);
    const std::vector<ProbeTableRecord> all = store.tables(QStringLiteral("Mandrel 1"));
    ASSERT_EQ(all.size(), 3u);
    const ProbeTableRecord& back = all[1];  // newest first: other, second, first
    EXPECT_EQ(back.version, 2);
    EXPECT_EQ(back.image, table(QString(), 0).image);  // bytes intact, NUL and 0xFF included
    EXPECT_EQ(back.uploadedBy, QStringLiteral("Boris"));
    ASSERT_TRUE(back.readbackCrc.has_value());
    EXPECT_EQ(*back.readbackCrc, 0xBEEF);
    EXPECT_TRUE(back.verified);
    EXPECT_FALSE(all[2].readbackCrc.has_value());
    EXPECT_TRUE(store.tables(QStringLiteral("Mandrel 9")).empty());
    ProbeTableRecord nobody = table(QStringLiteral("Mandrel 1"), 0);
    nobody.createdBy = QString();
    EXPECT_THROW(store.saveTable(nobody), std::invalid_argument);
}

TEST_P(CalibrationStoreTest, StoresKpCalibrations) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    CalibrationStore store(db);
    KpCalibrationRecord r;
    r.createdBy = QStringLiteral("Anna");
    r.drive = QStringLiteral("Cross feed X");
    r.kpNPerA = 149.2;
    r.offsetN = -3.0;
    r.r2 = 0.9995;
    r.pointsCsv = QStringLiteral("load_n,current_difference_a\n0,0.01\n");
    r.appliedTo = QStringLiteral("T12,T13");
    store.saveKp(r);
    const std::vector<KpCalibrationRecord> all = store.kpCalibrations();
    ASSERT_EQ(all.size(), 1u);
    EXPECT_DOUBLE_EQ(all[0].kpNPerA, 149.2);
    EXPECT_EQ(all[0].appliedTo, QStringLiteral("T12,T13"));
}

INSTANTIATE_TEST_SUITE_P(Backends, CalibrationStoreTest, ::testing::ValuesIn(test::backends()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tt::storage
