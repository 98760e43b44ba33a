// The calibration records keep 32-bit CRCs (CRC-32C of table image format 2 and probe protocol 2)
// whole on both backends: values above 2^31 - 1 do not fit PostgreSQL's INTEGER, so migration 2 of
// the "calibration" module widens the columns there.
#include <gtest/gtest.h>

#include "core/storage/calibration_store.h"
#include "scratch_database.h"

namespace tt::storage {
namespace {

class Crc32ColumnsTest : public ::testing::TestWithParam<std::string> {};

TEST_P(Crc32ColumnsTest, CrcsAboveTwoToTheThirtyOneRoundTrip) {
    test::ScratchDatabase scratch(GetParam());
    TT_REQUIRE_BACKEND(scratch);
    Database db(scratch.config());
    CalibrationStore store(db);
    EXPECT_EQ(db.schemaVersion(QStringLiteral("calibration")), 2);
    ProbeTableRecord r;
    r.probe = QStringLiteral("Mandrel 16-bit");
    r.createdBy = QStringLiteral("Anna");
    r.adcBits = 16;
    r.degree = 3;
    r.coefficients = QStringLiteral("32767.5 150 0 -3");
    r.pointsCsv = QStringLiteral("reference_um,adc_code\n");
    r.image = QByteArray(131104, '\x5A');
    // CRC-32/ISCSI check value of "123456789" (Greg Cook's catalogue) and the largest CRC.
    r.imageCrc = 0xE3069283;
    r.uploadCrc = 0xFFFFFFFF;
    const ProbeTableRecord saved = store.saveTable(r);
    store.recordUpload(saved.id, QStringLiteral("Boris"), qint64{0xE3069283}, true);
    const std::vector<ProbeTableRecord> back = store.tables(QStringLiteral("Mandrel 16-bit"));
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].imageCrc, 0xE3069283);
    EXPECT_EQ(back[0].uploadCrc, 0xFFFFFFFF);
    ASSERT_TRUE(back[0].readbackCrc.has_value());
    EXPECT_EQ(*back[0].readbackCrc, 0xE3069283);
    EXPECT_EQ(back[0].image.size(), 131104);
}

INSTANTIATE_TEST_SUITE_P(Backends, Crc32ColumnsTest, ::testing::ValuesIn(test::backends()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tt::storage
