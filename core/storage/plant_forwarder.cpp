#include "core/storage/plant_forwarder.h"

#include "core/storage/history_store.h"
#include "core/storage/journal_batch.h"
#include "core/storage/storage_log.h"

namespace tt::storage {

QString ForwarderStatus::describe() const {
    const QString kept =
        QStringLiteral("%1 part%2 kept on this terminal").arg(backlogParts).arg(backlogParts == 1 ? "" : "s");
    QString line;
    switch (link) {
        case Link::Offline:
            line = QStringLiteral("plant database offline since %1, %2 (%3; next attempt in %4 s)")
                       .arg(offlineSince.toString(QStringLiteral("HH:mm")), kept, reason)
                       .arg(retryInS, 0, 'f', 1);
            break;
        case Link::Starting:
            line = QStringLiteral("plant database: connecting, %1").arg(kept);
            break;
        case Link::Online:
            line = drained ? QStringLiteral("plant database: every part sent (drained)")
                           : QStringLiteral("plant database: sending, %1").arg(kept);
            break;
    }
    if (full())
        line += QStringLiteral("; the journal is full (%1 of %2 MiB): the loop takes no new part")
                    .arg(journalBytes / (1024 * 1024))
                    .arg(journalLimitBytes / (1024 * 1024));
    else if (nearFull())
        line += QStringLiteral("; the journal is nearly full (%1 of %2 MiB)")
                    .arg(journalBytes / (1024 * 1024))
                    .arg(journalLimitBytes / (1024 * 1024));
    return line;
}

PlantForwarder::PlantForwarder(const QString& journalPath, const DatabaseConfig& plant, const QString& machine,
                               std::int64_t journalLimitBytes, const ForwarderSettings& settings)
    : m_plantConfig(plant), m_machine(machine), m_limitBytes(journalLimitBytes), m_settings(settings) {
    if (settings.batchParts < 1 || settings.batchParts > 10000)
        throw StorageError("the forwarder's batch of " + std::to_string(settings.batchParts) +
                           " parts is outside 1 .. 10000");
    DatabaseConfig journal = DatabaseConfig::sqlite(journalPath);
    journal.durable = true;
    m_journal = std::make_unique<Database>(journal);
    m_journal->migrate(historySchema());
    m_journal->migrate(journalSchema());
}

PlantForwarder::~PlantForwarder() = default;

Database& PlantForwarder::plant() {
    if (!m_plant) {
        auto plant = std::make_unique<Database>(m_plantConfig);
        // A batch that waits on the server (a lock, a recovering server) fails after a bound and is sent again
        // instead of holding the forwarder (and the terminal's shutdown) for ever.
        if (plant->isPostgres())
            plant->exec(QStringLiteral("SET statement_timeout = %1").arg(kForwardStatementTimeoutMs));
        // The owner of the plant database brings its schema up to date; a terminal's role finds it current.
        plant->migrate(historySchema());
        m_plant = std::move(plant);
        qCInfo(lcStorage).noquote() << "forwarding the journal of" << m_machine << "to" << m_plantConfig.describe();
    }
    return *m_plant;
}

void PlantForwarder::disconnect() {
    m_plant.reset();
}

TerminalReport PlantForwarder::terminalReport(std::int64_t backlog) {
    return {m_machine, backlog, journalUsedBytes(*m_journal), m_limitBytes};
}

std::optional<std::int64_t> PlantForwarder::sendBatch() {
    const JournalBatch batch = readJournalBatch(*m_journal, journalSentSeq(*m_journal), m_settings.batchParts);
    if (batch.empty()) return std::nullopt;
    const auto parts = static_cast<std::int64_t>(batch.parts.size());
    const std::int64_t backlogAfter = std::max<std::int64_t>(0, journalBacklogParts(*m_journal) - parts);
    writePlantBatch(plant(), batch, terminalReport(backlogAfter));
    // Committed by the server: recorded here. Killed between the two, the batch is sent again and inserts nothing.
    markJournalSent(*m_journal, batch.lastSeq);
    const auto keep = static_cast<std::int64_t>(kJournalTrimShare * static_cast<double>(m_limitBytes));
    trimJournal(*m_journal, keep);
    return parts;
}

void PlantForwarder::report() {
    writeTerminalReport(plant(), terminalReport(journalBacklogParts(*m_journal)));
}

std::int64_t PlantForwarder::backlogParts() {
    return journalBacklogParts(*m_journal);
}

JournalUsage PlantForwarder::usage() {
    return {journalUsedBytes(*m_journal), m_limitBytes};
}

}  // namespace tt::storage
