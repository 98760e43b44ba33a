#include "ui/style.h"

#include <QApplication>
#include <QColor>
#include <QFile>
#include <QFont>
#include <QPalette>
#include <QStyleFactory>

namespace tt::ui {

void applyOperatorStyle(QApplication& app) {
    app.setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPointSize(13);
    app.setFont(font);
    // Selected items (lists, tables, the open list of a combo box): white on dark blue, never white on white.
    QPalette palette = app.palette();
    for (QPalette::ColorGroup group : {QPalette::Active, QPalette::Inactive}) {
        palette.setColor(group, QPalette::Highlight, QColor(0x1f, 0x5f, 0x99));
        palette.setColor(group, QPalette::HighlightedText, Qt::white);
        palette.setColor(group, QPalette::Text, QColor(0x1f, 0x2a, 0x36));
        palette.setColor(group, QPalette::ButtonText, QColor(0x1f, 0x2a, 0x36));
        palette.setColor(group, QPalette::WindowText, QColor(0x1f, 0x2a, 0x36));
    }
    app.setPalette(palette);
    QFile sheet(QStringLiteral(":/style/trueturn.qss"));
    if (sheet.open(QIODevice::ReadOnly)) app.setStyleSheet(QString::fromUtf8(sheet.readAll()));
}

}  // namespace tt::ui
