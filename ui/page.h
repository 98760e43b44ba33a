#pragma once

#include <QIcon>
#include <QString>
#include <QWidget>

#include "ui/app_context.h"

namespace tt::ui {

/// The pages of the main window, in navigation order.
enum class PageId { Run, Measurements, Tools, Calibration, Process, Controller, Reports, Plant, Devices, Settings };

/// All page ids in navigation order.
inline constexpr PageId kAllPages[] = {PageId::Run,        PageId::Measurements, PageId::Tools,   PageId::Calibration,
                                       PageId::Process,    PageId::Controller,   PageId::Reports, PageId::Plant,
                                       PageId::Devices,    PageId::Settings};

/// Stable, untranslated key of a page ("run", "tools"), used by --page and screenshot names.
QString pageKey(PageId id);

/// One page of the main window. Subclasses build their widgets in the constructor and set every
/// user-visible text in retranslate(), which also runs when the language changes.
class Page : public QWidget {
    Q_OBJECT
public:
    Page(PageId id, AppContext& context, QWidget* parent = nullptr);

    PageId id() const { return m_id; }
    /// Translated title shown in the navigation and the header.
    virtual QString title() const = 0;
    /// Icon of the navigation button.
    QIcon icon() const;

    /// Sets all user-visible texts (called once after construction and on language change).
    virtual void retranslate() = 0;

    /// What the user edited on this page and did not apply yet, in the user's words ("3 changed tools");
    /// empty when nothing is pending. The window asks before quitting with pending edits.
    virtual QString unappliedEdits() const { return {}; }

signals:
    /// Asks the window to show the Reports page with the reports of `machine` (the Plant page's click).
    void reportsRequested(const QString& machine);

protected:
    void changeEvent(QEvent* event) override;
    AppContext& context() { return m_context; }
    const AppContext& context() const { return m_context; }

private:
    PageId m_id;
    AppContext& m_context;
};

}  // namespace tt::ui
