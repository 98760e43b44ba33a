#pragma once

#include <QPlainTextEdit>

namespace tt::ui {

/// A read-only view of a CNC program with its line numbers in a margin on the left (the numbers are
/// not part of the program), in a fixed-width font large enough to read at the machine.
class GCodeView : public QPlainTextEdit {
    Q_OBJECT
public:
    /// An empty, read-only view.
    explicit GCodeView(QWidget* parent = nullptr);

    /// Shows `program` (replacing what was shown) from its first line.
    void setProgram(const QString& program);
    /// Width of the line-number margin, px.
    int numberAreaWidth() const;
    /// Paints the numbers of the visible lines into the margin (called by the margin widget).
    void paintNumbers(QPaintEvent* event);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void updateMargin();

    QWidget* m_numbers;
};

}  // namespace tt::ui
