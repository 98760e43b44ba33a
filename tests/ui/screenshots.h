#pragma once

#include <QApplication>
#include <QDir>
#include <QString>
#include <QWidget>

namespace tt::ui::test {

/// Folder for screenshots of the UI tests: <build>/screenshots (created).
inline QString screenshotDir() {
    const QString dir = QStringLiteral(TRUETURN_BINARY_DIR "/screenshots");
    QDir().mkpath(dir);
    return dir;
}

/// Grabs `widget` to <build>/screenshots/<name>.png; returns whether it was written.
inline bool saveScreenshot(QWidget& widget, const QString& name) {
    for (int i = 0; i < 3; ++i)
        QApplication::processEvents();  // pending layout requests after text changes
    return widget.grab().save(QDir(screenshotDir()).filePath(name + QStringLiteral(".png")));
}

}  // namespace tt::ui::test
