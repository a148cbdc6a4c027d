#include "ui/docks/force_editor_dock.h"

#include "ui/controls/number_control.h"
#include "ui/controls/settings_editor.h"
#include "ui/canvas/simulation_controller.h"

#include "sim/forces/custom_force.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace forcelab {

namespace {

// Undo ids of the constants' sliders: one per constant, apart from the panel's rows
// and the stage's sliders.
constexpr int kConstantMergeId = 3'000'000;

QLabel* problemLabel(QWidget* parent, const QString& name)
{
    auto* l = new QLabel(parent);
    l->setObjectName(name);
    l->setWordWrap(true);
    l->setStyleSheet(QStringLiteral("color: #b00020;"));
    l->hide();
    return l;
}

} // namespace

ForceEditorDock::ForceEditorDock(SimulationController* controller, SettingsEditor* editor, QWidget* parent)
    : QDockWidget(tr("Force editor"), parent)
    , m_controller(controller)
    , m_editor(editor)
{
    setObjectName(QStringLiteral("forceEditorDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    auto* help = new QLabel(tr("Write your own force law. Use x, y (px), vx, vy (px/s), m, r, q, the time t, the box "
                               "W and H, pi, functions such as sqrt, sin, exp, and your constants."),
                            body);
    help->setWordWrap(true);
    layout->addWidget(help);
    m_enabled = new QCheckBox(tr("Custom force on"), body);
    m_enabled->setObjectName(QStringLiteral("customForceOn"));
    layout->addWidget(m_enabled);
    m_kind = new QComboBox(body);
    m_kind->setObjectName(QStringLiteral("customForceKind"));
    m_kind->addItems({tr("the formulas give the force F (divided by m)"),
                      tr("the formulas give the acceleration a")});
    m_kind->setAccessibleName(tr("What the formulas give"));
    layout->addWidget(m_kind);

    auto* form = new QFormLayout;
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    auto field = [&](const QString& name, const QString& label, const QString& tip, QLabel*& problem) {
        auto* e = new QLineEdit(body);
        e->setObjectName(name);
        e->setAccessibleName(label);
        e->setToolTip(tip);
        QFont mono = e->font();
        mono.setFamily(QStringLiteral("monospace"));
        e->setFont(mono);
        form->addRow(label, e);
        problem = problemLabel(body, name + QStringLiteral("Problem"));
        form->addRow(problem);
        return e;
    };
    m_fx = field(QStringLiteral("customFx"), tr("F_x ="), tr("The x part of the force (or acceleration)"), m_fxProblem);
    m_fy = field(QStringLiteral("customFy"), tr("F_y ="), tr("The y part; y points down"), m_fyProblem);
    m_potential = field(QStringLiteral("customPotential"), tr("U ="),
                        tr("Optional: the potential energy of a conservative law, with F = −∇U"), m_potentialProblem);
    layout->addLayout(form);

    auto* constantsTitle = new QLabel(tr("<b>Constants</b>"), body);
    layout->addWidget(constantsTitle);
    m_constantsBox = new QWidget(body);
    m_constantsGrid = new QGridLayout(m_constantsBox);
    m_constantsGrid->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_constantsBox);
    auto* addRow = new QHBoxLayout;
    m_newName = new QLineEdit(body);
    m_newName->setObjectName(QStringLiteral("customNewConstant"));
    m_newName->setPlaceholderText(tr("name, e.g. k"));
    m_newName->setAccessibleName(tr("New constant's name"));
    m_add = new QPushButton(tr("Add constant"), body);
    m_add->setObjectName(QStringLiteral("customAddConstant"));
    addRow->addWidget(m_newName, 1);
    addRow->addWidget(m_add);
    layout->addLayout(addRow);
    m_constantsProblem = problemLabel(body, QStringLiteral("customConstantsProblem"));
    layout->addWidget(m_constantsProblem);
    layout->addStretch(1);
    setWidget(body);

    connect(m_enabled, &QCheckBox::toggled, this, [this] { apply(QStringLiteral("enabled")); });
    connect(m_kind, &QComboBox::currentIndexChanged, this, [this] { apply(QStringLiteral("kind")); });
    connect(m_fx, &QLineEdit::editingFinished, this, [this] { apply(QStringLiteral("fx")); });
    connect(m_fy, &QLineEdit::editingFinished, this, [this] { apply(QStringLiteral("fy")); });
    connect(m_potential, &QLineEdit::editingFinished, this, [this] { apply(QStringLiteral("potential")); });
    connect(m_add, &QPushButton::clicked, this, &ForceEditorDock::addConstant);
    connect(m_newName, &QLineEdit::returnPressed, this, &ForceEditorDock::addConstant);
    connect(m_controller, &SimulationController::settingsChanged, this, &ForceEditorDock::refresh);
    connect(m_controller, &SimulationController::sceneChanged, this, &ForceEditorDock::refresh);
    refresh();
}

QString ForceEditorDock::problem(const QString& field) const
{
    const QLabel* l = field == QLatin1String("fx")          ? m_fxProblem
                      : field == QLatin1String("fy")        ? m_fyProblem
                      : field == QLatin1String("potential") ? m_potentialProblem
                                                            : m_constantsProblem;
    return l->isHidden() ? QString() : l->text();
}

void ForceEditorDock::refresh()
{
    const sim::CustomForceSettings& c = m_controller->world().settings().custom;
    m_refreshing = true;
    m_enabled->setChecked(c.enabled);
    m_kind->setCurrentIndex(c.acceleration ? 1 : 0);
    m_fx->setText(QString::fromStdString(c.fx));
    m_fy->setText(QString::fromStdString(c.fy));
    m_potential->setText(QString::fromStdString(c.potential));
    m_fx->setToolTip(QString());
    rebuildConstants();
    m_refreshing = false;
}

void ForceEditorDock::rebuildConstants()
{
    const sim::CustomForceSettings& c = m_controller->world().settings().custom;
    // Same names in the same order: only the values move.
    bool same = m_constantSliders.size() == static_cast<qsizetype>(c.constants.size());
    for (qsizetype k = 0; same && k < m_constantSliders.size(); ++k)
        same = m_constantSliders[k]->objectName() ==
               QStringLiteral("customConstant_%1").arg(QString::fromStdString(c.constants[static_cast<std::size_t>(k)].name));
    if (same) {
        for (qsizetype k = 0; k < m_constantSliders.size(); ++k)
            if (!m_constantSliders[k]->isSliderDown())
                m_constantSliders[k]->setValue(c.constants[static_cast<std::size_t>(k)].value);
        return;
    }
    while (QLayoutItem* item = m_constantsGrid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_constantSliders.clear();
    for (std::size_t k = 0; k < c.constants.size(); ++k) {
        const sim::CustomConstant& constant = c.constants[k];
        NumberControl::Spec spec;
        spec.min = -1e12;
        spec.max = 1e12;
        spec.sliderMin = constant.min;
        spec.sliderMax = constant.max;
        spec.significant = 4;
        const QString name = QString::fromStdString(constant.name);
        auto* slider = new NumberControl(QStringLiteral("customConstant_%1").arg(name), spec, m_constantsBox);
        slider->setValue(constant.value);
        slider->setSpokenName(tr("Constant %1").arg(name));
        auto* label = new QLabel(name, m_constantsBox);
        m_constantsGrid->addWidget(label, static_cast<int>(k), 0);
        m_constantsGrid->addWidget(slider, static_cast<int>(k), 1);
        connect(slider, &NumberControl::valueEdited, this, [this, k](double value, bool) {
            const auto& constants = m_controller->world().settings().custom.constants;
            if (k >= constants.size())
                return;
            const QString name = QString::fromStdString(constants[k].name);
            m_editor->editSettings(tr("Constant %1").arg(name),
                                   [k, value](sim::WorldSettings& s) {
                                       sim::CustomConstant& c = s.custom.constants[k];
                                       // The slider's range is the lesson's; a typed value may go past it.
                                       c.min = std::min(c.min, value);
                                       c.max = std::max(c.max, value);
                                       c.value = value;
                                   },
                                   {kConstantMergeId + static_cast<int>(k)});
        });
        m_constantSliders.append(slider);
    }
}

void ForceEditorDock::addConstant()
{
    const QString name = m_newName->text().trimmed();
    if (name.isEmpty())
        return;
    sim::WorldSettings after = m_controller->world().settings();
    after.custom.constants.push_back({name.toStdString(), 1.0, 0.0, 2.0});
    if (auto error = sim::checkCustomForce(after.custom, after.box.width, after.box.height);
        error && error->keyPath.rfind("models.custom.constants", 0) == 0) {
        m_constantsProblem->setText(QString::fromStdString(error->message));
        m_constantsProblem->show();
        return;
    }
    m_constantsProblem->hide();
    if (m_editor->editSettings(tr("Add constant %1").arg(name),
                               [&after](sim::WorldSettings& s) { s.custom.constants = after.custom.constants; }))
        m_newName->clear();
}

void ForceEditorDock::apply(const QString& changed)
{
    if (m_refreshing)
        return;
    const sim::WorldSettings before = m_controller->world().settings();
    sim::WorldSettings after = before;
    after.custom.enabled = m_enabled->isChecked();
    after.custom.acceleration = m_kind->currentIndex() == 1;
    after.custom.fx = m_fx->text().trimmed().toStdString();
    after.custom.fy = m_fy->text().trimmed().toStdString();
    after.custom.potential = m_potential->text().trimmed().toStdString();
    if (after.custom.fx.empty())
        after.custom.fx.assign(1, '0');
    if (after.custom.fy.empty())
        after.custom.fy.assign(1, '0');
    for (QLabel* l : {m_fxProblem, m_fyProblem, m_potentialProblem})
        l->hide();
    // Compiled here first, so the message goes under its field; the world
    // keeps its last good law.
    if (auto error = sim::checkCustomForce(after.custom, after.box.width, after.box.height)) {
        QLabel* where = error->keyPath == "models.custom.fy"          ? m_fyProblem
                        : error->keyPath == "models.custom.potential" ? m_potentialProblem
                        : error->keyPath == "models.custom.fx"        ? m_fxProblem
                                                                      : m_constantsProblem;
        where->setText(QString::fromStdString(error->message));
        where->show();
        return;
    }
    if (after.custom.enabled == before.custom.enabled && after.custom.acceleration == before.custom.acceleration &&
        after.custom.fx == before.custom.fx && after.custom.fy == before.custom.fy &&
        after.custom.potential == before.custom.potential)
        return;
    m_editor->editSettings(tr("Custom force: %1").arg(changed),
                           [&after](sim::WorldSettings& s) { s.custom = after.custom; });
}

} // namespace forcelab
