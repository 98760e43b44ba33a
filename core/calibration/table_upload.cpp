#include "core/calibration/table_upload.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/common/crc16.h"
#include "core/common/crc32c.h"

namespace tt::core {

bool TableReadback::matches(int tableVersion, std::span<const std::uint8_t> image) const {
    if (!valid || version != tableVersion || sizeBytes != image.size()) return false;
    return crc32c ? *crc32c == core::crc32c(image) : crc16 == crc16Ccitt(image);
}

TableUploadProcedure::TableUploadProcedure(double readbackTimeoutS) : m_timeoutS(readbackTimeoutS) {
    if (!std::isfinite(readbackTimeoutS) || readbackTimeoutS < 0.1 || readbackTimeoutS > 60.0)
        throw std::invalid_argument("the read-back timeout must be within 0.1 .. 60 s");
}

void TableUploadProcedure::start(TableUploadPort& port, std::vector<std::uint8_t> image, std::uint16_t version) {
    if (running()) throw std::logic_error("an upload is already running");
    if (image.empty()) throw std::invalid_argument("the table image is empty");
    m_image = std::move(image);
    m_version = version;
    m_crc32c = crc32c(m_image);
    m_progress = 0.0;
    m_waitedS = 0.0;
    m_readback.reset();
    m_deviceMessage.clear();
    m_linkFailed = false;
    m_problem = Problem::None;
    try {
        port.startUpload(m_image, version, m_crc32c);
    } catch (const std::invalid_argument& e) {
        m_phase = Phase::Failed;
        m_problem = Problem::Refused;
        m_deviceMessage = e.what();
        return;
    }
    m_phase = Phase::Sending;
}

void TableUploadProcedure::pump(TableUploadPort& port, double elapsedS) {
    if (m_phase == Phase::Sending) {
        const UploadLinkStatus s = port.uploadStatus();
        m_progress = std::isfinite(s.progress) ? std::clamp(s.progress, 0.0, 1.0) : m_progress;
        m_deviceMessage = s.message;
        m_linkFailed = s.phase == UploadLinkStatus::Phase::Failed;
        if (s.phase != UploadLinkStatus::Phase::Done && !m_linkFailed) return;
        if (!m_linkFailed) m_progress = 1.0;
        m_phase = Phase::ReadingBack;
        m_waitedS = 0.0;
        port.requestReadback();
    }
    if (m_phase == Phase::ReadingBack) readBack(port, elapsedS);
}

void TableUploadProcedure::readBack(TableUploadPort& port, double elapsedS) {
    if (const std::optional<TableReadback> r = port.readback()) m_readback = r;
    if (m_readback && m_readback->matches(m_version, m_image)) {
        m_phase = Phase::Verified;
        m_problem = Problem::None;
        return;
    }
    // An answer that differs may be the table held before the upload: ask again until the timeout.
    if (std::isfinite(elapsedS) && elapsedS > 0.0) m_waitedS += elapsedS;
    if (m_waitedS < m_timeoutS) {
        port.requestReadback();
        return;
    }
    if (m_linkFailed) {
        m_phase = Phase::Failed;
        m_problem = Problem::LinkFailed;
        return;
    }
    m_phase = Phase::Mismatch;
    m_problem = m_readback ? Problem::ReadbackDiffers : Problem::NoReadback;
}

void TableUploadProcedure::abort() {
    if (!running()) return;
    m_phase = Phase::Failed;
    m_problem = Problem::Aborted;
}

}  // namespace tt::core
