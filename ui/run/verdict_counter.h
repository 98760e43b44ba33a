#pragma once

#include <QString>

#include <QWidget>
#include <cstdint>
#include <optional>

#include "core/common/tolerance.h"
#include "core/loop/loop_events.h"

class QLabel;

namespace tt::ui {

/// The setting (QSettings key) "Sound on rework or scrap": the Run page beeps for every part judged rework or
/// scrap (View menu of the main window).
inline const QString kSoundOnOutOfTolerance = QStringLiteral("run/soundOnOutOfTolerance");

/// The Run page's tally of the measured parts by tolerance verdict: the last part's verdict in a big coloured
/// banner (scrap red, rework amber, good green: an out-of-tolerance part never looks accepted), the good,
/// rework and scrap counters and the first-pass yield, in large type (read from a metre away). Counts each
/// PartMeasured event's part verdict (the worst of its points).
class VerdictCounter : public QWidget {
    Q_OBJECT

public:
    explicit VerdictCounter(QWidget* parent = nullptr);

    /// Counts the part of a PartMeasured event that has a verdict. While the run is paused on scrap, the banner
    /// keeps showing the scrap part that paused it (parts measured meanwhile are counted, not shown), until the run
    /// goes on; other events are ignored.
    void onLoopEvent(const core::LoopEvent& event);
    /// Starts from zero (a new run).
    void reset();
    /// The counts so far.
    const core::VerdictCounts& counts() const { return m_counts; }
    /// The last judged part's verdict, if any part was judged since the last reset.
    std::optional<core::ToleranceVerdict> lastVerdict() const { return m_lastVerdict; }

signals:
    /// A part was judged rework or scrap (the Run page sounds its alert on it).
    void outOfTolerance(tt::core::ToleranceVerdict verdict);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void updateTexts();
    void followScrapPause(const core::LoopEvent& stateChange);

    core::VerdictCounts m_counts;
    std::optional<core::ToleranceVerdict> m_lastVerdict;
    std::int64_t m_lastPart = 0;
    std::optional<core::ToleranceVerdict> m_shownVerdict;  ///< the banner's part: the last one, or the scrap part
    std::int64_t m_shownPart = 0;                          ///< that paused the run while it stays paused
    bool m_holdingScrap = false;
    QLabel* m_good;
    QLabel* m_rework;
    QLabel* m_scrap;
    QLabel* m_yield;
    QLabel* m_last;  ///< the last part's verdict, big and coloured
};

}  // namespace tt::ui
