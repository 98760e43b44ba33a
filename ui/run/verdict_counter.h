#pragma once

#include <QWidget>

#include "core/common/tolerance.h"
#include "core/loop/loop_events.h"

class QLabel;

namespace tt::ui {

/// The Run page's tally of the measured parts by tolerance verdict: good, rework and scrap counters and the
/// first-pass yield, in large type (read from a metre away). Counts each PartMeasured event's part verdict
/// (the worst of its points).
class VerdictCounter : public QWidget {
    Q_OBJECT

public:
    explicit VerdictCounter(QWidget* parent = nullptr);

    /// Counts the part of a PartMeasured event that has a verdict; other events are ignored.
    void onLoopEvent(const core::LoopEvent& event);
    /// Starts from zero (a new run).
    void reset();
    /// The counts so far.
    const core::VerdictCounts& counts() const { return m_counts; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void updateTexts();

    core::VerdictCounts m_counts;
    QLabel* m_good;
    QLabel* m_rework;
    QLabel* m_scrap;
    QLabel* m_yield;
};

}  // namespace tt::ui
