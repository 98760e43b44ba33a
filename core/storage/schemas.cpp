#include "core/storage/schemas.h"

#include "core/storage/audit_store.h"
#include "core/storage/calibration_store.h"
#include "core/storage/history_store.h"
#include "core/storage/tool_store.h"
#include "core/storage/user_store.h"

namespace tt::storage {

std::vector<SchemaModule> allSchemas() {
    return {historySchema(), adaptationSchema(), toolSchema(), calibrationSchema(), auditSchema(), userSchema()};
}

void migrateAll(Database& database) {
    for (const SchemaModule& module : allSchemas())
        database.migrate(module);
}

}  // namespace tt::storage
