#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tt::core {

/// What a probe mandrel reports about the table it holds: version, CRC-16 of the stored image,
/// its CRC-32C when the mandrel speaks probe protocol 2, size and whether it accepted the image.
struct TableReadback {
    std::uint16_t version = 0;
    std::uint16_t crc16 = 0;
    std::optional<std::uint32_t> crc32c;
    std::uint32_t sizeBytes = 0;
    bool valid = false;

    /// The CRC the upload is verified with: the CRC-32C, or the CRC-16 of a protocol-1 mandrel.
    std::uint32_t crc() const { return crc32c ? *crc32c : crc16; }
    /// True when the mandrel holds `image` as table `version`, valid, with the same size and CRC.
    bool matches(int version, std::span<const std::uint8_t> image) const;
};

/// How an upload the mandrel's link is carrying stands.
struct UploadLinkStatus {
    enum class Phase { Idle, Running, Done, Failed };
    Phase phase = Phase::Idle;
    double progress = 0.0;  ///< 0..1
    std::string message;    ///< the device's own words (why it failed), shown as they are
};

/// The probe mandrel as the upload needs it: a port implemented over the device plugin API
/// (TableUploadTarget) in the UI, and by test mandrels in the engine's tests.
class TableUploadPort {
public:
    virtual ~TableUploadPort() = default;
    /// Starts sending (returns at once). Throws std::invalid_argument with the device's reason
    /// when it refuses (image too large, busy, CRC wrong, not answering).
    virtual void startUpload(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) = 0;
    virtual UploadLinkStatus uploadStatus() const = 0;
    /// Asks the mandrel again which table it holds; the answer arrives in readback().
    virtual void requestReadback() = 0;
    /// What the mandrel last reported; nullopt before it answered.
    virtual std::optional<TableReadback> readback() const = 0;
};

/// Upload with read-back (issue 6, item 5; probe protocol 2): send the image, wait for the
/// mandrel to store it, ask which table it holds and compare version, size and CRC with the image
/// sent. When the link reports a failure the mandrel is still asked, so the outcome says what it
/// holds (a failure after the image was stored, in its read-back check, shows the CRC it reports).
/// A state machine driven by pump(); its outcome is a kind with data, worded by the UI.
class TableUploadProcedure {
public:
    enum class Phase { Idle, Sending, ReadingBack, Verified, Mismatch, Failed };
    /// Why an upload did not end verified.
    enum class Problem { None, Refused, LinkFailed, NoReadback, ReadbackDiffers, Aborted };

    /// `readbackTimeoutS`: how long to wait for a matching read-back after the last chunk, s (0.1 .. 60).
    explicit TableUploadProcedure(double readbackTimeoutS = 3.0);

    /// Sends `image` as table `version` through `port` (Idle, Verified, Mismatch or Failed →
    /// Sending; Refused → Failed with the device's message). Throws std::logic_error while an
    /// upload runs and std::invalid_argument for an empty image.
    void start(TableUploadPort& port, std::vector<std::uint8_t> image, std::uint16_t version);
    /// Follows the upload: progress while sending, the read-back once stored, the timeout while
    /// waiting (`elapsedS` of wall time since the last call).
    void pump(TableUploadPort& port, double elapsedS);
    /// The operator stops waiting (the mandrel may still store the image): → Failed (Aborted).
    void abort();

    Phase phase() const { return m_phase; }
    Problem problem() const { return m_problem; }
    bool running() const { return m_phase == Phase::Sending || m_phase == Phase::ReadingBack; }
    double progress() const { return m_progress; }
    /// The device's message (progress or failure), as it gave it.
    const std::string& deviceMessage() const { return m_deviceMessage; }
    /// What the mandrel reported last during this upload.
    const std::optional<TableReadback>& readback() const { return m_readback; }
    std::uint16_t version() const { return m_version; }
    /// The CRC-32C of the image sent (the record's upload CRC).
    std::uint32_t imageCrc32c() const { return m_crc32c; }
    const std::vector<std::uint8_t>& image() const { return m_image; }

private:
    void readBack(TableUploadPort& port, double elapsedS);

    double m_timeoutS;
    Phase m_phase = Phase::Idle;
    Problem m_problem = Problem::None;
    std::vector<std::uint8_t> m_image;
    std::uint16_t m_version = 0;
    std::uint32_t m_crc32c = 0;
    double m_progress = 0.0;
    double m_waitedS = 0.0;
    std::string m_deviceMessage;
    bool m_linkFailed = false;  ///< the link reported a failure; reading back what the mandrel holds
    std::optional<TableReadback> m_readback;
};

}  // namespace tt::core
