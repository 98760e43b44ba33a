#include "ui/about.h"

#include <trueturn/version.h>
#include <QtGlobal>
#include <iterator>

namespace tt::ui {

namespace {

// What TrueTurn does today (the About box's "Implemented" list).
constexpr const char* kImplemented[] = {
    QT_TRANSLATE_NOOP("tt::ui::About", "Run-to-run LQG control of the shaft profile"),
    QT_TRANSLATE_NOOP("tt::ui::About", "In-process compensation of boring-bar deflection"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Feed scheduling against force deformation, with G-code"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Neural corrective pulse of the feed drives at corners"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Hydraulic feed stabilisation"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Calibration of the probe and the gauge, tool stiffness table"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Devices: gauge, probe mandrel, Modbus, CNC correction output"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Run history (SQLite, PostgreSQL), SPC figures (report command)"),
    QT_TRANSLATE_NOOP("tt::ui::About", "The Reports page and PDF reports"),
    QT_TRANSLATE_NOOP("tt::ui::About", "The Controller page: tuning with live predictions and margins"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Integral action, double EWMA and model-mismatch detection"),
    QT_TRANSLATE_NOOP("tt::ui::About", "ARMA identification of the disturbance from the history"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Adaptive control: a robust fallback and a new design on a mismatch"),
    QT_TRANSLATE_NOOP("tt::ui::About", "The controller's changes on the Reports page's control chart"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Users, roles, log-in and the audit trail"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Kiosk mode and an on-screen keypad"),
    QT_TRANSLATE_NOOP("tt::ui::About", "One run request for the Run page, CLI and resume"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Devices in a thread of their own"),
    QT_TRANSLATE_NOOP("tt::ui::About", "The LinuxCNC lathe on the Run page and in simulate"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Plant-wide history: a journal on each terminal, the Plant page"),
    QT_TRANSLATE_NOOP("tt::ui::About", "Retraining of the corrective pulse on drive drifts"),
};

// What is not implemented yet (the About box's "Not yet" list). Remove an item when it lands.
constexpr const char* kNotYet[] = {
    QT_TRANSLATE_NOOP("tt::ui::About", "Adapting to the tool's wear and the lathe's warm-up"),
};

template <std::size_t N>
QStringList translated(const char* const (&items)[N]) {
    QStringList list;
    for (const char* item : items)
        list << QCoreApplication::translate("tt::ui::About", item);
    return list;
}

QString htmlList(const QStringList& items) {
    // One line per item (no wrapping): the box grows wide rather than tall on the 800-pixel screen.
    QString html = QStringLiteral("<ul style=\"white-space:nowrap\">");
    for (const QString& item : items)
        html += QStringLiteral("<li>%1</li>").arg(item.toHtmlEscaped());
    return html + QStringLiteral("</ul>");
}

}  // namespace

QStringList About::implemented() {
    return translated(kImplemented);
}

QStringList About::notYet() {
    return translated(kNotYet);
}

QString About::text(const QString& logFilePath) {
    return tr("<h2>TrueTurn %1</h2><p>Adaptive accuracy control for lathes.</p>"
              "<p><b>Implemented:</b></p>%2<p><b>Not yet implemented:</b></p>%3"
              "<p>Qt %4</p><p>Log file: %5</p>")
        .arg(QString::fromLatin1(tt::kVersion), htmlList(implemented()), htmlList(notYet()),
             QString::fromLatin1(qVersion()), logFilePath.isEmpty() ? tr("not written") : logFilePath.toHtmlEscaped());
}

}  // namespace tt::ui
