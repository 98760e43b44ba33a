#include "ui/keypad.h"

#include <QApplication>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMouseEvent>
#include <QPointingDevice>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace tt::ui {

namespace {

constexpr int kMaxDigits = 15;  ///< a double holds 15 significant digits exactly

QString shown(double v, int decimals) {
    return QString::number(v, 'f', decimals);  // C locale: '.' as decimal point
}

}  // namespace

NumericKeypad::NumericKeypad(QAbstractSpinBox* field, QWidget* parent)
    : QDialog(parent),
      m_field(field),
      m_display(new QLabel(this)),
      m_limits(new QLabel(this)),
      m_problem(new QLabel(this)) {
    setObjectName(QStringLiteral("numericKeypad"));
    setWindowTitle(tr("Enter a number"));
    takeField(field);
    buildLayout();
    updateDisplay();
}

void NumericKeypad::takeField(const QAbstractSpinBox* field) {
    if (auto* d = qobject_cast<const QDoubleSpinBox*>(field)) {
        m_minimum = d->minimum();
        m_maximum = d->maximum();
        m_decimals = d->decimals();
        m_unit = d->suffix().trimmed();
        m_typed = shown(d->value(), m_decimals);
    } else if (auto* i = qobject_cast<const QSpinBox*>(field)) {
        m_minimum = i->minimum();
        m_maximum = i->maximum();
        m_unit = i->suffix().trimmed();
        m_typed = QString::number(i->value());
    }
}

void NumericKeypad::buildLayout() {
    m_display->setObjectName(QStringLiteral("keypadDisplay"));
    m_display->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_display->setMinimumHeight(64);
    m_display->setStyleSheet(QStringLiteral(
        "QLabel { font-size: 26pt; font-weight: bold; background: #ffffff; color: #1f2a36; border: 2px solid #1f2a36;"
        " border-radius: 4px; padding: 4px 12px; }"));
    m_limits->setObjectName(QStringLiteral("keypadLimits"));
    m_limits->setText(limitsText());
    m_problem->setObjectName(QStringLiteral("keypadProblem"));
    m_problem->setStyleSheet(QStringLiteral("QLabel { color: #c62828; font-weight: bold; }"));
    m_problem->setWordWrap(true);

    QGridLayout* keys = buildKeys();
    auto* ok = new QPushButton(tr("OK"), this);
    ok->setObjectName(QStringLiteral("keyOk"));
    ok->setProperty("role", QStringLiteral("primary"));
    auto* cancel = new QPushButton(tr("Cancel"), this);
    cancel->setObjectName(QStringLiteral("keyCancel"));
    for (QPushButton* b : {ok, cancel}) {
        b->setMinimumSize(96, 64);
        b->setStyleSheet(QStringLiteral("QPushButton { font-size: 18pt; }"));
    }
    keys->addWidget(ok, 2, 3, 2, 1);
    connect(ok, &QPushButton::clicked, this, &NumericKeypad::accept);
    connect(cancel, &QPushButton::clicked, this, &NumericKeypad::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_display);
    layout->addWidget(m_limits);
    layout->addLayout(keys);
    layout->addWidget(m_problem);
    layout->addWidget(cancel, 0, Qt::AlignRight);
}

QGridLayout* NumericKeypad::buildKeys() {
    auto* keys = new QGridLayout;
    keys->setSpacing(8);
    const QString digits = QStringLiteral("789456123");
    for (int n = 0; n < digits.size(); ++n)
        keys->addWidget(key(digits.mid(n, 1), QStringLiteral("key") + digits.mid(n, 1), digits.mid(n, 1)), n / 3,
                        n % 3);
    QPushButton* sign = key(QStringLiteral("±"), QStringLiteral("keySign"), QStringLiteral("+/-"));
    sign->setEnabled(m_minimum < 0.0);
    keys->addWidget(sign, 3, 0);
    keys->addWidget(key(QStringLiteral("0"), QStringLiteral("key0"), QStringLiteral("0")), 3, 1);
    QPushButton* point = key(QLocale().decimalPoint(), QStringLiteral("keyPoint"), QStringLiteral("."));
    point->setEnabled(m_decimals > 0);
    keys->addWidget(point, 3, 2);
    keys->addWidget(key(QStringLiteral("⌫"), QStringLiteral("keyBack"), QStringLiteral("back")), 0, 3);
    keys->addWidget(key(tr("Clear"), QStringLiteral("keyClear"), QStringLiteral("clear")), 1, 3);
    return keys;
}

QPushButton* NumericKeypad::key(const QString& text, const QString& name, const QString& code) {
    auto* b = new QPushButton(text, this);
    b->setObjectName(name);
    b->setMinimumSize(88, 64);  // a gloved finger: about 20 mm on a 15" 1280x800 panel
    b->setFocusPolicy(Qt::NoFocus);
    b->setStyleSheet(QStringLiteral("QPushButton { font-size: 22pt; font-weight: bold; }"));
    connect(b, &QPushButton::clicked, this, [this, code] { press(code); });
    return b;
}

void NumericKeypad::press(const QString& k) {
    if (k == u"back") {
        m_typed.chop(1);
    } else if (k == u"clear") {
        m_typed.clear();
    } else if (k == u"+/-") {
        if (m_minimum < 0.0) m_typed = m_typed.startsWith(u'-') ? m_typed.mid(1) : QStringLiteral("-") + m_typed;
    } else if (k == u".") {
        if (m_decimals > 0 && !m_typed.contains(u'.'))
            m_typed += m_typed.isEmpty() || m_typed == u"-" ? QStringLiteral("0.") : QStringLiteral(".");
    } else if (k.size() == 1 && k.front().isDigit()) {
        const qsizetype point = m_typed.indexOf(u'.');
        const bool tooManyDecimals = point >= 0 && m_typed.size() - point - 1 >= m_decimals;
        const qsizetype digits = std::count_if(m_typed.begin(), m_typed.end(), [](QChar c) { return c.isDigit(); });
        if (!tooManyDecimals && digits < kMaxDigits) m_typed += k;
    }
    m_problem->clear();
    updateDisplay();
}

std::optional<double> NumericKeypad::value() const {
    bool ok = false;
    const double v = m_typed.toDouble(&ok);  // QString::toDouble uses the C locale
    if (!ok || !std::isfinite(v) || v < m_minimum || v > m_maximum) return std::nullopt;
    return v;
}

QString NumericKeypad::limitsText() const {
    const QLocale locale;
    const QString range =
        tr("Limits: %1 … %2")
            .arg(locale.toString(m_minimum, 'f', m_decimals), locale.toString(m_maximum, 'f', m_decimals));
    return m_unit.isEmpty() ? range : tr("%1 %2").arg(range, m_unit);
}

void NumericKeypad::accept() {
    const std::optional<double> v = value();
    if (!v) {
        m_problem->setText(m_typed.isEmpty() || m_typed == u"-" || m_typed == u"."
                               ? tr("Type a number first.")
                               : tr("%1 is outside the limits (%2).").arg(m_display->text(), limitsText()));
        return;
    }
    if (auto* d = qobject_cast<QDoubleSpinBox*>(m_field.data()))
        d->setValue(*v);
    else if (auto* i = qobject_cast<QSpinBox*>(m_field.data()))
        i->setValue(static_cast<int>(std::lround(*v)));
    if (m_field) emit m_field->editingFinished();
    QDialog::accept();
}

void NumericKeypad::updateDisplay() {
    QString text = m_typed;
    text.replace(u'.', QLocale().decimalPoint());
    m_display->setText(m_unit.isEmpty() ? text : tr("%1 %2").arg(text, m_unit));
}

KeypadLauncher::KeypadLauncher(QObject* parent) : QObject(parent) {
    qApp->installEventFilter(this);
}

bool KeypadLauncher::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::MouseButtonRelease || m_open) return false;
    auto* edit = qobject_cast<QLineEdit*>(watched);
    auto* field = edit ? qobject_cast<QAbstractSpinBox*>(edit->parentWidget()) : nullptr;
    if (!field || !field->isEnabled() || field->isReadOnly()) return false;
    if (!qobject_cast<QSpinBox*>(field) && !qobject_cast<QDoubleSpinBox*>(field)) return false;
    const auto* mouse = static_cast<QMouseEvent*>(event);
    const bool touch =
        mouse->source() != Qt::MouseEventNotSynthesized ||
        (mouse->pointingDevice() && mouse->pointingDevice()->type() == QInputDevice::DeviceType::TouchScreen);
    if (touch || m_alwaysOn) open(field);
    return false;
}

void KeypadLauncher::open(QAbstractSpinBox* field) {
    auto* keypad = new NumericKeypad(field, field->window());
    keypad->setAttribute(Qt::WA_DeleteOnClose);
    m_open = keypad;
    keypad->open();
    emit keypadOpened(keypad);
}

}  // namespace tt::ui
