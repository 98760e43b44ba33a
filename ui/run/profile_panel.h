#pragma once

#include <QVector>
#include <QWidget>
#include <deque>
#include <map>

#include "core/loop/loop_events.h"
#include "runtime/run/loop_snapshot.h"

namespace tt::plot {
class Chart;
}  // namespace tt::plot

namespace tt::ui {

/// The Run page's plots: the profile of the last part (diameter error at the control points and along
/// the shaft, the tolerance band, the systematic model and the correction path shown by its effect on
/// the diameter) and a history strip of the error at each control point over the last parts (the
/// page places the strip: historyChart()).
class ProfilePanel : public QWidget {
    Q_OBJECT
public:
    explicit ProfilePanel(QWidget* parent = nullptr);

    /// A new run: clears the plots and draws what is fixed (band, model).
    void setRun(const runtime::RunLayout& layout);
    void onLoopEvent(const core::LoopEvent& event);
    /// The part as it really came off the machine (machines that know it: ShaftMachine::trueProfile).
    void onPartProfile(qint64 partNumber, const QVector<double>& zMm, const QVector<double>& errorMm);
    void retranslate();

    plot::Chart* profileChart() const { return m_profile; }
    plot::Chart* historyChart() const { return m_history; }
    /// Parts in the history strip.
    int historyParts() const { return static_cast<int>(m_recent.size()); }
    /// How many parts back the history strip reaches.
    static constexpr int kHistoryParts = 30;

private:
    void drawFixed();
    void rescaleProfile();
    void drawHistory();

    plot::Chart* m_profile;
    plot::Chart* m_history;
    runtime::RunLayout m_layout;
    std::deque<std::pair<qint64, std::vector<double>>> m_recent;  ///< part, deviation per point (NaN: none)
    std::map<qint64, std::pair<QVector<double>, QVector<double>>> m_trueProfiles;  ///< recent true profiles
    qint64 m_lastMeasured = 0;
    qint64 m_lastStarted = 0;
};

}  // namespace tt::ui
