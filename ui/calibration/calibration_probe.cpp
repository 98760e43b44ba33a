#include "ui/calibration/calibration_probe.h"

#include "core/common/crc16.h"
#include "core/common/crc32c.h"

namespace tt::ui {

QString ProbeTableReadback::crcText() const {
    return crc32c ? QStringLiteral("CRC-32C %1").arg(QString::fromStdString(core::crcText(*crc32c)))
                  : QStringLiteral("CRC-16 %1").arg(QString::fromStdString(core::crcText(crc16, 16)));
}

bool ProbeTableReadback::matches(int tableVersion, std::span<const std::uint8_t> image) const {
    if (!valid || version != tableVersion || sizeBytes != image.size()) return false;
    return crc32c ? *crc32c == core::crc32c(image) : crc16 == core::crc16Ccitt(image);
}

}  // namespace tt::ui
