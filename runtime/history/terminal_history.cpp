#include "runtime/history/terminal_history.h"

#include <QSettings>
#include <QSysInfo>

#include "core/storage/data_stores.h"
#include "core/storage/history_store.h"

namespace tt::runtime {

bool isPlantDatabase(const QString& location) {
    const QString trimmed = location.trimmed();
    return trimmed.startsWith(QStringLiteral("postgresql://")) || trimmed.startsWith(QStringLiteral("postgres://"));
}

QString terminalMachineName() {
    const QString name = QSettings().value(QString::fromLatin1(kMachineNameSetting)).toString().trimmed();
    return name.isEmpty() ? QSysInfo::machineHostName() : name;
}

storage::JournalOptions journalOptionsFor(const TerminalHistoryOptions& options, const storage::DatabaseConfig& plant) {
    using Part = TerminalHistoryError::Part;
    if (options.machine.trimmed().isEmpty())
        throw TerminalHistoryError(Part::Journal,
                                   "the lathe's name is empty (a plant database tells its machines by name)");
    storage::JournalOptions journal;
    journal.machine = options.machine;
    journal.plant = plant.describe();
    journal.limitBytes = options.journalLimitBytes;
    try {
        journal.path =
            options.journalPath.isEmpty() ? storage::defaultJournalPath(options.machine, plant) : options.journalPath;
    } catch (const storage::StorageError& e) {
        throw TerminalHistoryError(Part::Journal, e.what());
    }
    return journal;
}

TerminalHistory::TerminalHistory(const TerminalHistoryOptions& options) : m_location(options.location) {
    using Part = TerminalHistoryError::Part;
    storage::DatabaseConfig config;
    try {
        config = storage::DataStores(options.location).config();
        if (config.kind == storage::DatabaseConfig::Kind::Sqlite) {
            m_database = std::make_unique<storage::Database>(config);
            m_store = std::make_unique<storage::SqlHistoryStore>(*m_database);
            return;
        }
    } catch (const std::exception& e) {
        throw TerminalHistoryError(Part::Database, e.what());
    }
    const storage::JournalOptions journal = journalOptionsFor(options, config);
    try {
        auto store = std::make_unique<storage::HistoryJournal>(journal);
        m_journal = store.get();
        m_store = std::move(store);
    } catch (const storage::StorageError& e) {
        throw TerminalHistoryError(Part::Journal, e.what());
    }
    storage::ForwarderOptions forward;
    forward.plant = config;
    forward.journalPath = journal.path;
    forward.machine = journal.machine;
    forward.journalLimitBytes = journal.limitBytes;
    forward.settings.batchParts = options.batchParts;
    m_forwarder = std::make_unique<storage::PlantForwarderThread>(forward);
    m_journal->setWrittenCallback([forwarder = m_forwarder.get()] { forwarder->wake(); });
}

TerminalHistory::~TerminalHistory() {
    if (m_journal) m_journal->setWrittenCallback({});
    m_forwarder.reset();
}

void TerminalHistory::startForwarding() {
    if (m_forwarder && !m_forwarder->isRunning() && !m_forwarder->isFinished()) m_forwarder->start();
}

bool TerminalHistory::drain(double waitS) {
    return !m_forwarder || m_forwarder->drainAndStop(waitS);
}

}  // namespace tt::runtime
