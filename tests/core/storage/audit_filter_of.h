#pragma once

#include <QString>

#include "core/storage/audit_store.h"

namespace tt::storage::test {

/// An audit-trail filter of the storage tests: one category (empty: all), a text, a UTC time range.
inline AuditFilter filterOf(const QString& category, const QString& text = {}, const QString& fromUtc = {},
                            const QString& toUtc = {}, int limit = 10000) {
    AuditFilter f;
    f.category = category;
    f.text = text;
    f.fromUtc = fromUtc;
    f.toUtc = toUtc;
    f.limit = limit;
    return f;
}

}  // namespace tt::storage::test
