#pragma once

#include <QString>
#include <QVariantMap>

#include "core/auth/permission.h"
#include "core/storage/audit_store.h"

namespace tt::ui {

struct AppContext;

/// The audit trail as a page uses it, e.g. the Controller page's Apply:
///
///     AuditTrail trail(context);
///     trail.require(core::auth::Permission::EditControllerTuning);  // throws PermissionDenied
///     ... apply ...
///     trail.record(storage::audit_category::kController, "controller", "ewma_lambda", "0.3", "0.4");
///
/// The record carries the logged-in user and role (without a session: the operator name of AppState).
class AuditTrail {
public:
    explicit AuditTrail(AppContext& context) : m_context(context) {}

    /// Throws core::auth::PermissionDenied ("… needs the engineer role") when the logged-in user's role
    /// lacks `permission`; does nothing without a session (tests of pages that log nobody in).
    void require(core::auth::Permission permission) const;
    /// Writes one change (who and when added). Throws std::runtime_error when the database cannot be
    /// opened, std::invalid_argument for an empty category, subject, field or user name.
    storage::AuditRecord record(const QString& category, const QString& subject, const QString& field,
                                const QString& before, const QString& after);

    /// One record per key whose value differs between `before` and `after` (a key missing on one side
    /// is recorded with an empty value there). A failure to write is logged as a warning, not thrown:
    /// the change itself is already made. Returns the records written.
    int recordValues(const QString& category, const QString& subject, const QVariantMap& before,
                     const QVariantMap& after);

private:
    AppContext& m_context;
};

}  // namespace tt::ui
