#include "ui/controls/number_control.h"

#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLineEdit>
#include <QLocale>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace forcelab {

NumberSpinBox::NumberSpinBox(QWidget* parent)
    : QDoubleSpinBox(parent)
{
    setAlignment(Qt::AlignRight);
    // Edits arrive when the user presses Enter or leaves the field, not at
    // every typed digit (typing "980" must not push 9 and 98 on the way).
    setKeyboardTracking(false);
    setAccelerated(true);
}

void NumberSpinBox::setSignificantDigits(int digits)
{
    m_significant = digits;
    // QDoubleSpinBox rounds its value to `decimals`: keep every digit of a
    // number written in 'g' notation.
    if (digits > 0)
        setDecimals(323);
}

QString NumberSpinBox::textFromValue(double value) const
{
    if (m_significant <= 0)
        return QDoubleSpinBox::textFromValue(value);
    QLocale c = locale();
    c.setNumberOptions(QLocale::OmitGroupSeparator);
    return c.toString(value, 'g', m_significant);
}

double NumberSpinBox::valueFromText(const QString& text) const
{
    QString t = text;
    if (!suffix().isEmpty() && t.endsWith(suffix()))
        t.chop(suffix().size());
    return locale().toDouble(t.trimmed());
}

QValidator::State NumberSpinBox::validate(QString& text, int& /*pos*/) const
{
    // Any number may be typed; one outside the range stays Intermediate, so
    // Enter reports it (outOfRange) instead of the base class refusing the key.
    QString t = text;
    if (!suffix().isEmpty() && t.endsWith(suffix()))
        t.chop(suffix().size());
    t = t.trimmed();
    bool ok = false;
    const double v = locale().toDouble(t, &ok);
    if (ok)
        return v >= minimum() && v <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
    // Half-typed numbers such as "-", "1e" or "1e-".
    static const QString partial = QStringLiteral("0123456789.,eE+-");
    for (QChar ch : t)
        if (!partial.contains(ch))
            return QValidator::Invalid;
    return QValidator::Intermediate;
}

std::optional<double> NumberSpinBox::typedNumber() const
{
    QString t = lineEdit()->displayText();
    if (!suffix().isEmpty() && t.endsWith(suffix()))
        t.chop(suffix().size());
    if (!prefix().isEmpty() && t.startsWith(prefix()))
        t.remove(0, prefix().size());
    bool ok = false;
    const double v = locale().toDouble(t.trimmed(), &ok);
    if (!ok)
        return std::nullopt;
    return v;
}

void NumberSpinBox::reportIfOutside(const std::optional<double>& typed)
{
    if (typed && !(*typed >= minimum() && *typed <= maximum()))
        emit outOfRange(*typed);
}

void NumberSpinBox::keyPressEvent(QKeyEvent* event)
{
    // Read the text before the base class puts the old value back.
    const bool enter = event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter;
    const std::optional<double> typed = enter ? typedNumber() : std::nullopt;
    QDoubleSpinBox::keyPressEvent(event);
    if (enter)
        reportIfOutside(typed);
}

void NumberSpinBox::focusOutEvent(QFocusEvent* event)
{
    const std::optional<double> typed = typedNumber();
    QDoubleSpinBox::focusOutEvent(event);
    reportIfOutside(typed);
}

namespace {

bool isSliderKey(int key)
{
    return key == Qt::Key_Left || key == Qt::Key_Right || key == Qt::Key_Up || key == Qt::Key_Down ||
           key == Qt::Key_PageUp || key == Qt::Key_PageDown || key == Qt::Key_Home || key == Qt::Key_End;
}

} // namespace

bool NumberSlider::event(QEvent* e)
{
    // Claim the slider's keys before the window's shortcuts see them.
    if (e->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(e);
        if (isSliderKey(key->key()) && !(key->modifiers() & (Qt::ControlModifier | Qt::AltModifier))) {
            e->accept();
            return true;
        }
    }
    return QSlider::event(e);
}

void NumberSlider::keyPressEvent(QKeyEvent* e)
{
    // Shift + arrow: one position, a thousandth of the travel (fine). The
    // rest as every slider: arrows a single step, Page Up / Down, Home / End.
    if (e->modifiers() & Qt::ShiftModifier) {
        if (e->key() == Qt::Key_Left || e->key() == Qt::Key_Down) {
            setValue(value() - 1);
            return;
        }
        if (e->key() == Qt::Key_Right || e->key() == Qt::Key_Up) {
            setValue(value() + 1);
            return;
        }
    }
    QSlider::keyPressEvent(e);
}

NumberControl::Spec NumberControl::spawnSpeedSpec()
{
    Spec s;
    s.max = 1e7; // the lesson reader's range for spawn.speed
    s.sliderMax = 1000.0;
    s.decimals = 0;
    return s;
}

NumberControl::NumberControl(const QString& objectName, const Spec& spec, QWidget* parent)
    : QWidget(parent)
    , m_spec(spec)
{
    setObjectName(objectName + QStringLiteral("Control"));
    m_slider = new NumberSlider(Qt::Horizontal, this);
    m_slider->setObjectName(objectName + QStringLiteral("Slider"));
    m_slider->setRange(0, kSteps);
    m_slider->setSingleStep(kSteps / 100);
    m_slider->setPageStep(kSteps / 20);
    m_slider->setMinimumWidth(90);
    m_spin = new NumberSpinBox(this);
    m_spin->setObjectName(objectName + QStringLiteral("Spin"));
    applySpec();

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_slider, 3);
    layout->addWidget(m_spin, 2);
    setFocusProxy(m_spin);

    connect(m_slider, &QSlider::sliderPressed, this, &NumberControl::dragStarted);
    connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
        if (m_updating)
            return;
        const double v = rounded(valueAt(position));
        {
            const QSignalBlocker block(m_spin);
            m_spin->setValue(v);
        }
        emit valueEdited(v, m_slider->isSliderDown());
    });
    connect(m_spin, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (m_updating)
            return;
        {
            const QSignalBlocker block(m_slider);
            m_slider->setValue(positionFor(v));
        }
        emit valueEdited(v, false);
    });
    connect(m_spin, &NumberSpinBox::outOfRange, this, &NumberControl::outOfRange);
    // The slider's own value is a position (0 … kSteps): its description
    // carries the number a student reads, with the unit.
    connect(m_spin, &QDoubleSpinBox::textChanged, m_slider,
            [this](const QString& text) { m_slider->setAccessibleDescription(text); });
    m_slider->setAccessibleDescription(m_spin->text());
}

void NumberControl::setSpokenName(const QString& name)
{
    setAccessibleName(name);
    m_slider->setAccessibleName(tr("%1, slider").arg(name));
    m_spin->setAccessibleName(tr("%1, value").arg(name));
}

void NumberControl::applySpec()
{
    const Spec& spec = m_spec;
    // Decimals first: the range and the value are rounded to them.
    m_spin->setSignificantDigits(spec.significant); // 0 (fixed decimals) too, after a spec with digits
    if (spec.significant <= 0)
        m_spin->setDecimals(spec.decimals);
    m_spin->setRange(spec.min, spec.max);
    m_spin->setSuffix(spec.suffix);
    // A single step of about a hundredth of the slider's span.
    const double span = spec.scale == Scale::Log ? spec.sliderMin : (spec.sliderMax - spec.sliderMin) / 100.0;
    m_spin->setSingleStep(std::max(span, std::pow(10.0, -spec.decimals)));
    // Wide enough for a typical value with the whole unit ("1000 px³/(mass·s²)"),
    // so the unit is never cut; the frame and arrows take about 36 px.
    const QString typical = QStringLiteral("-0000.000") + spec.suffix;
    m_spin->setMinimumWidth(std::max(96, m_spin->fontMetrics().horizontalAdvance(typical) + 36));
}

void NumberControl::setSpec(const Spec& spec, double value)
{
    m_updating = true;
    {
        const QSignalBlocker block(m_spin);
        m_spec = spec;
        applySpec();
    }
    m_updating = false;
    setValue(value);
}

void NumberControl::setValue(double value)
{
    m_updating = true;
    m_spin->setValue(value);
    if (!m_slider->isSliderDown())
        m_slider->setValue(positionFor(value));
    m_updating = false;
    m_slider->setAccessibleDescription(m_spin->text()); // also when only the unit changed (setSpec)
}

double NumberControl::value() const
{
    return m_spin->value();
}

bool NumberControl::isSliderDown() const
{
    return m_slider->isSliderDown();
}

int NumberControl::positionFor(double value) const
{
    const double lo = m_spec.sliderMin, hi = m_spec.sliderMax;
    double f = 0.0;
    if (m_spec.scale == Scale::Log)
        f = value > 0.0 ? std::log(value / lo) / std::log(hi / lo) : 0.0;
    else
        f = (value - lo) / (hi - lo);
    // Outside the slider's span the slider rests at its end; the spin box shows the value.
    return static_cast<int>(std::lround(std::clamp(f, 0.0, 1.0) * kSteps));
}

double NumberControl::valueAt(int position) const
{
    const double f = static_cast<double>(position) / kSteps;
    const double lo = m_spec.sliderMin, hi = m_spec.sliderMax;
    // Log: equal slider moves multiply the value by equal factors.
    if (m_spec.scale == Scale::Log)
        return lo * std::pow(hi / lo, f);
    return lo + f * (hi - lo);
}

double NumberControl::rounded(double value) const
{
    if (m_spec.significant > 0 || m_spec.scale == Scale::Log) {
        // Three significant digits: 0.00123, 4.56e+06.
        if (value == 0.0 || !std::isfinite(value))
            return value;
        const double magnitude = std::pow(10.0, std::floor(std::log10(std::abs(value))) - 2.0);
        const double r = std::round(value / magnitude) * magnitude;
        return m_spec.significant > 0 ? r : std::round(r * std::pow(10.0, m_spec.decimals)) / std::pow(10.0, m_spec.decimals);
    }
    const double scale = std::pow(10.0, m_spec.decimals);
    return std::round(value * scale) / scale;
}

} // namespace forcelab
