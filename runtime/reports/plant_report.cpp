#include "runtime/reports/plant_report.h"

#include <QJsonArray>
#include <QTimeZone>
#include <cmath>
#include <stdexcept>

#include "runtime/reports/point_report.h"

namespace tt::runtime {

namespace {

std::optional<QDateTime> utcTime(const std::string& iso) {
    const QDateTime t = QDateTime::fromString(QString::fromStdString(iso), Qt::ISODateWithMs);
    if (!t.isValid()) return std::nullopt;
    return t.toUTC();
}

/// The readings of `all` from `first` on, `count` of them (a window; its verdict counts are not used).
storage::PointReadings window(const storage::PointReadings& all, std::size_t first, std::size_t count) {
    storage::PointReadings w = all;
    const auto from = static_cast<std::ptrdiff_t>(first);
    const auto to = static_cast<std::ptrdiff_t>(first + count);
    w.valuesMm.assign(all.valuesMm.begin() + from, all.valuesMm.begin() + to);
    w.partNumbers.assign(all.partNumbers.begin() + from, all.partNumbers.begin() + to);
    w.timesS.assign(all.timesS.begin() + from, all.timesS.begin() + to);
    return w;
}

/// Cpk of the readings as `trueturn report` computes it (I-MR); none without tolerance or with too few readings.
std::optional<double> cpkOf(const storage::PointReadings& readings) {
    if (readings.valuesMm.empty() || !readings.lowerLimitMm || !readings.upperLimitMm) return std::nullopt;
    try {
        const PointReport report = pointReportOf(readings, reportSettings(1, ReportChart::Automatic, 0));
        if (!report.analysis.capability || !std::isfinite(report.analysis.capability->indices.cpk)) return std::nullopt;
        return report.analysis.capability->indices.cpk;
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
}

PlantPointCapability capabilityOf(const storage::PointReadings& recent, int windowParts) {
    PlantPointCapability c;
    c.pointIndex = recent.pointIndex;
    c.zMm = recent.zMm;
    const std::size_t n = recent.valuesMm.size();
    const auto w = static_cast<std::size_t>(windowParts);
    const std::size_t newest = std::min(n, w);
    c.count = static_cast<std::int64_t>(newest);
    c.cpk = cpkOf(window(recent, n - newest, newest));
    const std::size_t before = std::min(n - newest, w);
    c.countBefore = static_cast<std::int64_t>(before);
    if (before > 0) c.cpkBefore = cpkOf(window(recent, n - newest - before, before));
    return c;
}

MachineState stateOf(const storage::PlantMachineRow& row, const QDateTime& at, const std::optional<QDateTime>& lastPart,
                     const std::optional<QDateTime>& reported) {
    if (row.terminal && (!reported || reported->secsTo(at) > kOfflineAfterS)) return MachineState::Offline;
    if (row.newestRunOpen && lastPart && lastPart->secsTo(at) <= kRunningWithinS) return MachineState::Running;
    return MachineState::Idle;
}

QJsonValue timeJson(const std::optional<QDateTime>& t) {
    return t ? QJsonValue(t->toString(Qt::ISODateWithMs)) : QJsonValue();
}

QJsonValue numberJson(const std::optional<double>& v) {
    return v && std::isfinite(*v) ? QJsonValue(*v) : QJsonValue();
}

}  // namespace

std::string machineStateName(MachineState state) {
    switch (state) {
        case MachineState::Running:
            return "running";
        case MachineState::Offline:
            return "offline";
        case MachineState::Idle:
            break;
    }
    return "idle";
}

PlantOverview plantOverview(storage::Database& db, const QDateTime& at, int windowParts) {
    PlantOverview overview;
    overview.at = at.toUTC();
    overview.windowParts = windowParts;
    const QDate day = at.toLocalTime().date();
    overview.dayFrom = QDateTime(day, QTime(0, 0), QTimeZone::systemTimeZone()).toUTC();
    overview.dayTo = QDateTime(day.addDays(1), QTime(0, 0), QTimeZone::systemTimeZone()).toUTC();
    storage::PlantQuery query;
    query.dayFromUtc = overview.dayFrom.toString(Qt::ISODateWithMs).toStdString();
    query.dayToUtc = overview.dayTo.toString(Qt::ISODateWithMs).toStdString();
    query.windowParts = windowParts;
    for (const storage::PlantMachineRow& row : storage::queryPlant(db, query)) {
        PlantMachine m;
        m.machine = row.machine;
        m.lastPartAt = row.lastPartAt ? utcTime(*row.lastPartAt) : std::nullopt;
        if (row.terminal) {
            m.reportedAt = utcTime(row.terminal->reportedAt);
            m.backlogParts = row.terminal->backlogParts;
            m.journalNearFull = row.terminal->journalLimitBytes > 0 &&
                                row.terminal->journalBytes >= 0.9 * static_cast<double>(row.terminal->journalLimitBytes);
        }
        m.state = stateOf(row, overview.at, m.lastPartAt, m.reportedAt);
        m.runId = row.newestRunId;
        m.today = row.dayParts;
        m.todayParts = row.dayPartCount;
        for (const storage::PointReadings& p : row.recent)
            m.points.push_back(capabilityOf(p, windowParts));
        m.openAlarmCount = row.openAlarmCount;
        m.openAlarms = row.openAlarms;
        overview.machines.push_back(std::move(m));
    }
    return overview;
}

QJsonObject plantOverviewJson(const PlantOverview& overview) {
    QJsonArray machines;
    for (const PlantMachine& m : overview.machines) {
        QJsonArray points;
        for (const PlantPointCapability& p : m.points)
            points.append(QJsonObject{{QStringLiteral("point"), p.pointIndex + 1},
                                      {QStringLiteral("x_mm"), p.zMm},
                                      {QStringLiteral("n"), static_cast<qint64>(p.count)},
                                      {QStringLiteral("cpk"), numberJson(p.cpk)},
                                      {QStringLiteral("n_before"), static_cast<qint64>(p.countBefore)},
                                      {QStringLiteral("cpk_before"), numberJson(p.cpkBefore)},
                                      {QStringLiteral("cpk_change"), numberJson(p.change())}});
        QJsonArray alarms;
        for (const storage::PlantAlarm& a : m.openAlarms)
            alarms.append(QJsonObject{
                {QStringLiteral("part"), a.partNumber ? QJsonValue(static_cast<qint64>(*a.partNumber)) : QJsonValue()},
                {QStringLiteral("kind"), QString::fromStdString(a.kind)},
                {QStringLiteral("message"), QString::fromStdString(a.message)},
                {QStringLiteral("at"), QString::fromStdString(a.recordedAt)}});
        machines.append(QJsonObject{
            {QStringLiteral("machine"), QString::fromStdString(m.machine)},
            {QStringLiteral("state"), QString::fromStdString(machineStateName(m.state))},
            {QStringLiteral("last_part_at"), timeJson(m.lastPartAt)},
            {QStringLiteral("run"), m.runId ? QJsonValue(static_cast<qint64>(*m.runId)) : QJsonValue()},
            {QStringLiteral("terminal_reported_at"), timeJson(m.reportedAt)},
            {QStringLiteral("backlog_parts"),
             m.backlogParts ? QJsonValue(static_cast<qint64>(*m.backlogParts)) : QJsonValue()},
            {QStringLiteral("journal_near_full"), m.journalNearFull},
            {QStringLiteral("today"), QJsonObject{{QStringLiteral("parts"), static_cast<qint64>(m.todayParts)},
                                                  {QStringLiteral("good"), static_cast<qint64>(m.today.good)},
                                                  {QStringLiteral("rework"), static_cast<qint64>(m.today.rework)},
                                                  {QStringLiteral("scrap"), static_cast<qint64>(m.today.scrap)}}},
            {QStringLiteral("points"), points},
            {QStringLiteral("open_alarms"), static_cast<qint64>(m.openAlarmCount)},
            {QStringLiteral("alarms"), alarms}});
    }
    return {{QStringLiteral("at"), overview.at.toString(Qt::ISODateWithMs)},
            {QStringLiteral("day_from"), overview.dayFrom.toString(Qt::ISODateWithMs)},
            {QStringLiteral("day_to"), overview.dayTo.toString(Qt::ISODateWithMs)},
            {QStringLiteral("window_parts"), overview.windowParts},
            {QStringLiteral("machines"), machines}};
}

}  // namespace tt::runtime
