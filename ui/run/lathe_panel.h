#pragma once

#include <QString>
#include <QWidget>
#include <optional>

class QLabel;
class QPushButton;

namespace tt::ui {

/// What the operator does at the real lathe, big enough to read and press from the machine: machine the
/// part whose corrections are on the CNC and confirm it with the big "Part N finished" button; measure the
/// finished parts at the control point shown (the gauge's DATA button, or "Take gauge reading" for a polled
/// gauge; or by hand below).
class LathePanel : public QWidget {
    Q_OBJECT
public:
    /// What the panel shows.
    struct View {
        bool runGoing = false;                ///< a run on the real lathe is going (running or paused)
        std::optional<qint64> partOnMachine;  ///< the part being machined
        QString cncValue;                     ///< what the CNC output last did ("part 7: part-7.nc")
        std::optional<qint64> awaitingPart;   ///< the part waiting longest for its diameters
        int nextPoint = 0;                    ///< its next control point (0-based)
        int pointCount = 0;
        double nextPointXMm = 0.0;  ///< where to measure, mm from the part's left end
        bool byHand = false;        ///< the diameters are typed in (the manual entry panel)
        bool haveGauge = false;     ///< a gauge device is connected
        bool gaugeReady = false;    ///< and answers
        QString gaugeValue;         ///< its last reading ("26.812 mm")
    };

    explicit LathePanel(QWidget* parent = nullptr);
    /// Shows `view` (texts, which buttons can be pressed).
    void setView(const View& view);
    /// Sets every visible text (also on a language change).
    void retranslate();

    /// The big "Part N finished" button.
    QPushButton* finishedButton() const { return m_finished; }
    /// "Take gauge reading" (shown with a gauge device, when the diameters are not typed by hand).
    QPushButton* readingButton() const { return m_reading; }
    /// What to do with the machine / where to measure, as shown (for tests).
    QString machineText() const;
    QString measureText() const;

signals:
    /// The operator pressed Part finished.
    void partFinished();
    /// The operator asks the gauge for a reading.
    void readingRequested();

private:
    QString machineDetail() const;
    QString measureDetail() const;

    View m_view;
    std::optional<qint64> m_pressedPart;  ///< the part whose Part finished was pressed last
    QLabel* m_machine;
    QLabel* m_machineDetail;
    QLabel* m_measure;
    QLabel* m_measureDetail;
    QPushButton* m_reading;
    QPushButton* m_finished;
};

}  // namespace tt::ui
