#include "ui/controls/ball_table_model.h"

#include "ui/canvas/simulation_controller.h"
#include "ui/controls/ball_commands.h"
#include "ui/controls/readable_numbers.h"
#include "ui/controls/settings_editor.h"
#include "ui/drawing/display_units.h"

#include "sim/world/number_text.h"

#include <QColor>

#include <cmath>

namespace forcelab {

BallTableModel::BallTableModel(SimulationController* controller, SettingsEditor* editor, QObject* parent)
    : QAbstractTableModel(parent)
    , m_controller(controller)
    , m_editor(editor)
    , m_rows(controller->world().balls().size())
{
    connect(m_controller, &SimulationController::stepped, this, &BallTableModel::refresh);
    connect(m_controller, &SimulationController::sceneChanged, this, &BallTableModel::refresh);
}

int BallTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : m_rows;
}

int BallTableModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

double BallTableModel::massOf(double radius, double density)
{
    return density * sim::sphereMass(radius);
}

void BallTableModel::unitsChanged()
{
    beginResetModel();
    endResetModel();
}

QString BallTableModel::pixelUnit(int column)
{
    switch (column) {
    case X: case Y: case Radius: return QStringLiteral("px");
    case Vx: case Vy: return QStringLiteral("px/s");
    case Mass: return QStringLiteral("mass");
    default: return {}; // density is relative to the default ball's, charge is in its own units
    }
}

QVariant BallTableModel::data(const QModelIndex& index, int role) const
{
    const sim::BallState& balls = m_controller->world().balls();
    const int i = index.row();
    if (!index.isValid() || i >= balls.size())
        return {};
    double value = 0.0;
    switch (index.column()) {
    case Index: value = i; break;
    case X: value = balls.position(0, i); break;
    case Y: value = balls.position(1, i); break;
    case Vx: value = balls.velocity(0, i); break;
    case Vy: value = balls.velocity(1, i); break;
    case Radius: value = balls.radius[i]; break;
    case Mass: value = balls.mass[i]; break;
    case Density: value = balls.mass[i] / sim::sphereMass(balls.radius[i]); break;
    case Charge: value = balls.charge[i]; break;
    case Restitution:
        value = balls.restitution[i];
        if (!sim::hasOwnRestitution(value)) { // the world's: said in words, typed over from empty
            switch (role) {
            case Qt::DisplayRole: return tr("world");
            case Qt::EditRole: return QString();
            case kSortRole: return value;
            case Qt::TextAlignmentRole: return int(Qt::AlignRight | Qt::AlignVCenter);
            default: return {};
            }
        }
        break;
    case Pinned: {
        const bool pinned = balls.pinned[static_cast<std::size_t>(i)] != 0;
        if (role == Qt::CheckStateRole)
            return pinned ? Qt::Checked : Qt::Unchecked;
        if (role == kSortRole)
            return pinned ? 1 : 0;
        return {};
    }
    case Colour: {
        const QColor colour = QColor::fromRgb(balls.color[static_cast<std::size_t>(i)]);
        if (role == Qt::DecorationRole)
            return colour;
        if (role == Qt::DisplayRole || role == Qt::EditRole || role == kSortRole)
            return colour.name();
        return {};
    }
    default: return {};
    }
    // In the view's units (SI or px); setData converts a typed value back.
    value = shownUnit(pixelUnit(index.column()), displayUnits()).toShown(value);
    switch (role) {
    case Qt::DisplayRole: return index.column() == Index ? QString::number(i) : humanNumber(value, 5);
    // Typed over as text with every digit (a spin box would round to its decimals).
    case Qt::EditRole: return QString::fromStdString(sim::shortestText(value));
    case kSortRole: return value;
    case Qt::TextAlignmentRole: return int(Qt::AlignRight | Qt::AlignVCenter);
    default: return {};
    }
}

QVariant BallTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal)
        return {};
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case Radius: return tr("Radius. A new radius keeps the density: twice as big is 8 times the mass.");
        case Mass: return tr("Mass, in the mass units of the lesson (a 10 px ball of density 1 has 4189). "
                             "Independent of the size: a small ball can be heavy.");
        case Density: return tr("Mass per volume of a sphere: 1 is the density of every ball a lesson does not "
                                "give a mass.");
        case Charge: return tr("What a magnetic field acts on (1: like the 10 px reference ball).");
        case Restitution: return tr("How much of its speed this ball keeps in a bounce: 0 stops it dead, 1 keeps it "
                                    "all. \"world\": the scene's value. When two balls hit, the smaller value "
                                    "counts. Clear the cell to go back to the world's.");
        case Pinned: return tr("A pinned ball never moves: other balls bounce off it as off a ball too heavy to "
                               "push.");
        default: return {};
        }
    }
    if (role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Index: return tr("Ball");
    case X: return tr("x (%1)").arg(unitText(pixelUnit(X)));
    case Y: return tr("y (%1)").arg(unitText(pixelUnit(Y)));
    case Vx: return tr("vx (%1)").arg(unitText(pixelUnit(Vx)));
    case Vy: return tr("vy (%1)").arg(unitText(pixelUnit(Vy)));
    case Radius: return tr("r (%1)").arg(unitText(pixelUnit(Radius)));
    case Mass: return displayUnits().si ? tr("mass (%1)").arg(unitText(pixelUnit(Mass))) : tr("mass");
    case Density: return tr("density");
    case Charge: return tr("charge");
    case Colour: return tr("colour");
    case Restitution: return tr("restitution");
    case Pinned: return tr("pinned");
    default: return {};
    }
}

Qt::ItemFlags BallTableModel::flags(const QModelIndex& index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.isValid() && index.column() == Pinned)
        f |= Qt::ItemIsUserCheckable;
    else if (index.isValid() && index.column() != Index)
        f |= Qt::ItemIsEditable;
    return f;
}

bool BallTableModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    const sim::BallState& balls = m_controller->world().balls();
    const int i = index.row();
    if (!index.isValid() || i >= balls.size())
        return false;
    sim::Ball ball = balls.ball(i);
    if (index.column() == Pinned) {
        if (role != Qt::CheckStateRole)
            return false;
        ball.pinned = value.toInt() == Qt::Checked;
        return m_editor->editBall(ball.pinned ? tr("Pin ball %1").arg(i) : tr("Free ball %1").arg(i), i, ball,
                                  kBallPinned);
    }
    if (role != Qt::EditRole)
        return false;
    if (index.column() == Restitution && value.toString().trimmed().isEmpty()) {
        ball.restitution = sim::kWorldRestitution;
        return m_editor->editBall(tr("Give ball %1 the world's restitution").arg(i), i, ball, kBallRestitution);
    }
    if (index.column() == Colour) {
        const QColor colour = QColor::fromString(value.toString().trimmed());
        if (!colour.isValid()) {
            emit m_editor->ballEditNote(tr("colour: \"%1\" is not a colour; type a name like red or #e05050")
                                            .arg(value.toString().left(40)),
                                        true);
            return false;
        }
        ball.color = colour.rgb() & 0xffffff;
        return m_editor->editBall(tr("Colour of ball %1").arg(i), i, ball, kBallColour);
    }
    bool ok = false;
    const double typed = value.toDouble(&ok);
    if (!ok || !std::isfinite(typed)) {
        const QString column = headerData(index.column(), Qt::Horizontal).toString();
        emit m_editor->ballEditNote(tr("%1: \"%2\" is not a number").arg(column, value.toString().left(40)), true);
        return false;
    }
    // Typed in the view's units: the world takes px and mass units.
    const double v = fromShown(typed, pixelUnit(index.column()));
    const QString what = headerData(index.column(), Qt::Horizontal).toString();
    const QString text = tr("Set %1 of ball %2").arg(what, QString::number(i));
    switch (index.column()) {
    case X: ball.position.x() = v; return m_editor->editBall(text, i, ball, kBallPosition);
    case Y: ball.position.y() = v; return m_editor->editBall(text, i, ball, kBallPosition);
    case Vx: ball.velocity.x() = v; return m_editor->editBall(text, i, ball, kBallVelocity);
    case Vy: ball.velocity.y() = v; return m_editor->editBall(text, i, ball, kBallVelocity);
    case Radius: {
        const double density = ball.mass / sim::sphereMass(ball.radius);
        ball.radius = v;
        ball.mass = massOf(v, density);
        return m_editor->editBall(text, i, ball, kBallRadius | kBallMass);
    }
    case Mass: ball.mass = v; return m_editor->editBall(text, i, ball, kBallMass);
    case Density: ball.mass = massOf(ball.radius, v); return m_editor->editBall(text, i, ball, kBallMass);
    case Charge: ball.charge = v; return m_editor->editBall(text, i, ball, kBallCharge);
    case Restitution:
        if (v < 0.0) { // below 0 is not "the world's": an empty cell is
            emit m_editor->ballEditNote(tr("restitution: %1 is outside %2; leave it empty for the world's")
                                            .arg(QString::fromStdString(sim::numberText(v)),
                                                 QString::fromStdString(sim::rangeText(0.0, 1.0))),
                                        true);
            return false;
        }
        ball.restitution = v;
        return m_editor->editBall(text, i, ball, kBallRestitution);
    default: return false;
    }
}

void BallTableModel::refresh()
{
    const int rows = m_controller->world().balls().size();
    if (rows != m_rows) {
        beginResetModel();
        m_rows = rows;
        endResetModel();
        return;
    }
    if (rows > 0)
        emit dataChanged(index(0, 0), index(rows - 1, ColumnCount - 1),
                         {Qt::DisplayRole, Qt::EditRole, Qt::CheckStateRole});
}

} // namespace forcelab
