#pragma once

#include <QColor>
#include <QString>
#include <QWidget>
#include <vector>

class QCustomPlot;
class QCPPainter;

namespace tt::plot {

/// A technical x-y chart for the operator pages. All plotting goes through this class so the
/// plotting library (QCustomPlot today) stays behind ui/plot and can be replaced.
class Chart : public QWidget {
    Q_OBJECT
public:
    /// How a series is drawn.
    enum class Style { Line, Points, LineAndPoints, Steps, SmallPoints };

    explicit Chart(QWidget* parent = nullptr);

    void setTitle(const QString& title);
    void setAxisTitles(const QString& x, const QString& y);

    /// Creates or replaces the series `key` (legend shows `label`; none when it is empty). xs and ys
    /// have equal length.
    void setSeries(const QString& key, const QString& label, const std::vector<double>& xs,
                   const std::vector<double>& ys, const QColor& color, Style style = Style::Line);
    /// A shaded band between `lower` and `upper` (tolerance band, prediction band).
    void setBand(const QString& key, const QString& label, const std::vector<double>& xs,
                 const std::vector<double>& lower, const std::vector<double>& upper, const QColor& color);
    void removeSeries(const QString& key);
    void clear();

    /// Number of data points of series `key` (0 when absent); for tests and empty-state logic.
    int pointCount(const QString& key) const;
    /// Fits the axes to the data with a small margin; `includeZeroY` keeps y = 0 visible.
    void rescale(bool includeZeroY = true);
    void setXRange(double lower, double upper);
    void setYRange(double lower, double upper);
    /// About how many ticks the y axis shows (fewer for a short strip chart).
    void setYTickCount(int count);
    /// About how many ticks the x axis shows (fewer for a narrow chart).
    void setXTickCount(int count);
    /// Puts the legend in a corner inside the plot (top right by default): top left for a rising
    /// curve, whose top right holds its last points.
    void setLegendCorner(Qt::Alignment corner);
    /// Puts the legend under the plot in `columns` columns, so it never covers the data.
    void setLegendBelow(int columns);
    /// Redraws (queued; cheap to call often).
    void refresh();
    /// Sets the size of the axis, legend and title fonts, pt (small multiples and printed pages).
    void setFontPointSize(int pointSize);
    /// Paints the chart as vector graphics into `target` of an active painter (a PDF page).
    void render(QCPPainter& painter, const QRect& target);
    /// Writes the chart as PNG; false when the file cannot be written.
    bool savePng(const QString& path, int width = 0, int height = 0);

private:
    void showLegendWhenItHasEntries();
    int graphIndex(const QString& key) const;

    QCustomPlot* m_plot;
};

}  // namespace tt::plot
