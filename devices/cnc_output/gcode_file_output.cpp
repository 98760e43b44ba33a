#include "devices/cnc_output/gcode_file_output.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

namespace tt::devices {

GCodeFileOutput::GCodeFileOutput(const QVariantMap& settings, const DeviceContext& context)
    : DeviceBase(DeviceKind::CorrectionOutput, context),
      m_folder(settings.value(QStringLiteral("folder")).toString()),
      m_fileName(settings.value(QStringLiteral("fileName")).toString()) {
    m_job.nominalDiameterMm = settings.value(QStringLiteral("nominalDiameterMm")).toDouble();
    m_job.feedMmPerRev = settings.value(QStringLiteral("feedMmPerRev")).toDouble();
    m_job.spindleRpm = settings.value(QStringLiteral("spindleRpm")).toInt();
    m_job.diameterMode = settings.value(QStringLiteral("xMode")).toString() != QLatin1String("radius");
    m_job.emitModeCode = settings.value(QStringLiteral("emitModeCode")).toBool();
    m_job.zOriginMm = settings.value(QStringLiteral("zOriginMm")).toDouble();
    m_job.zDirection = settings.value(QStringLiteral("zDirection")).toString() == QLatin1String("+1") ? 1 : -1;
    m_job.clearanceMm = settings.value(QStringLiteral("clearanceMm")).toDouble();
    m_job.toolNumber = settings.value(QStringLiteral("toolNumber")).toInt();
    m_job.programNumber = settings.value(QStringLiteral("programNumber")).toInt();
    m_job.maxCorrectionMm = settings.value(QStringLiteral("maxCorrectionMm")).toDouble();
}

void GCodeFileOutput::open() {
    const QFileInfo folder(m_folder);
    if (!folder.isDir()) {
        setState(core::DeviceState::Error,
                 QCoreApplication::translate("GCodeOutput", "the folder %1 does not exist").arg(m_folder));
        return;
    }
    if (!folder.isWritable()) {
        setState(core::DeviceState::Error,
                 QCoreApplication::translate("GCodeOutput", "the folder %1 is not writable").arg(m_folder));
        return;
    }
    setState(core::DeviceState::Ready,
             QCoreApplication::translate("GCodeOutput", "G-code files go to %1").arg(m_folder));
}

void GCodeFileOutput::close() {
    setState(core::DeviceState::Disconnected);
}

core::OutputResult GCodeFileOutput::refuse(const QString& message) {
    ++m_refused;
    reportError(message);
    return {false, message.toStdString()};
}

core::OutputResult GCodeFileOutput::sendPartCorrection(const core::PartCorrection& correction) {
    if (state() != core::DeviceState::Ready) open();
    if (state() != core::DeviceState::Ready) return refuse(QString::fromStdString(health().message));
    std::string program;
    try {
        program = writeCorrectionGCode(correction, m_job);
    } catch (const std::invalid_argument& e) {
        return refuse(QCoreApplication::translate("GCodeOutput", "part %1: %2")
                          .arg(correction.partNumber)
                          .arg(QString::fromStdString(e.what())));
    }
    QString name = m_fileName;
    name.replace(QStringLiteral("{part}"), QString::number(correction.partNumber));
    const QString path = QDir(m_folder).filePath(name);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text) ||
        file.write(program.data(), static_cast<qint64>(program.size())) != static_cast<qint64>(program.size()) ||
        !file.commit()) {
        const QString message =
            QCoreApplication::translate("GCodeOutput", "cannot write %1: %2").arg(path, file.errorString());
        setState(core::DeviceState::Error, message);
        return refuse(message);
    }
    ++m_written;
    m_lastFile = path;
    setLiveValue(QCoreApplication::translate("GCodeOutput", "part %1: %2")
                     .arg(correction.partNumber)
                     .arg(QFileInfo(path).fileName()));
    return {true, {}};
}

core::OutputResult GCodeFileOutput::sendDynamicOffset(double) {
    return refuse(QCoreApplication::translate(
        "GCodeOutput", "a G-code file cannot apply a dynamic X offset; use a Modbus correction output"));
}

QList<DeviceStatistic> GCodeFileOutput::statistics() const {
    return {{QCoreApplication::translate("GCodeOutput", "Files written"), QString::number(m_written)},
            {QCoreApplication::translate("GCodeOutput", "Refused"), QString::number(m_refused)},
            {QCoreApplication::translate("GCodeOutput", "Last file"),
             m_lastFile.isEmpty() ? QCoreApplication::translate("GCodeOutput", "none") : m_lastFile}};
}

}  // namespace tt::devices
