#include "devices/parsers/probe_protocol.h"

#include <gtest/gtest.h>

#include <numeric>

#include "core/common/crc16.h"
#include "core/common/crc32c.h"

namespace tt::devices::probe {
namespace {

SamplePayload sample(std::uint32_t t) {
    SamplePayload s;
    s.timeUs = t;
    s.adcCode = {31000 + static_cast<std::int32_t>(t % 100), -12};
    s.deflectionNm = {-25000, 1300};
    s.status = kStatusTableValid | kStatusStreaming;
    return s;
}

std::vector<std::uint8_t> sampleFrame(std::uint8_t seq, std::uint32_t t = 0) {
    return encodeFrame(seq, MessageType::Sample, encodeSample(sample(t)));
}

TEST(ProbeFrame, LayoutIsSyncLengthSequenceTypePayloadCrc) {
    const std::vector<std::uint8_t> payload{0x10, 0x00};
    const auto frame = encodeFrame(7, MessageType::SetRate, payload);
    ASSERT_EQ(frame.size(), 4u + 2u + 2u);
    EXPECT_EQ(frame[0], 0xA5);
    EXPECT_EQ(frame[1], 2);
    EXPECT_EQ(frame[2], 7);
    EXPECT_EQ(frame[3], 0x12);
    // CRC-16/CCITT-FALSE over LEN..PAYLOAD, little-endian (docs/protocols/probe-mandrel.md).
    const std::uint16_t crc = core::crc16Ccitt(std::span(frame).subspan(1, 5));
    EXPECT_EQ(frame[6], crc & 0xFF);
    EXPECT_EQ(frame[7], crc >> 8);
    EXPECT_THROW(encodeFrame(0, 0x01, std::vector<std::uint8_t>(251)), std::invalid_argument);
}

TEST(ProbeFrame, TheExamplesOfTheProtocolDocument) {
    // docs/protocols/probe-mandrel.md, "Frame": SET_RATE 200 Hz as host frame 7, and a sample as
    // mandrel frame 42.
    EXPECT_EQ(encodeFrame(7, MessageType::SetRate, encodeRate(200)),
              (std::vector<std::uint8_t>{0xA5, 0x02, 0x07, 0x12, 0xC8, 0x00, 0x5C, 0xB6}));
    SamplePayload s;
    s.timeUs = 125000;
    s.adcCode = {36728, 31769};
    s.deflectionNm = {20000, -5000};
    s.status = kStatusTableValid | kStatusStreaming;
    EXPECT_EQ(encodeFrame(42, MessageType::Sample, encodeSample(s)),
              (std::vector<std::uint8_t>{0xA5, 0x16, 0x2A, 0x01, 0x48, 0xE8, 0x01, 0x00, 0x78, 0x8F,
                                         0x00, 0x00, 0x19, 0x7C, 0x00, 0x00, 0x20, 0x4E, 0x00, 0x00,
                                         0x78, 0xEC, 0xFF, 0xFF, 0x11, 0x00, 0xAB, 0x0A}));
}

TEST(ProbeFrame, SampleRoundTripsThroughTheReader) {
    FrameReader reader;
    const auto frames = reader.feed(sampleFrame(0, 1234));
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0].type, static_cast<std::uint8_t>(MessageType::Sample));
    const auto s = decodeSample(frames[0].payload);
    ASSERT_TRUE(s) << s.error();
    EXPECT_EQ(s->timeUs, 1234u);
    EXPECT_EQ(s->adcCode[0], 31034);
    EXPECT_EQ(s->adcCode[1], -12);
    EXPECT_EQ(s->deflectionNm[0], -25000);
    EXPECT_EQ(s->status, kStatusTableValid | kStatusStreaming);
    EXPECT_FALSE(decodeSample(std::vector<std::uint8_t>(21)));
}

TEST(ProbeFrame, FramesSplitAnywhereAcrossReadsAreReassembled) {
    std::vector<std::uint8_t> stream;
    for (std::uint8_t seq = 0; seq < 5; ++seq) {
        const auto f = sampleFrame(seq, seq);
        stream.insert(stream.end(), f.begin(), f.end());
    }
    FrameReader reader;
    std::size_t got = 0;
    for (std::size_t i = 0; i < stream.size(); i += 3)
        got += reader.feed(std::span(stream).subspan(i, std::min<std::size_t>(3, stream.size() - i))).size();
    EXPECT_EQ(got, 5u);
    EXPECT_EQ(reader.stats().lost, 0u);
    EXPECT_EQ(reader.stats().discardedBytes, 0u);
}

TEST(ProbeFrame, CorruptFramesAreCountedAndNeverReturned) {
    FrameReader reader;
    auto good0 = sampleFrame(0);
    auto bad1 = sampleFrame(1);
    bad1[10] ^= 0x40;  // one flipped bit in the payload
    auto good2 = sampleFrame(2);
    std::vector<std::uint8_t> stream = good0;
    stream.insert(stream.end(), bad1.begin(), bad1.end());
    stream.insert(stream.end(), good2.begin(), good2.end());
    const auto frames = reader.feed(stream);
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(frames[0].sequence, 0);
    EXPECT_EQ(frames[1].sequence, 2);
    EXPECT_EQ(reader.stats().corrupt, 1u);
    EXPECT_EQ(reader.stats().lost, 1u);  // the corrupt frame is also missing from the sequence
    EXPECT_EQ(reader.stats().frames, 2u);
}

TEST(ProbeFrame, ACorruptFrameIsCountedOnceEvenWithSyncBytesInside) {
    // A payload full of SYNC values with plausible lengths after them: after the CRC fails, every
    // 0xA5 inside looks like a frame start; none of them may count as another corrupt frame.
    std::vector<std::uint8_t> payload;
    for (int i = 0; i < 10; ++i) {
        payload.push_back(kSync);
        payload.push_back(2);
    }
    auto bad = encodeFrame(5, 0x01, payload);
    bad.back() ^= 0xFF;  // CRC broken
    std::vector<std::uint8_t> stream = bad;
    const auto good = sampleFrame(6);
    stream.insert(stream.end(), good.begin(), good.end());
    FrameReader reader;
    const auto frames = reader.feed(stream);
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0].sequence, 6);
    EXPECT_EQ(reader.stats().corrupt, 1u);
    EXPECT_EQ(reader.stats().malformed, 0u);
}

TEST(ProbeFrame, LostAndDuplicatedFramesAreDetectedByTheSequence) {
    FrameReader reader;
    std::size_t used = 0;
    for (std::uint8_t seq : {10, 11, 11, 14, 15, 13, 16})
        used += reader.feed(sampleFrame(seq)).size();
    EXPECT_EQ(used, 5u);                      // 10 11 14 15 16
    EXPECT_EQ(reader.stats().duplicate, 2u);  // the second 11 and the late 13
    EXPECT_EQ(reader.stats().lost, 2u);       // 12 and 13 missing when 14 arrived
    // The sequence wraps from 255 to 0 without a loss.
    FrameReader wrap;
    for (int seq : {254, 255, 0, 1})
        wrap.feed(sampleFrame(static_cast<std::uint8_t>(seq)));
    EXPECT_EQ(wrap.stats().lost, 0u);
    EXPECT_EQ(wrap.stats().frames, 4u);
}

TEST(ProbeFrame, AMandrelRestartResynchronisesAfterThreeFrames) {
    FrameReader reader;
    for (std::uint8_t seq = 0; seq < 50; ++seq)
        reader.feed(sampleFrame(seq));
    std::size_t used = 0;
    for (std::uint8_t seq = 0; seq < 5; ++seq)
        used += reader.feed(sampleFrame(seq)).size();
    EXPECT_EQ(used, 3u);  // 0 and 1 look stale, 2 resynchronises, 3 and 4 follow
    EXPECT_EQ(reader.stats().resyncs, 1u);
}

TEST(ProbeFrame, GarbageAndImpossibleLengthsAreSkipped) {
    FrameReader reader;
    std::vector<std::uint8_t> stream{0x00, 0xA5, 0xFF, 0x13, 0x55};  // SYNC with length 255: malformed
    const auto f = sampleFrame(3);
    stream.insert(stream.end(), f.begin(), f.end());
    const auto frames = reader.feed(stream);
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(reader.stats().malformed, 1u);
    EXPECT_EQ(reader.stats().discardedBytes, 5u);
}

TEST(ProbePayloads, RoundTripAndRefuseWrongLengths) {
    const auto ack = decodeAck(encodeAck({0x15, AckResult::OutOfOrder, 256}));
    ASSERT_TRUE(ack);
    EXPECT_EQ(ack->command, 0x15);
    EXPECT_EQ(ack->result, AckResult::OutOfOrder);
    EXPECT_EQ(ack->detail, 256u);
    EXPECT_FALSE(decodeAck(std::vector<std::uint8_t>{0x15, 9, 0, 0, 0, 0}));
    const auto info = decodeTableInfo(encodeTableInfo({3, 0xBEEF, 1024, true, std::nullopt}));
    ASSERT_TRUE(info);
    EXPECT_EQ(info->version, 3);
    EXPECT_EQ(info->crc, 0xBEEF);
    EXPECT_EQ(info->sizeBytes, 1024u);
    EXPECT_TRUE(info->valid);
    const auto chunk = decodeTableChunk(encodeTableChunk({128, {1, 2, 3}}));
    ASSERT_TRUE(chunk);
    EXPECT_EQ(chunk->offset, 128u);
    EXPECT_EQ(chunk->bytes, (std::vector<std::uint8_t>{1, 2, 3}));
    EXPECT_FALSE(decodeTableChunk(std::vector<std::uint8_t>{0, 0, 0, 0}));
    EXPECT_EQ(decodeRate(encodeRate(500)).value(), 500);
    EXPECT_FALSE(decodeRate(std::vector<std::uint8_t>{0, 0}));
    EXPECT_THROW(encodeRate(0), std::invalid_argument);
    EXPECT_EQ(messageTypeName(0x14), "TABLE_BEGIN");
    EXPECT_EQ(messageTypeName(0x7F), "type 0x7F");
}

std::vector<std::uint8_t> image(std::size_t n) {
    std::vector<std::uint8_t> v(n);
    std::iota(v.begin(), v.end(), std::uint8_t{7});
    return v;
}

// Protocol 1 (TABLE_BEGIN and TABLE_INFO with the CRC-16); protocol 2: tests/devices/probe_protocol2/.
TEST(TableUploader, WalksBeginChunksCommitVerify) {
    const auto img = image(300);
    const std::uint16_t crc = core::crc16Ccitt(img);
    TableUploader up(img, 4, core::crc32c(img), MandrelCapabilities::protocol1());
    ASSERT_EQ(up.chunkCount(), 3u);  // 128 + 128 + 44
    EXPECT_EQ(up.current().type, MessageType::TableBegin);
    const auto begin = decodeTableBegin(up.current().payload);
    EXPECT_EQ(begin->sizeBytes, 300u);
    up.onAck({0x14, AckResult::Ok, 0});
    std::vector<std::uint8_t> received;
    for (std::size_t i = 0; i < 3; ++i) {
        ASSERT_EQ(up.current().type, MessageType::TableChunk);
        const auto c = decodeTableChunk(up.current().payload);
        EXPECT_EQ(c->offset, received.size());
        received.insert(received.end(), c->bytes.begin(), c->bytes.end());
        if (i == 1) up.onAck({0x15, AckResult::Ok, 128});  // late ACK of chunk 0: ignored
        up.onAck({0x15, AckResult::Ok, static_cast<std::uint32_t>(received.size())});
    }
    EXPECT_EQ(received, img);
    EXPECT_EQ(up.current().type, MessageType::TableCommit);
    up.onAck({0x16, AckResult::Ok, 0});
    EXPECT_EQ(up.current().type, MessageType::ReadTableInfo);
    up.onTableInfo({4, crc, 300, true, std::nullopt});
    EXPECT_EQ(up.phase(), TableUploader::Phase::Done);
    EXPECT_DOUBLE_EQ(up.progress(), 1.0);
}

TEST(TableUploader, FailsOnRefusalOrAWrongTableAndNeverSendsACorruptImage) {
    const auto img = image(10);
    const std::uint16_t crc = core::crc16Ccitt(img);
    const std::uint32_t record = core::crc32c(img);
    const MandrelCapabilities v1 = MandrelCapabilities::protocol1();
    EXPECT_THROW(TableUploader(img, 1, record ^ 1, v1), std::invalid_argument);
    EXPECT_THROW(TableUploader({}, 1, 0, v1), std::invalid_argument);
    TableUploader refused(img, 1, record, v1);
    refused.onAck({0x14, AckResult::BadArgument, 0});
    EXPECT_EQ(refused.phase(), TableUploader::Phase::Failed);
    EXPECT_NE(refused.failure().find("value out of range"), std::string::npos);
    TableUploader wrong(img, 2, record, v1);
    wrong.onAck({0x14, AckResult::Ok, 0});
    wrong.onAck({0x15, AckResult::Ok, 10});
    wrong.onAck({0x16, AckResult::Ok, 0});
    wrong.onTableInfo({1, crc, 10, true, std::nullopt});  // the mandrel still has version 1
    EXPECT_EQ(wrong.phase(), TableUploader::Phase::Failed);
    EXPECT_NE(wrong.failure().find("version 1"), std::string::npos) << wrong.failure();
}

}  // namespace
}  // namespace tt::devices::probe
