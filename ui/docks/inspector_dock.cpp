#include "ui/docks/inspector_dock.h"

#include "ui/controls/readable_numbers.h"
#include "ui/canvas/simulation_controller.h"
#include "ui/drawing/display_units.h"
#include "ui/drawing/human_number.h"

#include "sim/forces/force_model.h"
#include "sim/world/world.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QLabel>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace forcelab {

namespace {

// "(x, y) unit", and "|v| = size" when `symbol` is given; `pixelUnit` as
// the world has it, shown in the view's units (ui/drawing/display_units.h).
QString vec(const sim::Vec2& v, const QString& pixelUnit, const QString& symbol = {})
{
    const ShownUnit u = shownUnit(pixelUnit, displayUnits());
    // In px one decimal; in SI four significant digits (0.25 m is 25 px).
    auto num = [&u](double x) {
        return u.px != 0 || u.mass != 0 ? humanNumber(u.toShown(x), 4) : QString::number(x, 'f', 1);
    };
    const QString xy = QStringLiteral("(%1, %2) %3").arg(num(v.x()), num(v.y()), u.text);
    return symbol.isEmpty() ? xy : xy + QStringLiteral("   |%1| = %2").arg(symbol, num(v.norm()));
}

QLabel* valueLabel(const QString& name, QWidget* parent)
{
    auto* label = new QLabel(parent);
    label->setObjectName(name);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Digits of equal width: the numbers do not jitter as they change.
    QFont f = label->font();
    f.setFamily(QStringLiteral("monospace"));
    f.setStyleHint(QFont::TypeWriter);
    label->setFont(f);
    return label;
}

} // namespace

std::vector<InspectorDock::ModelForce> InspectorDock::modelForces(const sim::World& world, int i,
                                                                  const sim::Vec2& /*acceleration*/)
{
    std::vector<ModelForce> forces;
    if (i < 0 || i >= world.balls().size())
        return forces;
    // F = m a for each model that is on, with the world's own wind, random
    // values and pointer (sim/forces/force_models.h lists the models).
    const double m = world.balls().mass[i];
    for (const sim::World::SourceAcceleration& source : world.accelerationBySource(i))
        forces.push_back(ModelForce{QString::fromUtf8(source.model.data(), static_cast<qsizetype>(source.model.size())),
                                    m * source.acceleration});
    return forces;
}

InspectorDock::InspectorDock(SimulationController* controller, QWidget* parent)
    : QDockWidget(tr("Inspector"), parent)
    , m_controller(controller)
{
    setObjectName(QStringLiteral("inspectorDock"));
    m_pages = new QStackedWidget;

    auto* hint = new QLabel(tr("Click a ball to see its numbers."));
    hint->setObjectName(QStringLiteral("inspectorHint"));
    hint->setAlignment(Qt::AlignCenter);
    hint->setWordWrap(true);
    hint->setStyleSheet(QStringLiteral("color: #5a6270"));
    m_pages->addWidget(hint);

    auto* page = new QWidget;
    auto* form = new QFormLayout;
    form->setLabelAlignment(Qt::AlignRight);
    m_ballLabel = valueLabel(QStringLiteral("inspectorBall"), page);
    m_positionLabel = valueLabel(QStringLiteral("inspectorPosition"), page);
    m_velocityLabel = valueLabel(QStringLiteral("inspectorVelocity"), page);
    m_accelerationLabel = valueLabel(QStringLiteral("inspectorAcceleration"), page);
    m_massLabel = valueLabel(QStringLiteral("inspectorMass"), page);
    form->addRow(tr("Ball"), m_ballLabel);
    form->addRow(tr("Position x"), m_positionLabel);
    form->addRow(tr("Velocity v"), m_velocityLabel);
    form->addRow(tr("Acceleration a"), m_accelerationLabel);
    form->addRow(tr("Mass, radius"), m_massLabel);
    m_forcesLabel = new QLabel(page);
    m_forcesLabel->setObjectName(QStringLiteral("inspectorForces"));
    m_forcesLabel->setTextFormat(Qt::RichText);
    m_trailCheck = new QCheckBox(tr("Draw its trail"), page);
    m_trailCheck->setObjectName(QStringLiteral("trailCheck"));
    connect(m_trailCheck, &QCheckBox::toggled, this, &InspectorDock::trailToggled);
    auto* layout = new QVBoxLayout(page);
    layout->addLayout(form);
    layout->addWidget(m_forcesLabel);
    layout->addWidget(m_trailCheck);
    layout->addStretch(1);
    m_pages->addWidget(page);
    setWidget(m_pages);

    connect(m_controller, &SimulationController::stepped, this, &InspectorDock::refresh);
    // A reset keeps the canvas's selection (while the ball is there): the
    // Inspector keeps it too, or a click on the still-ringed ball, which
    // changes no selection, would never fill it again.
    connect(m_controller, &SimulationController::sceneChanged, this, [this] { setSelectedBall(m_readout.ball); });
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible)
            refresh();
    });
}

bool InspectorDock::isTrailOn() const
{
    return m_trailCheck->isChecked();
}

void InspectorDock::setSelectedBall(int index)
{
    const int n = m_controller->world().balls().size();
    m_readout = Readout{};
    m_readout.ball = index >= 0 && index < n ? index : -1;
    {
        const QSignalBlocker block(m_trailCheck);
        m_trailCheck->setChecked(false);
    }
    m_pages->setCurrentIndex(m_readout.ball >= 0 ? 1 : 0);
    refresh();
}

void InspectorDock::refresh()
{
    const sim::World& world = m_controller->world();
    const int i = m_readout.ball;
    if (i < 0 || i >= world.balls().size()) {
        m_pages->setCurrentIndex(0);
        return;
    }
    // Every frame costs a force evaluation: only while someone can see it.
    if (!isVisible() && m_readout.mass > 0.0)
        return;
    const sim::BallState& balls = world.balls();
    Readout& r = m_readout;
    r.position = balls.position.col(i);
    r.velocity = balls.velocity.col(i);
    r.acceleration = world.accelerations().col(i);
    r.mass = balls.mass[i];
    r.radius = balls.radius[i];
    r.forces = modelForces(world, i, r.acceleration);
    r.totalForce = r.mass * r.acceleration;

    m_ballLabel->setText(tr("#%1 of %2").arg(i).arg(balls.size()));
    m_positionLabel->setText(vec(r.position, QStringLiteral("px")));
    m_velocityLabel->setText(vec(r.velocity, QStringLiteral("px/s"), QStringLiteral("v")));
    m_accelerationLabel->setText(vec(r.acceleration, QStringLiteral("px/s²"), QStringLiteral("a")));
    const ShownUnit massUnit = shownUnit(QStringLiteral("mass"), displayUnits());
    const ShownUnit length = shownUnit(QStringLiteral("px"), displayUnits());
    if (massUnit.mass != 0)
        m_massLabel->setText(tr("m = %1 %2, r = %3 %4")
                                 .arg(humanNumber(massUnit.toShown(r.mass), 5), massUnit.text,
                                      humanNumber(length.toShown(r.radius), 4), length.text));
    else
        m_massLabel->setText(tr("m = %1, r = %2 px").arg(r.mass, 0, 'g', 5).arg(r.radius, 0, 'f', 2));
    const ShownUnit forceUnit = shownUnit(QStringLiteral("mass·px/s²"), displayUnits());

    QString html = QStringLiteral("<b>%1</b><table cellspacing='0' cellpadding='2'>").arg(tr("Forces F = m a"));
    // Four digits of the largest force in the table: a component far below
    // that is rounding noise (1.4e-09 next to 2000) and shows as 0.
    double scale = forceUnit.toShown(r.totalForce.cwiseAbs().maxCoeff());
    for (const ModelForce& f : r.forces)
        scale = std::max(scale, forceUnit.toShown(f.force.cwiseAbs().maxCoeff()));
    auto row = [&html, scale, &forceUnit](const QString& name, const sim::Vec2& pixelForce, bool bold) {
        const sim::Vec2 f(forceUnit.toShown(pixelForce.x()), forceUnit.toShown(pixelForce.y()));
        const QString b = bold ? QStringLiteral("<b>") : QString(), e = bold ? QStringLiteral("</b>") : QString();
        html += QStringLiteral("<tr><td>%1%2%3</td><td align='right'>&nbsp;%1%4%3</td><td align='right'>&nbsp;%1%5%3</td></tr>")
                    .arg(b, name.toHtmlEscaped(), e)
                    .arg(rounded(f.x(), scale), rounded(f.y(), scale));
    };
    html += QStringLiteral("<tr><td></td><td align='right'>F<sub>x</sub></td><td align='right'>F<sub>y</sub></td></tr>");
    for (const ModelForce& f : r.forces)
        row(f.model, f.force, false);
    if (r.forces.empty())
        html += QStringLiteral("<tr><td colspan='3'>%1</td></tr>").arg(tr("no force acts"));
    row(tr("total"), r.totalForce, true);
    html += QStringLiteral("</table><span style='color:#5a6270'>%1</span>").arg(tr("in %1").arg(forceUnit.text));
    m_forcesLabel->setText(html);
    m_pages->setCurrentIndex(1);
}

} // namespace forcelab
