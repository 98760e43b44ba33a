#pragma once

#include <QString>
#include <cstdint>
#include <memory>
#include <stdexcept>

#include "core/ports/history_store.h"
#include "core/storage/database.h"
#include "core/storage/history_journal.h"
#include "core/storage/plant_forwarder_thread.h"

namespace tt::runtime {

/// The QSettings key of this terminal's lathe name in a plant database (default: the computer's host name).
inline constexpr const char* kMachineNameSetting = "history/machine";

/// Whether a history location is a plant database (postgresql:// or postgres://) rather than an SQLite file.
bool isPlantDatabase(const QString& location);

/// The lathe this terminal writes as (kMachineNameSetting, else the host name).
QString terminalMachineName();

/// Where a terminal's runs go and how.
struct TerminalHistoryOptions {
    QString location;     ///< an SQLite file (the history itself) or a postgresql:// plant database
    QString machine;      ///< the lathe's name in the plant database (not empty with a plant database)
    QString journalPath;  ///< the journal; empty: storage::defaultJournalPath(machine, plant)
    std::int64_t journalLimitBytes = storage::kDefaultJournalLimitBytes;
    int batchParts = storage::kDefaultForwardBatchParts;  ///< parts per batch sent to the plant database
};

/// A terminal's history could not be opened; `part` says which: the database named by the location, or
/// the terminal's journal of a plant database.
class TerminalHistoryError : public std::runtime_error {
public:
    enum class Part { Database, Journal };
    TerminalHistoryError(Part part, const std::string& what) : std::runtime_error(what), m_part(part) {}
    Part part() const { return m_part; }

private:
    Part m_part;
};

/// The journal a terminal keeps for the plant database `location` (a postgresql:// URL): its file (the
/// given one, else the default next to the application's data), machine, plant and bound. Throws
/// TerminalHistoryError (Journal) when the folder cannot be made or the machine's name is empty.
storage::JournalOptions journalOptionsFor(const TerminalHistoryOptions& options, const storage::DatabaseConfig& plant);

/// The history a terminal's runs write, the CLI's and the GUI's alike. An SQLite location is the history
/// itself (a single lathe); a plant database (postgresql://) is written through the terminal's journal
/// (storage::HistoryJournal, every part stored locally first) and a forwarder thread that sends it on, so a
/// run neither stops nor waits while the plant database is down. Use from one thread (QtSql); the
/// forwarder runs in its own.
class TerminalHistory {
public:
    /// Opens the history; with a plant database, the journal (the forwarder starts with startForwarding()).
    /// Throws TerminalHistoryError.
    explicit TerminalHistory(const TerminalHistoryOptions& options);
    ~TerminalHistory();
    TerminalHistory(const TerminalHistory&) = delete;
    TerminalHistory& operator=(const TerminalHistory&) = delete;

    /// The store the loop writes (the journal with a plant database).
    core::HistoryStore& store() { return *m_store; }
    /// The location it was opened with.
    const QString& location() const { return m_location; }
    /// The forwarder with a plant database, else null. Connect to its statusChanged before startForwarding().
    storage::PlantForwarderThread* forwarder() const { return m_forwarder.get(); }
    /// The journal with a plant database, else null.
    storage::HistoryJournal* journal() const { return m_journal; }
    /// Starts sending the journal (no effect without a plant database or when started).
    void startForwarding();
    /// Waits at most `waitS` for the forwarder to send everything, then stops it; true when all is sent (and
    /// always without a plant database). What is left stays in the journal for the next run.
    bool drain(double waitS);

private:
    QString m_location;
    std::unique_ptr<storage::Database> m_database;
    std::unique_ptr<core::HistoryStore> m_store;
    storage::HistoryJournal* m_journal = nullptr;
    std::unique_ptr<storage::PlantForwarderThread> m_forwarder;
};

}  // namespace tt::runtime
