// libFuzzer target: the probe-mandrel frame reader, the payload decoders and the host session
// on arbitrary bytes from the mandrel.
#include <cstddef>
#include <cstdint>
#include <span>

#include "devices/parsers/probe_protocol.h"
#include "devices/parsers/probe_session.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tt::devices::probe;
    const std::span<const std::uint8_t> bytes(data, size);
    FrameReader reader;
    // Fed in pieces whose lengths come from the data itself.
    std::size_t at = 0;
    while (at < size) {
        const std::size_t piece = 1 + data[at] % 64;
        const std::size_t n = piece < size - at ? piece : size - at;
        for (const Frame& f : reader.feed(bytes.subspan(at, n))) {
            if (f.payload.size() > kMaxPayload) __builtin_trap();
            (void)decodeSample(f.payload);
            (void)decodeAck(f.payload);
            (void)decodeTableInfo(f.payload);
            (void)decodeTableInfo32(f.payload);
            (void)decodeDeviceInfo(f.payload);
            (void)decodeTableBegin(f.payload);
            (void)decodeTableBegin32(f.payload);
            (void)decodeTableChunk(f.payload);
            (void)decodeRate(f.payload);
            (void)messageTypeName(f.type);
        }
        at += n;
    }
    const FrameStats& s = reader.stats();
    if (s.frames + s.discardedBytes > size) __builtin_trap();  // never more out than in
    // The host session takes the same bytes while talking to the mandrel.
    ProbeSession session;
    double t = 0.0;
    session.start(t);
    for (std::size_t i = 0; i < size; i += 17) {
        (void)session.poll(t);
        session.receive(bytes.subspan(i, size - i < 17 ? size - i : 17), t);
        t += 0.05;
    }
    (void)session.takeSamples();
    return 0;
}
