// Upload with read-back as a state machine: a scripted mandrel link that stores, fails, answers
// late or not at all; the outcome is a kind with the read-back as data.
#include "core/calibration/table_upload.h"

#include <gtest/gtest.h>

#include <numeric>

#include "core/common/crc16.h"
#include "core/common/crc32c.h"

namespace tt::core {
namespace {

/// A mandrel link the test scripts: it stores what it is sent (one byte wrong when the flash is
/// faulty) and reports it from the `answerAfter`-th read-back request on.
class ScriptedMandrel final : public TableUploadPort {
public:
    void startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) override {
        if (refuse) throw std::invalid_argument("the mandrel is busy");
        if (core::crc32c(image) != crc32c) throw std::invalid_argument("CRC");
        sent = std::move(image);
        sentVersion = version;
        status = {UploadLinkStatus::Phase::Running, 0.5, "chunk 1 of 2"};
    }
    UploadLinkStatus uploadStatus() const override { return status; }
    void requestReadback() override {
        if (++requests < answerAfter) return;
        std::vector<std::uint8_t> stored = sent;
        if (faultyFlash) stored[3] ^= 0x01;
        held = TableReadback{sentVersion, crc16Ccitt(stored), core::crc32c(stored),
                             static_cast<std::uint32_t>(stored.size()), true};
    }
    std::optional<TableReadback> readback() const override { return held; }

    bool refuse = false;
    bool faultyFlash = false;
    int answerAfter = 1;
    int requests = 0;
    std::vector<std::uint8_t> sent;
    std::uint16_t sentVersion = 0;
    UploadLinkStatus status;
    std::optional<TableReadback> held{TableReadback{1, 0x1234, 0x89ABCDEFu, 100, true}};  ///< the table before
};

std::vector<std::uint8_t> image() {
    std::vector<std::uint8_t> bytes(300);
    std::iota(bytes.begin(), bytes.end(), std::uint8_t{7});
    return bytes;
}

TEST(TableUpload, VerifiesTheReadBackEvenWhenTheFirstAnswerIsTheOldTable) {
    ScriptedMandrel mandrel;
    mandrel.answerAfter = 3;  // two answers still describe the table held before
    TableUploadProcedure upload(3.0);
    upload.start(mandrel, image(), 2);
    EXPECT_EQ(upload.phase(), TableUploadProcedure::Phase::Sending);
    EXPECT_EQ(upload.imageCrc32c(), crc32c(image()));
    upload.pump(mandrel, 0.1);
    EXPECT_DOUBLE_EQ(upload.progress(), 0.5);
    EXPECT_EQ(upload.deviceMessage(), "chunk 1 of 2");
    mandrel.status = {UploadLinkStatus::Phase::Done, 1.0, {}};
    upload.pump(mandrel, 0.1);
    EXPECT_EQ(upload.phase(), TableUploadProcedure::Phase::ReadingBack);
    upload.pump(mandrel, 0.1);
    EXPECT_EQ(upload.phase(), TableUploadProcedure::Phase::ReadingBack);  // version 1: not yet
    upload.pump(mandrel, 0.1);
    EXPECT_EQ(upload.phase(), TableUploadProcedure::Phase::Verified);
    EXPECT_EQ(upload.readback()->version, 2);
    EXPECT_FALSE(upload.running());
}

TEST(TableUpload, SaysWhetherTheMandrelHoldsAnotherTableAnswersNotOrRefuses) {
    ScriptedMandrel faulty;
    faulty.faultyFlash = true;
    TableUploadProcedure upload(1.0);
    upload.start(faulty, image(), 2);
    faulty.status = {UploadLinkStatus::Phase::Done, 1.0, {}};
    for (int i = 0; i < 20 && upload.running(); ++i)
        upload.pump(faulty, 0.1);
    EXPECT_EQ(upload.phase(), TableUploadProcedure::Phase::Mismatch);
    EXPECT_EQ(upload.problem(), TableUploadProcedure::Problem::ReadbackDiffers);
    EXPECT_NE(upload.readback()->crc(), upload.imageCrc32c());

    ScriptedMandrel silent;
    silent.held.reset();
    silent.answerAfter = 1000;
    upload.start(silent, image(), 3);
    silent.status = {UploadLinkStatus::Phase::Done, 1.0, {}};
    for (int i = 0; i < 20 && upload.running(); ++i)
        upload.pump(silent, 0.1);
    EXPECT_EQ(upload.problem(), TableUploadProcedure::Problem::NoReadback);

    // The link fails in its own read-back check: the mandrel is asked, and its answer kept.
    ScriptedMandrel failing;
    failing.faultyFlash = true;
    upload.start(failing, image(), 4);
    failing.status = {UploadLinkStatus::Phase::Failed, 1.0, "verification failed"};
    for (int i = 0; i < 20 && upload.running(); ++i)
        upload.pump(failing, 0.1);
    EXPECT_EQ(upload.phase(), TableUploadProcedure::Phase::Failed);
    EXPECT_EQ(upload.problem(), TableUploadProcedure::Problem::LinkFailed);
    EXPECT_EQ(upload.deviceMessage(), "verification failed");
    ASSERT_TRUE(upload.readback());
    EXPECT_EQ(upload.readback()->version, 4);

    ScriptedMandrel busy;
    busy.refuse = true;
    upload.start(busy, image(), 5);
    EXPECT_EQ(upload.problem(), TableUploadProcedure::Problem::Refused);
    EXPECT_EQ(upload.deviceMessage(), "the mandrel is busy");

    ScriptedMandrel slow;
    upload.start(slow, image(), 6);
    EXPECT_THROW(upload.start(slow, image(), 6), std::logic_error);
    upload.abort();
    EXPECT_EQ(upload.problem(), TableUploadProcedure::Problem::Aborted);
    EXPECT_THROW(upload.start(slow, {}, 6), std::invalid_argument);
}

}  // namespace
}  // namespace tt::core
