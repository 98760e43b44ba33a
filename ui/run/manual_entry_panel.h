#pragma once

#include <QVector>
#include <QWidget>
#include <optional>

class QLabel;
class QLineEdit;
class QGridLayout;

namespace tt::ui {

/// Manual entry of measured diameters for a shop with a hand micrometer: one big field per control
/// point with its position and the nominal, each value checked against nominal ± the plausible range
/// as it is entered (the measuring session's rule), Enter moves to the next point; after the last
/// point the part's diameters go to the loop. Values stay editable (with undo) until then.
class ManualEntryPanel : public QWidget {
    Q_OBJECT
public:
    explicit ManualEntryPanel(QWidget* parent = nullptr);

    /// The control points and the rule of a new run (clears the fields).
    void setPoints(const QVector<double>& pointZMm, double nominalDiameterMm, double plausibleRangeMm);
    /// The part whose diameters are expected now (none: nothing to enter).
    void setAwaitingPart(std::optional<qint64> partNumber);
    void retranslate();

    int fieldCount() const { return static_cast<int>(m_fields.size()); }
    QLineEdit* field(int index) const { return m_fields.at(index); }
    /// The refusal shown for field `index` (empty when its value is fine).
    QString message(int index) const;

signals:
    /// All fields hold plausible values and Enter was pressed on the last one.
    void diametersEntered(qint64 partNumber, const QVector<double>& diametersMm);
    /// A value was refused, with the reason (for the alarm list).
    void valueRefused(const QString& text);

private:
    void onReturn(int index);
    std::optional<double> check(int index);
    void rebuild();
    void showMessage(int index, const QString& text);

    QLabel* m_title;
    QLabel* m_hint;
    QGridLayout* m_grid;
    QVector<QLabel*> m_labels;
    QVector<QLineEdit*> m_fields;
    QVector<QLabel*> m_units;
    QLabel* m_message;
    int m_messageField = -1;
    QVector<double> m_points;
    double m_nominal = 0.0;
    double m_range = 0.0;
    std::optional<qint64> m_part;
};

}  // namespace tt::ui
