#pragma once
// One number of the Parameters panel: a slider for quick moves beside a spin
// box for exact values. The slider covers a comfortable range, linear or
// logarithmic (for ranges that span decades: G, dt, tolerance, strengths);
// the spin box accepts the whole allowed range. A typed value outside the spin
// box's range is not clamped: it is reported through outOfRange(), so the
// panel can pass it on to the world, which refuses it with its own message.

#include <QDoubleSpinBox>
#include <QSlider>
#include <QString>
#include <QWidget>

#include <optional>


namespace forcelab {

/// A spin box that shows very small or large numbers in 'g' notation and
/// reports typed values outside its range instead of silently correcting them.
class NumberSpinBox : public QDoubleSpinBox {
    Q_OBJECT
public:
    explicit NumberSpinBox(QWidget* parent = nullptr);

    /// 'g' notation with this many significant digits (0: fixed decimals).
    void setSignificantDigits(int digits);

    QString textFromValue(double value) const override;
    double valueFromText(const QString& text) const override;
    QValidator::State validate(QString& text, int& pos) const override;

signals:
    /// The user finished typing a number outside [minimum, maximum]; the box keeps its value.
    void outOfRange(double value);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    /// The number in the edit field (without suffix), if it parses.
    std::optional<double> typedNumber() const;
    void reportIfOutside(const std::optional<double>& typed);

    int m_significant = 0;
};

/// The slider of a number control, with the usual keys: the arrows move it by
/// a hundredth of its travel, Shift + arrows by a thousandth (fine), Page Up /
/// Page Down by a twentieth, Home / End to its ends. While it has the
/// keyboard these keys are its own, not the window's shortcuts (→ steps the
/// simulation everywhere else).
class NumberSlider : public QSlider {
    Q_OBJECT
public:
    using QSlider::QSlider;

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
};

class NumberControl : public QWidget {
    Q_OBJECT
public:
    enum class Scale { Linear, Log };

    /// Everything in the shown unit.
    struct Spec {
        double min = 0.0;       ///< spin box range: the values the world accepts
        double max = 1.0;
        double sliderMin = 0.0; ///< slider range; for Log both must be > 0
        double sliderMax = 1.0;
        Scale scale = Scale::Linear;
        int decimals = 2;       ///< fixed decimals, or with significant > 0 the 'g' digits
        int significant = 0;
        QString suffix;
    };

    /// A random ball's starting speed, px/s (the panel's and the stage's
    /// spawn speed rows): typed up to the lesson reader's limit, a slider to
    /// 1000 px/s, whole numbers.
    static Spec spawnSpeedSpec();

    NumberControl(const QString& objectName, const Spec& spec, QWidget* parent = nullptr);

    /// A new range, slider span, digits and unit (the units shown changed,
    /// issue #36); shows `value` in the new unit without emitting anything.
    void setSpec(const Spec& spec, double value);
    const Spec& spec() const { return m_spec; }

    /// Shows `value` without emitting anything.
    void setValue(double value);
    double value() const;

    /// What a screen reader calls the row: the slider "NAME, slider", the
    /// field "NAME, value"; the slider's description says the value with
    /// its unit as the field shows it ("980 px/s²"), kept up to date.
    void setSpokenName(const QString& name);

    NumberSpinBox* spinBox() const { return m_spin; }
    QSlider* slider() const { return m_slider; }
    /// True while the user drags the slider (consecutive moves merge into one undo step).
    bool isSliderDown() const;

    /// Slider position (0 … kSteps) for a value and back.
    int positionFor(double value) const;
    double valueAt(int position) const;
    static constexpr int kSteps = 1000;

signals:
    /// The user set a value (slider move, spin box, or typed); `dragging` while the slider is held.
    void valueEdited(double value, bool dragging);
    void outOfRange(double value);
    void dragStarted();

private:
    /// Applies m_spec to the spin box (range, digits, unit, step, width).
    void applySpec();
    /// Rounds a slider value to what the spin box shows, so the two agree.
    double rounded(double value) const;

    Spec m_spec;
    QSlider* m_slider = nullptr;
    NumberSpinBox* m_spin = nullptr;
    bool m_updating = false;
};

} // namespace forcelab
