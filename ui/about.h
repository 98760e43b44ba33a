#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>

namespace tt::ui {

/// The About box's account of the product: what TrueTurn implements today and what is not
/// implemented yet. The two lists in ui/about.cpp are the one place to update when a feature
/// lands (README.md's "Not yet" paragraph says the same in prose).
class About {
    Q_DECLARE_TR_FUNCTIONS(tt::ui::About)

public:
    /// What the product does today, one item per feature, in the current language.
    static QStringList implemented();
    /// What is planned but not implemented yet, in the current language.
    static QStringList notYet();
    /// The About box's text (rich text): version, the two lists, the Qt version and the log file
    /// (`logFilePath`, empty: "not written").
    static QString text(const QString& logFilePath);
};

}  // namespace tt::ui
