#include "ui/process/feed_block_diagram.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <cmath>

namespace tt::ui {

namespace {

constexpr double kTopBand = 26.0;     ///< the load's label and arrows above the blocks
constexpr double kBottomBand = 30.0;  ///< the loop back from the feed below them
constexpr double kBlockHeight = 70.0;
constexpr double kGap = 26.0;     ///< between blocks: an arrow
constexpr double kOutput = 46.0;  ///< after the cylinder: the feed's arrow and label

const QColor kLine(56, 67, 79);
const QColor kBlockFill(255, 255, 255);
const QColor kSelectedFill(227, 240, 228);
const QColor kSelectedBorder(46, 125, 50);
const QColor kLoad(178, 106, 0);

void arrowHead(QPainter& p, QPointF tip, QPointF from) {
    const QPointF d = tip - from;
    const double length = std::hypot(d.x(), d.y());
    if (length <= 0.0) return;
    const QPointF u = d / length;
    const QPointF n(-u.y(), u.x());
    QPainterPath head;
    head.moveTo(tip);
    head.lineTo(tip - 9.0 * u + 4.5 * n);
    head.lineTo(tip - 9.0 * u - 4.5 * n);
    head.closeSubpath();
    p.fillPath(head, p.pen().color());
}

void arrow(QPainter& p, QPointF from, QPointF to) {
    p.drawLine(from, to);
    arrowHead(p, to, from);
}

}  // namespace

FeedBlockDiagram::FeedBlockDiagram(QWidget* parent) : QWidget(parent) {
    setFocusPolicy(Qt::StrongFocus);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setCursor(Qt::PointingHandCursor);
}

void FeedBlockDiagram::setBlockText(FeedBlock block, const QString& title, const QString& equation) {
    m_titles[static_cast<std::size_t>(block)] = title;
    m_equations[static_cast<std::size_t>(block)] = equation;
    update();
}

void FeedBlockDiagram::setSignalTexts(const QString& load, const QString& feed, const QString& loop, bool loopClosed) {
    m_load = load;
    m_feed = feed;
    m_loop = loop;
    m_loopClosed = loopClosed;
    update();
}

void FeedBlockDiagram::setSelected(FeedBlock block) {
    if (block == m_selected) return;
    m_selected = block;
    update();
    emit blockSelected(block);
}

QSize FeedBlockDiagram::sizeHint() const {
    return {900, minimumSizeHint().height()};
}

QSize FeedBlockDiagram::minimumSizeHint() const {
    return {600, static_cast<int>(kTopBand + kBlockHeight + kBottomBand + 4)};
}

QRectF FeedBlockDiagram::blockRect(FeedBlock block) const {
    const double blockWidth = (width() - 8.0 - kOutput - kGap * (kFeedBlockCount - 1)) / kFeedBlockCount;
    const double x = 4.0 + static_cast<int>(block) * (blockWidth + kGap);
    return {x, kTopBand, blockWidth, kBlockHeight};
}

void FeedBlockDiagram::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    QFont titleFont = font();
    titleFont.setPointSizeF(11.5);
    titleFont.setBold(true);
    QFont textFont = font();
    textFont.setPointSizeF(10.0);

    p.setPen(QPen(kLine, 1.6));
    for (int k = 0; k < kFeedBlockCount; ++k)
        paintBlock(p, static_cast<FeedBlock>(k), titleFont, textFont);
    paintFeedLoop(p, titleFont, textFont);
    paintLoad(p, textFont);
    if (hasFocus()) {
        p.setPen(QPen(kSelectedBorder, 1, Qt::DotLine));
        p.setBrush(Qt::NoBrush);
        p.drawRect(rect().adjusted(0, 0, -1, -1));
    }
}

void FeedBlockDiagram::paintBlock(QPainter& p, FeedBlock block, const QFont& titleFont, const QFont& textFont) const {
    const int k = static_cast<int>(block);
    const QRectF r = blockRect(block);
    const bool chosen = block == m_selected;
    p.setPen(QPen(chosen ? kSelectedBorder : kLine, chosen ? 3.0 : 1.6));
    p.setBrush(chosen ? kSelectedFill : kBlockFill);
    p.drawRoundedRect(r, 6, 6);
    p.setPen(kLine);
    p.setFont(titleFont);
    const QRectF titleRect(r.left() + 3, r.top() + 3, r.width() - 6, 22);
    p.drawText(titleRect, Qt::AlignCenter,
               p.fontMetrics().elidedText(m_titles[k], Qt::ElideRight, static_cast<int>(titleRect.width())));
    p.setFont(textFont);
    p.drawText(QRectF(r.left() + 2, r.top() + 24, r.width() - 4, r.height() - 25), Qt::AlignHCenter | Qt::AlignTop,
               m_equations[k]);
    if (k + 1 < kFeedBlockCount) {
        p.setPen(QPen(kLine, 1.6));
        arrow(p, QPointF(r.right(), r.center().y()), QPointF(r.right() + kGap - 1, r.center().y()));
    }
}

void FeedBlockDiagram::paintFeedLoop(QPainter& p, const QFont& titleFont, const QFont& textFont) const {
    // The feed leaves the cylinder to the right and comes back under the chain to the sensor.
    const QRectF sensor = blockRect(FeedBlock::Sensor);
    const QRectF cylinder = blockRect(FeedBlock::Cylinder);
    const double y = cylinder.center().y();
    const QPointF out(cylinder.right() + kOutput - 8, y);
    p.setPen(QPen(kLine, 1.6));
    arrow(p, QPointF(cylinder.right(), y), out);
    p.setFont(titleFont);
    p.drawText(QRectF(cylinder.right() + 2, y - 24, kOutput, 20), Qt::AlignCenter, m_feed);
    const double bottom = cylinder.bottom() + kBottomBand - 10;
    QPen loopPen(kLine, 1.4);
    if (!m_loopClosed) loopPen.setStyle(Qt::DashLine);
    p.setPen(loopPen);
    const double turn = cylinder.right() + kOutput / 2.0;
    p.drawLine(QPointF(turn, y), QPointF(turn, bottom));
    p.drawLine(QPointF(turn, bottom), QPointF(sensor.center().x(), bottom));
    p.setPen(QPen(kLine, 1.4));
    arrow(p, QPointF(sensor.center().x(), bottom), QPointF(sensor.center().x(), sensor.bottom() + 1));
    p.setFont(textFont);
    p.drawText(QRectF(sensor.center().x() + 8, bottom - 1, turn - sensor.center().x() - 16, kBottomBand - 6),
               Qt::AlignHCenter | Qt::AlignTop, m_loop);
}

void FeedBlockDiagram::paintLoad(QPainter& p, const QFont& textFont) const {
    // The load acts on the tool (read by the sensor) and on the cylinder (leakage).
    const QRectF sensor = blockRect(FeedBlock::Sensor);
    const QRectF cylinder = blockRect(FeedBlock::Cylinder);
    p.setPen(QPen(kLoad, 1.8));
    const double top = 4.0;
    p.drawLine(QPointF(sensor.center().x(), top + 8), QPointF(cylinder.center().x(), top + 8));
    arrow(p, QPointF(sensor.center().x(), top + 8), QPointF(sensor.center().x(), sensor.top() - 1));
    arrow(p, QPointF(cylinder.center().x(), top + 8), QPointF(cylinder.center().x(), cylinder.top() - 1));
    p.setFont(textFont);
    const QRectF loadRect(sensor.center().x() + 10, top - 3, cylinder.center().x() - sensor.center().x() - 20, 20);
    p.fillRect(QRectF(loadRect.center().x() - p.fontMetrics().horizontalAdvance(m_load) / 2.0 - 6, top - 2,
                      p.fontMetrics().horizontalAdvance(m_load) + 12, 20),
               palette().window());
    p.drawText(loadRect, Qt::AlignCenter, m_load);
}

void FeedBlockDiagram::mousePressEvent(QMouseEvent* event) {
    for (int k = 0; k < kFeedBlockCount; ++k)
        if (blockRect(static_cast<FeedBlock>(k)).contains(event->position())) {
            setSelected(static_cast<FeedBlock>(k));
            return;
        }
    QWidget::mousePressEvent(event);
}

void FeedBlockDiagram::keyPressEvent(QKeyEvent* event) {
    const int k = static_cast<int>(m_selected);
    if (event->key() == Qt::Key_Left && k > 0)
        setSelected(static_cast<FeedBlock>(k - 1));
    else if (event->key() == Qt::Key_Right && k + 1 < kFeedBlockCount)
        setSelected(static_cast<FeedBlock>(k + 1));
    else
        QWidget::keyPressEvent(event);
}

}  // namespace tt::ui
