#include "ui/run/profile_panel.h"

#include <QVBoxLayout>
#include <cmath>
#include <limits>

#include "core/control/profile_interpolation.h"
#include "plot/chart.h"

namespace tt::ui {

namespace {

const QColor kBand(46, 125, 50);
const QColor kModel(230, 126, 34);
const QColor kPath(21, 101, 192);
const QColor kMeasured(198, 40, 40);
const QColor kTrue(120, 128, 138);
const QColor kPointColours[] = {QColor(198, 40, 40),  QColor(21, 101, 192), QColor(46, 125, 50), QColor(230, 126, 34),
                                QColor(106, 27, 154), QColor(0, 131, 143),  QColor(93, 64, 55),  QColor(84, 110, 122)};

std::vector<double> toStd(const QVector<double>& v) {
    return {v.begin(), v.end()};
}

}  // namespace

ProfilePanel::ProfilePanel(QWidget* parent) : QWidget(parent), m_profile(new plot::Chart(this)), m_history(new plot::Chart(this)) {
    m_profile->setObjectName(QStringLiteral("profileChart"));
    m_history->setObjectName(QStringLiteral("historyChart"));
    m_profile->setMinimumHeight(220);
    m_history->setMinimumHeight(180);  // the Run page fits 1280 x 800 with the verdict banner
    m_history->setYTickCount(3);
    // Before the first run: the axes of a 325 mm shaft and of the strip, not arbitrary ones.
    m_profile->setXRange(0.0, 325.0);
    m_profile->setYRange(-0.05, 0.25);
    m_history->setXRange(1.0, kHistoryParts);
    m_history->setYRange(-0.05, 0.05);
    // The history strip is placed by the page (it may sit elsewhere than the profile).
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_profile, 1);
    retranslate();
}

void ProfilePanel::retranslate() {
    m_profile->setTitle(tr("Last part: diameter error along the shaft"));
    m_profile->setAxisTitles(tr("x along the shaft, mm"), tr("diameter error, mm"));
    m_history->setTitle(tr("Error at the points, last %1 parts").arg(kHistoryParts));
    m_history->setAxisTitles(tr("part"), tr("diameter error, mm"));
    if (!m_layout.pointZMm.isEmpty()) {
        drawFixed();
        drawHistory();
    }
}

void ProfilePanel::setRun(const runtime::RunLayout& layout) {
    m_layout = layout;
    m_recent.clear();
    m_trueProfiles.clear();
    m_lastMeasured = 0;
    m_lastStarted = 0;
    m_profile->clear();
    m_history->clear();
    // The legends go under the plots once there is something to name (an empty legend there upsets the
    // plot's layout).
    m_profile->setLegendBelow(3);
    m_history->setLegendBelow(3);
    drawFixed();
    m_profile->setXRange(0.0, layout.partLengthMm);
    m_profile->rescale(true);
    m_profile->refresh();
    m_history->refresh();
}

void ProfilePanel::drawFixed() {
    const std::vector<double> xs = {0.0, m_layout.partLengthMm};
    m_profile->setBand(QStringLiteral("tolerance"), tr("tolerance ±%1").arg(m_layout.toleranceMm, 0, 'f', 3), xs,
                       {-m_layout.toleranceMm, -m_layout.toleranceMm}, {m_layout.toleranceMm, m_layout.toleranceMm},
                       kBand);
    if (!m_layout.systematicZMm.isEmpty())
        m_profile->setSeries(QStringLiteral("model"), tr("model d(x)"), toStd(m_layout.systematicZMm),
                             toStd(m_layout.systematicErrorMm), kModel);
}

void ProfilePanel::onLoopEvent(const core::LoopEvent& event) {
    if (m_layout.pointZMm.isEmpty()) return;
    if (event.kind == core::LoopEvent::Kind::PartStarted && !event.path.zMm.empty()) {
        // The cutter's radial correction shown by its effect on the diameter (-2 y_set): it mirrors the
        // systematic model where the feed-forward cancels it.
        std::vector<double> onDiameter;
        onDiameter.reserve(event.path.xCorrectionMm.size());
        for (double y : event.path.xCorrectionMm)
            onDiameter.push_back(-2.0 * y);
        m_profile->setSeries(QStringLiteral("path"), tr("correction, part %1").arg(event.partNumber), event.path.zMm,
                             onDiameter, kPath);
        m_lastStarted = event.partNumber;
        rescaleProfile();
        return;
    }
    if (event.kind != core::LoopEvent::Kind::PartMeasured || !event.measurement) return;
    const core::PartMeasurementRecord& m = *event.measurement;
    std::vector<double> zs, errors, all(m.points.size(), std::numeric_limits<double>::quiet_NaN());
    for (const core::PointMeasurementRecord& p : m.points) {
        if (!p.accepted || !p.measuredMm) continue;
        zs.push_back(p.zMm);
        errors.push_back(*p.measuredMm - p.nominalMm);
        all[static_cast<std::size_t>(p.pointIndex)] = *p.measuredMm - p.nominalMm;
    }
    m_profile->setSeries(QStringLiteral("measured"), tr("part %1 gauged").arg(m.partNumber), zs, errors, kMeasured,
                         plot::Chart::Style::Points);
    if (zs.size() >= 2) {
        const core::PiecewiseCubic curve = core::PiecewiseCubic::pchip(zs, errors);
        std::vector<double> x, y;
        for (int i = 0; i <= 130; ++i) {
            const double z = m_layout.partLengthMm * i / 130.0;
            x.push_back(z);
            y.push_back(curve.value(z));
        }
        m_profile->setSeries(QStringLiteral("interpolated"), tr("between points"), x, y, kMeasured.lighter(130));
    } else {
        m_profile->removeSeries(QStringLiteral("interpolated"));
    }
    // The same part as the simulator made it (the truth the gauge saw), when known.
    const auto truth = m_trueProfiles.find(m.partNumber);
    if (truth != m_trueProfiles.end())
        m_profile->setSeries(QStringLiteral("true"), tr("true profile"), toStd(truth->second.first),
                             toStd(truth->second.second), kTrue);
    else
        m_profile->removeSeries(QStringLiteral("true"));
    m_lastMeasured = m.partNumber;
    m_recent.emplace_back(m.partNumber, all);
    while (static_cast<int>(m_recent.size()) > kHistoryParts)
        m_recent.pop_front();
    rescaleProfile();
    drawHistory();
}

void ProfilePanel::rescaleProfile() {
    m_profile->rescale(true);
    m_profile->setXRange(0.0, m_layout.partLengthMm);
    m_profile->refresh();
}

void ProfilePanel::onPartProfile(qint64 partNumber, const QVector<double>& zMm, const QVector<double>& errorMm) {
    if (m_layout.pointZMm.isEmpty()) return;
    m_trueProfiles[partNumber] = {zMm, errorMm};
    while (m_trueProfiles.size() > 16)
        m_trueProfiles.erase(m_trueProfiles.begin());
}

void ProfilePanel::drawHistory() {
    if (m_recent.empty()) return;
    for (int i = 0; i < m_layout.pointZMm.size(); ++i) {
        std::vector<double> parts, errors;
        for (const auto& [part, values] : m_recent) {
            if (std::isnan(values[static_cast<std::size_t>(i)])) continue;
            parts.push_back(static_cast<double>(part));
            errors.push_back(values[static_cast<std::size_t>(i)]);
        }
        m_history->setSeries(QStringLiteral("point%1").arg(i), tr("x = %1").arg(m_layout.pointZMm[i], 0, 'f', 0), parts,
                             errors, kPointColours[i % 8], plot::Chart::Style::LineAndPoints);
    }
    m_history->setBand(QStringLiteral("tolerance"), tr("tolerance"),
                       {static_cast<double>(m_recent.front().first), static_cast<double>(m_recent.back().first)},
                       {-m_layout.toleranceMm, -m_layout.toleranceMm}, {m_layout.toleranceMm, m_layout.toleranceMm},
                       kBand);
    m_history->rescale(true);
    m_history->refresh();
}

}  // namespace tt::ui
