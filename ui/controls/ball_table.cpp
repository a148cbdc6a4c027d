#include "ui/controls/ball_table.h"

#include "ui/controls/settings_editor.h"
#include "ui/controls/ball_table_model.h"

#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>
#include <QHBoxLayout>

namespace forcelab {

BallTable::BallTable(SimulationController* controller, SettingsEditor* editor, const QList<QAction*>& actions,
                     QWidget* parent)
    : QWidget(parent)
    , m_model(new BallTableModel(controller, editor, this))
    , m_proxy(new QSortFilterProxyModel(this))
    , m_view(new QTableView)
    , m_note(new QLabel)
{
    setObjectName(QStringLiteral("ballTable"));
    m_proxy->setSourceModel(m_model);
    m_proxy->setSortRole(BallTableModel::kSortRole); // numbers sort as numbers
    m_proxy->setDynamicSortFilter(false); // sorted when a header is clicked, not re-sorted every frame

    m_view->setObjectName(QStringLiteral("ballTableView"));
    // Tab leaves the table (the arrows move between its cells), so a keyboard
    // user is not caught in it on the way round the window.
    m_view->setTabKeyNavigation(false);
    m_view->setModel(m_proxy);
    m_view->setSortingEnabled(true);
    m_view->sortByColumn(BallTableModel::Index, Qt::AscendingOrder);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                            QAbstractItemView::AnyKeyPressed);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_view->setAccessibleName(tr("Balls"));

    m_note->setObjectName(QStringLiteral("ballTableNote"));
    m_note->setWordWrap(true);
    m_note->setText(tr("Double-click a number to type a new one. Undo (Ctrl+Z) takes it back."));

    auto* buttons = new QHBoxLayout;
    for (QAction* action : actions) {
        auto* button = new QToolButton;
        button->setDefaultAction(action);
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        buttons->addWidget(button);
    }
    buttons->addStretch();

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(buttons);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_note);

    connect(editor, &SettingsEditor::ballEditNote, this, [this](const QString& message, bool refused) {
        m_note->setText(refused ? tr("⚠ %1").arg(message) : message);
    });
    connect(m_view->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                if (m_selecting || !current.isValid())
                    return;
                m_selected = m_proxy->mapToSource(current).row();
                emit ballSelected(m_selected);
            });
    // A new set of rows (a ball added or removed, a new lesson) clears the
    // view's selection: put the selected ball back.
    connect(m_model, &QAbstractItemModel::modelReset, this, [this] { setSelectedBall(m_selected); });
}

int BallTable::rowOf(int ball) const
{
    if (ball < 0 || ball >= m_model->rowCount())
        return -1;
    return m_proxy->mapFromSource(m_model->index(ball, 0)).row();
}

void BallTable::setSelectedBall(int index)
{
    m_selected = index;
    m_selecting = true;
    const int row = rowOf(index);
    if (row < 0) {
        m_view->selectionModel()->clearSelection();
    } else {
        const QModelIndex at = m_proxy->index(row, 0);
        m_view->selectionModel()->setCurrentIndex(at, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        m_view->scrollTo(at);
    }
    m_selecting = false;
}

} // namespace forcelab
