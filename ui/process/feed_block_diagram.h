#pragma once

#include <QRectF>
#include <QString>
#include <QWidget>
#include <array>

class QPainter;

namespace tt::ui {

/// The blocks of the hydraulic feed stabiliser's chain (paper 003), in signal order.
enum class FeedBlock { Sensor, Amplifier, Magnet, Spool, Slot, Cylinder };
inline constexpr int kFeedBlockCount = 6;

/// The block diagram of the chain: sensor -> amplifier -> electromagnet -> spool -> slot -> cylinder ->
/// feed v, the load P entering the sensor (through the tool) and the cylinder (leakage), and the path
/// back from the feed to the sensor through the chip thickness (drawn dashed when the force does not
/// follow the feed). A block is chosen by a click or with the arrow keys; its parameters are edited
/// beside the diagram.
class FeedBlockDiagram : public QWidget {
    Q_OBJECT
public:
    explicit FeedBlockDiagram(QWidget* parent = nullptr);

    /// The title and equation lines shown in block `block` (translated by the owner).
    void setBlockText(FeedBlock block, const QString& title, const QString& equation);
    /// Labels of the load, the feed and the loop through the chip; `loopClosed` draws the loop solid.
    void setSignalTexts(const QString& load, const QString& feed, const QString& loop, bool loopClosed);

    FeedBlock selected() const { return m_selected; }
    void setSelected(FeedBlock block);
    /// Where block `block` is drawn (for tests that click it).
    QRectF blockRect(FeedBlock block) const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void blockSelected(tt::ui::FeedBlock block);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    /// Block `block`: its box (highlighted when chosen), title and equation, and the arrow to the next.
    void paintBlock(QPainter& p, FeedBlock block, const QFont& titleFont, const QFont& textFont) const;
    /// The feed leaving the cylinder and the loop back under the chain to the sensor.
    void paintFeedLoop(QPainter& p, const QFont& titleFont, const QFont& textFont) const;
    /// The load acting on the sensor (through the tool) and on the cylinder (leakage).
    void paintLoad(QPainter& p, const QFont& textFont) const;

    std::array<QString, kFeedBlockCount> m_titles;
    std::array<QString, kFeedBlockCount> m_equations;
    QString m_load;
    QString m_feed;
    QString m_loop;
    bool m_loopClosed = false;
    FeedBlock m_selected = FeedBlock::Spool;
};

}  // namespace tt::ui
