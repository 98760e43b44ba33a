#include "core/storage/plant_roles.h"

#include <QStringList>

namespace tt::storage {

namespace {

/// The history tables a terminal inserts into (each row belongs to one run, so to one machine).
const char* const kRunTables[] = {"run_points", "parts", "alarms", "run_ends"};
const char* const kPartTables[] = {"corrections", "measurements"};

/// Creates `role` (NOLOGIN) unless a role of that name exists (roles are shared by every database of the server).
void createGroupRole(Database& db, const char* role) {
    db.exec(QStringLiteral("DO $$ BEGIN IF NOT EXISTS (SELECT FROM pg_roles WHERE rolname = '%1') THEN "
                           "CREATE ROLE %1 NOLOGIN; END IF; END $$")
                .arg(QLatin1String(role)));
}

/// Row-level security on `table`: the terminals see and insert the rows `own` accepts, the quality engineers
/// read every row.
void protect(Database& db, const QString& table, const QString& own) {
    db.exec(QStringLiteral("ALTER TABLE %1 ENABLE ROW LEVEL SECURITY").arg(table));
    db.exec(QStringLiteral("CREATE POLICY terminal_own_rows ON %1 TO %2 USING (%3) WITH CHECK (%3)")
                .arg(table, QLatin1String(kTerminalRole), own));
    db.exec(QStringLiteral("CREATE POLICY quality_reads ON %1 FOR SELECT TO %2 USING (true)")
                .arg(table, QLatin1String(kQualityRole)));
}

}  // namespace

void createPlantRoles(Database& db) {
    createGroupRole(db, kTerminalRole);
    createGroupRole(db, kQualityRole);
    const QString terminal = QLatin1String(kTerminalRole);
    const QString quality = QLatin1String(kQualityRole);
    db.exec(QStringLiteral("CREATE TABLE plant_terminals (login TEXT NOT NULL, machine TEXT NOT NULL,"
                           " PRIMARY KEY (login, machine))"));
    // Reading: the quality engineers every history table; the terminals what they need to forward.
    QStringList history{QStringLiteral("runs"), QStringLiteral("plant_terminal_status")};
    for (const char* t : kRunTables)
        history << QLatin1String(t);
    for (const char* t : kPartTables)
        history << QLatin1String(t);
    db.exec(QStringLiteral("GRANT SELECT ON schema_versions, plant_terminals, %1 TO %2")
                .arg(history.join(QStringLiteral(", ")), quality));
    db.exec(QStringLiteral("GRANT SELECT ON schema_versions, plant_terminals TO %1").arg(terminal));
    // Writing: INSERT only (never UPDATE or DELETE history); the status row is the terminal's own to update.
    QStringList inserted{QStringLiteral("runs")};
    for (const char* t : kRunTables)
        inserted << QLatin1String(t);
    for (const char* t : kPartTables)
        inserted << QLatin1String(t);
    db.exec(QStringLiteral("GRANT SELECT, INSERT ON %1 TO %2").arg(inserted.join(QStringLiteral(", ")), terminal));
    db.exec(QStringLiteral("GRANT SELECT, INSERT, UPDATE ON plant_terminal_status TO %1").arg(terminal));
    db.exec(QStringLiteral("GRANT USAGE ON SEQUENCE runs_id_seq, parts_id_seq, alarms_id_seq TO %1").arg(terminal));

    // Which machines a login writes: its rows of plant_terminals. Runs of other machines are invisible to it
    // and cannot be inserted; every other row belongs to a run (or to a part of one) it can see.
    const QString myMachines =
        QStringLiteral("machine IN (SELECT t.machine FROM plant_terminals t WHERE t.login = current_user)");
    protect(db, QStringLiteral("runs"), myMachines);
    protect(db, QStringLiteral("plant_terminal_status"), myMachines);
    for (const char* t : kRunTables)
        protect(db, QLatin1String(t), QStringLiteral("EXISTS (SELECT 1 FROM runs r WHERE r.id = run_id)"));
    for (const char* t : kPartTables)
        protect(db, QLatin1String(t), QStringLiteral("EXISTS (SELECT 1 FROM parts p WHERE p.id = part_id)"));
}

}  // namespace tt::storage
