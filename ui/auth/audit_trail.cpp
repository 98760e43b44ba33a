#include "ui/auth/audit_trail.h"

#include <stdexcept>

#include "ui/app_context.h"
#include "ui/app_state.h"

namespace tt::ui {

void AuditTrail::require(core::auth::Permission permission) const {
    if (m_context.access) m_context.access->require(permission);
}

storage::AuditRecord AuditTrail::record(const QString& category, const QString& subject, const QString& field,
                                        const QString& before, const QString& after) {
    storage::AuditStore* audit = m_context.data().audit();
    if (!audit)
        throw std::runtime_error("the audit trail cannot be written: " + m_context.data().problem().toStdString());
    const QString who = m_context.state ? m_context.state->operatorName() : QString();
    return audit->record({category, subject, field, before, after}, who, QString());
}

}  // namespace tt::ui
