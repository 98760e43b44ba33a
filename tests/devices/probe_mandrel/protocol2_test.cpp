// Probe protocol 2 (docs/protocols/probe-mandrel.md): DEVICE_INFO tells the host the mandrel's
// protocol and capacity, TABLE_BEGIN_32 / TABLE_INFO_32 carry the CRC-32C of images up to
// 256 KiB; a mandrel of protocol 1 is recognised and gets tables of at most 64 KiB with CRC-16.
// The host session runs against the emulated mandrel in memory (no wire, no clock).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/calibration/linearisation_image.h"
#include "core/calibration/probe_linearisation.h"
#include "core/common/crc16.h"
#include "core/common/crc32c.h"
#include "devices/parsers/probe_protocol.h"
#include "devices/parsers/probe_session.h"
#include "devices/simulator/mandrel_emulator.h"

namespace tt::devices::probe {
namespace {

std::vector<std::uint8_t> hexBytes(const std::string& text) {
    std::vector<std::uint8_t> out;
    for (std::size_t i = 0; i + 1 < text.size(); i += 3)
        out.push_back(static_cast<std::uint8_t>(std::stoi(text.substr(i, 2), nullptr, 16)));
    return out;
}

/// A table of the emulated mandrel's own characteristic from 21 points over ±0.27 mm, read as
/// rounded ADC codes against an exact reference (what a calibration on the stand gives).
core::Linearisation emulatorTable(int bits) {
    std::vector<core::CalibrationPoint> points;
    const double scale = std::ldexp(1.0, bits - MandrelEmulator::kAdcBits);
    for (int i = 0; i <= 20; ++i) {
        const double mm = -0.27 + 0.027 * i;
        points.push_back({mm * 1000.0, std::round(MandrelEmulator::exactCode(mm) * scale), 0});
    }
    return core::linearise(points, bits, core::kAutoDegree);
}

/// Host session and emulated mandrel in memory: commands are answered at once, samples flow at
/// the mandrel's rate, in steps of 5 ms of the session's clock.
struct InMemoryLink {
    explicit InMemoryLink(int protocol) : mandrel(protocol) {}
    void run(double seconds) {
        for (const double end = t + seconds; t < end; t += 0.005) {
            for (int i = 0; i < 64; ++i) {
                const std::vector<std::uint8_t> out = session.poll(t);
                if (out.empty()) break;
                session.receive(mandrel.receive(out), t);
            }
            session.receive(mandrel.advance(0.005), t);
        }
    }
    ProbeSession session;
    MandrelEmulator mandrel;
    double t = 0.0;
};

TEST(ProbeProtocol2, PayloadsRoundTripAndWrongOnesAreRefused) {
    const auto info = decodeDeviceInfo(encodeDeviceInfo({2, 16, 262144}));
    ASSERT_TRUE(info);
    EXPECT_EQ(info->protocol, 2);
    EXPECT_EQ(info->adcBits, 16);
    EXPECT_EQ(info->maxTableBytes, 262144U);
    EXPECT_FALSE(decodeDeviceInfo(encodeDeviceInfo({1, 16, 65536})));  // DEVICE_INFO exists from protocol 2
    EXPECT_FALSE(decodeDeviceInfo(encodeDeviceInfo({2, 40, 65536})));
    EXPECT_FALSE(decodeDeviceInfo(encodeDeviceInfo({2, 16, 0})));
    EXPECT_FALSE(decodeDeviceInfo(std::vector<std::uint8_t>{2, 16, 0, 0}));

    TableInfoPayload stored{3, 0xBEEF, 131104, true, 0x1A2B3C4DU};
    const auto back = decodeTableInfo32(encodeTableInfo32(stored));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->crc32c, 0x1A2B3C4DU);
    EXPECT_EQ(back->crc, 0xBEEF);
    EXPECT_EQ(back->sizeBytes, 131104U);
    EXPECT_TRUE(back->valid);
    EXPECT_FALSE(decodeTableInfo32(encodeTableInfo(stored)));  // 9 bytes are a protocol-1 TABLE_INFO
    stored.crc32c.reset();
    EXPECT_THROW(encodeTableInfo32(stored), std::invalid_argument);

    const auto begin = decodeTableBegin32(encodeTableBegin32({3, 0x1A2B3C4DU, 131104}));
    ASSERT_TRUE(begin);
    EXPECT_EQ(begin->crc32c, 0x1A2B3C4DU);
    EXPECT_EQ(begin->sizeBytes, 131104U);
    EXPECT_FALSE(decodeTableBegin32(encodeTableBegin({3, 0xBEEF, 1000})));
    EXPECT_EQ(messageTypeName(0x17), "READ_DEVICE_INFO");
    EXPECT_EQ(messageTypeName(0x18), "TABLE_BEGIN_32");
    EXPECT_EQ(messageTypeName(0x19), "READ_TABLE_INFO_32");
    EXPECT_EQ(messageTypeName(0x04), "DEVICE_INFO");
    EXPECT_EQ(messageTypeName(0x05), "TABLE_INFO_32");
}

TEST(ProbeProtocol2, TheDocumentsExampleFramesAreWhatTheCodeSends) {
    // docs/protocols/probe-mandrel.md, "Protocol 2".
    EXPECT_EQ(encodeFrame(0, MessageType::ReadDeviceInfo), hexBytes("A5 00 00 17 4A AE"));
    EXPECT_EQ(encodeFrame(0, MessageType::DeviceInfo, encodeDeviceInfo({2, 16, 262144})),
              hexBytes("A5 06 00 04 02 10 00 00 04 00 E2 C0"));
    EXPECT_EQ(encodeFrame(5, MessageType::TableBegin32, encodeTableBegin32({3, 0x1A2B3C4DU, 131104})),
              hexBytes("A5 0A 05 18 03 00 4D 3C 2B 1A 20 00 02 00 6D AF"));
    EXPECT_EQ(encodeFrame(9, MessageType::TableInfo32, encodeTableInfo32({3, 0xBEEF, 131104, true, 0x1A2B3C4DU})),
              hexBytes("A5 0D 09 05 03 00 4D 3C 2B 1A EF BE 20 00 02 00 01 6E 26"));
}

TEST(ProbeProtocol2, UploaderAnnouncesAndVerifiesTheCrc32c) {
    std::vector<std::uint8_t> img(300);
    for (std::size_t i = 0; i < img.size(); ++i)
        img[i] = static_cast<std::uint8_t>(i * 7);
    const std::uint32_t crc = core::crc32c(img);
    TableUploader up(img, 4, crc);  // protocol 2 unless told otherwise
    ASSERT_EQ(up.current().type, MessageType::TableBegin32);
    EXPECT_EQ(decodeTableBegin32(up.current().payload)->crc32c, crc);
    up.onAck({0x18, AckResult::Ok, 0});
    for (std::uint32_t end : {128U, 256U, 300U})
        up.onAck({0x15, AckResult::Ok, end});
    up.onAck({0x16, AckResult::Ok, 0});
    ASSERT_EQ(up.current().type, MessageType::ReadTableInfo32);
    up.onTableInfo({4, core::crc16Ccitt(img), 300, true, std::nullopt});  // a plain TABLE_INFO: not the answer
    EXPECT_EQ(up.phase(), TableUploader::Phase::Verify);
    up.onTableInfo({4, core::crc16Ccitt(img), 300, true, crc ^ 0x100U});  // flash holds something else
    ASSERT_EQ(up.phase(), TableUploader::Phase::Failed);
    EXPECT_NE(up.failure().find("CRC-32C"), std::string::npos) << up.failure();

    // 256 KiB is the limit of TABLE_BEGIN_32; a protocol-1 mandrel takes at most 64 KiB.
    const std::vector<std::uint8_t> big(kMaxTableBytes32 + 1, 0x11);
    EXPECT_THROW(TableUploader(big, 1, core::crc32c(big)), std::invalid_argument);
    const std::vector<std::uint8_t> sixteenBit(131104, 0x22);
    TableUploader late(sixteenBit, 1, core::crc32c(sixteenBit));
    late.setMandrel(MandrelCapabilities::protocol1());
    ASSERT_EQ(late.phase(), TableUploader::Phase::Failed);
    EXPECT_NE(late.failure().find("protocol 1"), std::string::npos) << late.failure();
}

TEST(ProbeProtocol2, SessionLearnsProtocolTwoAndUploadsASixteenBitTable) {
    InMemoryLink link(2);
    link.session.start(0.0);
    link.run(0.1);
    ASSERT_EQ(link.session.link(), ProbeSession::Link::Streaming) << link.session.problem();
    ASSERT_TRUE(link.session.deviceInfo().has_value());
    EXPECT_EQ(link.session.deviceInfo()->adcBits, 16);
    ASSERT_TRUE(link.session.mandrel().has_value());
    EXPECT_EQ(link.session.mandrel()->protocol, 2);
    EXPECT_EQ(link.session.mandrel()->maxTableBytes, kMaxTableBytes32);
    ASSERT_TRUE(link.session.tableInfo().has_value());
    EXPECT_TRUE(link.session.tableInfo()->crc32c.has_value());  // read with READ_TABLE_INFO_32
    EXPECT_TRUE(link.session.lastError().empty()) << link.session.lastError();

    const core::Linearisation lin = emulatorTable(16);
    const std::vector<std::uint8_t> image = core::encodeTableImage(lin.table, {5, 0, 0, 3});
    ASSERT_EQ(image.size(), 131104U);
    link.session.uploadTable(image, 5, core::tableUploadCrc(image));
    link.run(0.5);  // 1025 chunks; each answered at once
    ASSERT_EQ(link.session.uploadState().phase, TableUploader::Phase::Done) << link.session.uploadState().message;
    EXPECT_EQ(link.mandrel.tableImage(), image);
    EXPECT_EQ(link.session.tableInfo()->crc32c, core::crc32c(image));
    EXPECT_NE(link.session.uploadState().message.find("CRC-32C"), std::string::npos);
}

TEST(ProbeProtocol2, AProtocolOneMandrelIsRecognisedAndGetsOnlyTablesItCanStore) {
    InMemoryLink link(1);
    link.session.start(0.0);
    // Asked before the handshake found out: the uploader learns the protocol before sending.
    const std::vector<std::uint8_t> big = core::encodeTableImage(emulatorTable(16).table, {2, 0, 0, 3});
    link.session.uploadTable(big, 2, core::crc32c(big));
    link.run(0.2);
    ASSERT_EQ(link.session.link(), ProbeSession::Link::Streaming) << link.session.problem();
    ASSERT_TRUE(link.session.mandrel().has_value());
    EXPECT_EQ(link.session.mandrel()->protocol, 1);
    EXPECT_FALSE(link.session.deviceInfo().has_value());
    EXPECT_TRUE(link.session.lastError().empty()) << link.session.lastError();  // the unknown command is the answer
    EXPECT_FALSE(link.session.tableInfo()->crc32c.has_value());
    ASSERT_EQ(link.session.uploadState().phase, TableUploader::Phase::Failed);
    EXPECT_NE(link.session.uploadState().message.find("protocol 1"), std::string::npos)
        << link.session.uploadState().message;
    EXPECT_TRUE(link.mandrel.tableImage().empty());  // nothing was sent

    // A 12-bit table in format 1 (what protocol-1 firmware reads) goes through with its CRC-16.
    const std::vector<std::uint8_t> small =
        core::encodeTableImage(emulatorTable(12).table, {3, 0, 0, 3}, core::kTableImageFormatCrc16);
    link.session.uploadTable(small, 3, core::crc32c(small));
    link.run(0.2);
    ASSERT_EQ(link.session.uploadState().phase, TableUploader::Phase::Done) << link.session.uploadState().message;
    EXPECT_EQ(link.mandrel.tableImage(), small);
    EXPECT_EQ(link.session.tableInfo()->crc, core::crc16Ccitt(small));
    EXPECT_EQ(link.mandrel.commandsHandled() > 0, true);
}

}  // namespace
}  // namespace tt::devices::probe
