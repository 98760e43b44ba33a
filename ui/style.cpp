#include "ui/style.h"

#include <QApplication>
#include <QFile>
#include <QFont>
#include <QStyleFactory>

namespace tt::ui {

void applyOperatorStyle(QApplication& app) {
    app.setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPointSize(13);
    app.setFont(font);
    QFile sheet(QStringLiteral(":/style/trueturn.qss"));
    if (sheet.open(QIODevice::ReadOnly)) app.setStyleSheet(QString::fromUtf8(sheet.readAll()));
}

}  // namespace tt::ui
