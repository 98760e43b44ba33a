#include "devices/api/probe_status.h"

#include <QCoreApplication>

namespace tt::devices {

namespace {

probe::SessionConfig sessionConfig(const QVariantMap& settings) {
    probe::SessionConfig c;
    c.rateHz = settings.value(QStringLiteral("rateHz"), c.rateHz).toInt();
    c.silenceTimeoutS =
        settings.value(QStringLiteral("silenceTimeoutMs"), c.silenceTimeoutS * 1000.0).toDouble() / 1000.0;
    c.replyTimeoutS = settings.value(QStringLiteral("replyTimeoutMs"), c.replyTimeoutS * 1000.0).toDouble() / 1000.0;
    return c;
}

TableUploadStatus toUploadStatus(const probe::ProbeSession::UploadState& state) {
    TableUploadStatus s;
    s.progress = state.progress;
    s.message = QString::fromStdString(state.message);
    if (!state.phase) return s;
    if (state.active)
        s.phase = TableUploadStatus::Phase::Running;
    else if (*state.phase == probe::TableUploader::Phase::Done)
        s.phase = TableUploadStatus::Phase::Done;
    else
        s.phase = TableUploadStatus::Phase::Failed;
    return s;
}

std::optional<MandrelTableInfo> toTableInfo(const std::optional<probe::TableInfoPayload>& info) {
    if (!info) return std::nullopt;
    return MandrelTableInfo{info->version, info->crc, info->sizeBytes, info->valid, info->crc32c};
}

std::optional<MandrelInfo> toMandrelInfo(const probe::ProbeSession& session) {
    const auto& mandrel = session.mandrel();
    if (!mandrel) return std::nullopt;
    MandrelInfo info;
    info.protocol = mandrel->protocol;
    info.maxTableBytes = static_cast<std::uint32_t>(mandrel->maxTableBytes);
    if (const auto& device = session.deviceInfo()) info.adcBits = device->adcBits;
    return info;
}

QList<DeviceStatistic> probeStatistics(const probe::ProbeSession& session, std::uint64_t queueOverflow) {
    const probe::FrameStats& f = session.frameStats();
    QList<DeviceStatistic> list{
        {QCoreApplication::translate("ProbeStatus", "Samples used"), QString::number(session.samplesUsed())},
        {QCoreApplication::translate("ProbeStatus", "Frames lost"), QString::number(f.lost)},
        {QCoreApplication::translate("ProbeStatus", "Frames duplicated"), QString::number(f.duplicate)},
        {QCoreApplication::translate("ProbeStatus", "Frames corrupt"), QString::number(f.corrupt + f.malformed)},
        {QCoreApplication::translate("ProbeStatus", "Samples dropped (over-range, excitation)"),
         QString::number(session.samplesDropped())},
        {QCoreApplication::translate("ProbeStatus", "Commands resent"), QString::number(session.resends())},
    };
    if (queueOverflow > 0)
        list.append(
            {QCoreApplication::translate("ProbeStatus", "Samples not taken in time"), QString::number(queueOverflow)});
    if (const auto& mandrel = session.mandrel())
        list.append({QCoreApplication::translate("ProbeStatus", "Protocol"),
                     mandrel->protocol >= 2
                         ? QCoreApplication::translate("ProbeStatus", "%1 (tables up to %2 KiB, CRC-32C)")
                               .arg(mandrel->protocol)
                               .arg(mandrel->maxTableBytes / 1024)
                         : QCoreApplication::translate("ProbeStatus", "1 (tables up to 64 KiB, CRC-16)")});
    if (const auto& info = session.tableInfo())
        list.append(
            {QCoreApplication::translate("ProbeStatus", "Linearisation table"),
             info->valid
                 ? QCoreApplication::translate("ProbeStatus", "version %1, %2, %3 bytes")
                       .arg(info->version)
                       .arg(
                           info->crc32c
                               ? QStringLiteral("CRC-32C 0x%1")
                                     .arg(QString::number(*info->crc32c, 16)
                                              .toUpper()
                                              .rightJustified(8, QLatin1Char('0')))
                               : QStringLiteral("CRC 0x%1")
                                     .arg(QString::number(info->crc, 16).toUpper().rightJustified(4, QLatin1Char('0'))))
                       .arg(info->sizeBytes)
                 : QCoreApplication::translate("ProbeStatus", "none (raw ADC codes only)")});
    return list;
}

}  // namespace

ProbeSessionPorts::ProbeSessionPorts(const QVariantMap& settings) : m_session(sessionConfig(settings)) {}

std::optional<core::ProbeSample> ProbeSessionPorts::takeSample() {
    if (m_samples.empty()) return std::nullopt;
    const core::ProbeSample s = m_samples.front();
    m_samples.pop_front();
    return s;
}

void ProbeSessionPorts::uploadTable(std::vector<std::uint8_t> image, std::uint16_t version, std::uint32_t crc32c) {
    m_session.uploadTable(std::move(image), version, crc32c);
}

TableUploadStatus ProbeSessionPorts::uploadStatus() const {
    return toUploadStatus(m_session.uploadState());
}

std::optional<MandrelTableInfo> ProbeSessionPorts::tableInfo() const {
    return toTableInfo(m_session.tableInfo());
}

std::optional<MandrelInfo> ProbeSessionPorts::mandrelInfo() const {
    return toMandrelInfo(m_session);
}

void ProbeSessionPorts::queueSessionSamples() {
    for (const core::ProbeSample& s : m_session.takeSamples()) {
        if (m_samples.size() == kMaxQueued) {
            m_samples.pop_front();
            ++m_overflow;
        }
        m_samples.push_back(s);
    }
}

QString ProbeSessionPorts::lastSampleText() const {
    const auto& last = m_session.lastSample();
    if (!last) return {};
    return QCoreApplication::translate("ProbeStatus", "%1 / %2 mm")
        .arg(last->deflectionNm[0] * 1e-6, 0, 'f', 4)
        .arg(last->deflectionNm[1] * 1e-6, 0, 'f', 4);
}

QList<DeviceStatistic> ProbeSessionPorts::sessionStatistics() const {
    return probeStatistics(m_session, m_overflow);
}

}  // namespace tt::devices
