#include "ui/process/gcode_view.h"

#include <QFontDatabase>
#include <QPainter>
#include <QTextBlock>

namespace tt::ui {

namespace {

/// The margin beside the text: it only asks the view to paint the numbers.
class NumberArea : public QWidget {
public:
    explicit NumberArea(GCodeView* view) : QWidget(view), m_view(view) {}
    QSize sizeHint() const override { return {m_view->numberAreaWidth(), 0}; }

protected:
    void paintEvent(QPaintEvent* event) override { m_view->paintNumbers(event); }

private:
    GCodeView* m_view;
};

}  // namespace

GCodeView::GCodeView(QWidget* parent) : QPlainTextEdit(parent), m_numbers(new NumberArea(this)) {
    setReadOnly(true);
    setLineWrapMode(QPlainTextEdit::NoWrap);
    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    mono.setPointSize(12);
    setFont(mono);
    setStyleSheet(QStringLiteral("QPlainTextEdit { background: #ffffff; border: 1px solid #8a96a3; }"));
    connect(this, &QPlainTextEdit::blockCountChanged, this, [this] { updateMargin(); });
    connect(this, &QPlainTextEdit::updateRequest, this, [this](const QRect& rect, int dy) {
        if (dy != 0)
            m_numbers->scroll(0, dy);
        else
            m_numbers->update(0, rect.y(), m_numbers->width(), rect.height());
    });
    updateMargin();
}

void GCodeView::setProgram(const QString& program) {
    setPlainText(program);
    moveCursor(QTextCursor::Start);
}

int GCodeView::numberAreaWidth() const {
    int digits = 1;
    for (int n = std::max(1, blockCount()); n >= 10; n /= 10)
        ++digits;
    return 16 + fontMetrics().horizontalAdvance(QLatin1Char('9')) * std::max(3, digits);
}

void GCodeView::updateMargin() {
    setViewportMargins(numberAreaWidth(), 0, 0, 0);
    const QRect r = contentsRect();
    m_numbers->setGeometry(QRect(r.left(), r.top(), numberAreaWidth(), r.height()));
}

void GCodeView::resizeEvent(QResizeEvent* event) {
    QPlainTextEdit::resizeEvent(event);
    updateMargin();
}

void GCodeView::paintNumbers(QPaintEvent* event) {
    QPainter painter(m_numbers);
    painter.fillRect(event->rect(), QColor(0xdf, 0xe4, 0xea));
    painter.setPen(QColor(0x56, 0x61, 0x6d));
    painter.setFont(font());
    QTextBlock block = firstVisibleBlock();
    int number = block.blockNumber() + 1;
    int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
    int bottom = top + qRound(blockBoundingRect(block).height());
    const int height = fontMetrics().height();
    while (block.isValid() && top <= event->rect().bottom()) {
        if (block.isVisible() && bottom >= event->rect().top())
            painter.drawText(0, top, m_numbers->width() - 8, height, Qt::AlignRight, QString::number(number));
        block = block.next();
        top = bottom;
        bottom = top + qRound(blockBoundingRect(block).height());
        ++number;
    }
}

}  // namespace tt::ui
