#pragma once

#include <QDialog>
#include <QObject>
#include <QPointer>
#include <optional>

class QAbstractSpinBox;
class QGridLayout;
class QLabel;
class QPushButton;

namespace tt::ui {

/// The on-screen numeric keypad for one number field (QSpinBox or QDoubleSpinBox) at a touch terminal:
/// large keys (digits, sign, decimal point, backspace, clear, OK, Cancel), the field's unit (its suffix)
/// and limits shown above the number. OK writes the number into the field when it is a number within the
/// field's limits; otherwise the keypad stays open and says why.
class NumericKeypad : public QDialog {
    Q_OBJECT
public:
    explicit NumericKeypad(QAbstractSpinBox* field, QWidget* parent = nullptr);

    /// Presses a key: "0".."9", "." (decimal point), "+/-" (sign), "back", "clear".
    void press(const QString& key);
    /// The number typed so far, as shown.
    QString typed() const { return m_typed; }
    /// The typed number when it is a number within the field's limits; none otherwise.
    std::optional<double> value() const;
    /// The limits and unit shown ("Limits: 1 … 8 parts").
    QString limitsText() const;

    /// OK: writes the value into the field and closes, or says why not and stays open.
    void accept() override;

private:
    /// Takes the limits, decimals, unit and value of the number field.
    void takeField(const QAbstractSpinBox* field);
    /// The display, the limits, the keys, OK and Cancel.
    void buildLayout();
    /// The grid of digit, sign, decimal point, backspace and clear keys (OK goes into its last column).
    QGridLayout* buildKeys();
    QPushButton* key(const QString& text, const QString& name, const QString& code);
    void updateDisplay();

    QPointer<QAbstractSpinBox> m_field;
    double m_minimum = 0.0;
    double m_maximum = 0.0;
    int m_decimals = 0;
    QString m_unit;
    QString m_typed;
    QLabel* m_display;
    QLabel* m_limits;
    QLabel* m_problem;
};

/// Opens the NumericKeypad for a number field: on a touch of the field's text, or on any click when the
/// "On-screen keypad" setting is on (the arrows still step). One per window; watches the application.
class KeypadLauncher : public QObject {
    Q_OBJECT
public:
    explicit KeypadLauncher(QObject* parent = nullptr);

    /// The "On-screen keypad" setting: open the keypad on a click as well as on a touch.
    void setAlwaysOn(bool on) { m_alwaysOn = on; }
    bool alwaysOn() const { return m_alwaysOn; }
    /// The keypad open now, if any.
    NumericKeypad* openKeypad() const { return m_open; }

signals:
    /// A keypad opened for a field (tests press its keys).
    void keypadOpened(tt::ui::NumericKeypad* keypad);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void open(QAbstractSpinBox* field);

    bool m_alwaysOn = false;
    QPointer<NumericKeypad> m_open;
};

}  // namespace tt::ui
