#include "ui/auth/audit_trail.h"

#include <QSet>
#include <stdexcept>

#include "ui/app_context.h"
#include "ui/app_state.h"
#include "ui/log_categories.h"

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

int AuditTrail::recordValues(const QString& category, const QString& subject, const QVariantMap& before,
                             const QVariantMap& after) {
    QStringList keys = before.keys() + after.keys();
    keys.removeDuplicates();
    keys.sort();
    int written = 0;
    for (const QString& key : keys) {
        const QString old = before.value(key).toString();
        const QString now = after.value(key).toString();
        if (old == now && before.contains(key) == after.contains(key)) continue;
        try {
            record(category, subject, key, old, now);
            ++written;
        } catch (const std::exception& e) {
            qCWarning(lcUi).noquote() << "not in the audit trail:" << subject << key << "-" << e.what();
        }
    }
    return written;
}

}  // namespace tt::ui
