#pragma once

#include <QColor>
#include <QHash>
#include <QImage>
#include <QRect>
#include <algorithm>
#include <cmath>

namespace tt::ui::test {

/// Relative luminance of an sRGB colour (WCAG 2.1, definition "relative luminance").
inline double relativeLuminance(const QColor& c) {
    auto channel = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    return 0.2126 * channel(c.redF()) + 0.7152 * channel(c.greenF()) + 0.0722 * channel(c.blueF());
}

/// Contrast ratio of two colours, 1 .. 21 (WCAG 2.1, definition "contrast ratio").
inline double contrastRatio(const QColor& a, const QColor& b) {
    const double la = relativeLuminance(a);
    const double lb = relativeLuminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

/// What a region of a rendered image shows: its background (the most frequent colour) and the colour that
/// contrasts most with it (the core of the text's glyphs, or of an arrow), with their ratio.
struct RegionContrast {
    QColor background;
    QColor foreground;
    double ratio = 1.0;
};

/// Samples every pixel of `region` of `image` (clipped to the image).
inline RegionContrast sampleContrast(const QImage& image, const QRect& region) {
    const QRect r = region.intersected(image.rect());
    RegionContrast out;
    if (r.isEmpty()) return out;
    QHash<QRgb, int> counts;
    for (int y = r.top(); y <= r.bottom(); ++y)
        for (int x = r.left(); x <= r.right(); ++x)
            ++counts[image.pixel(x, y) | 0xff000000u];
    int most = 0;
    for (auto it = counts.cbegin(); it != counts.cend(); ++it)
        if (it.value() > most) {
            most = it.value();
            out.background = QColor(it.key());
        }
    out.foreground = out.background;
    for (auto it = counts.cbegin(); it != counts.cend(); ++it) {
        const double ratio = contrastRatio(QColor(it.key()), out.background);
        if (ratio > out.ratio) {
            out.ratio = ratio;
            out.foreground = QColor(it.key());
        }
    }
    return out;
}

}  // namespace tt::ui::test
