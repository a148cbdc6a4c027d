#include "ui/stage/stage_tool_title.h"

#include <QDockWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QToolButton>

namespace forcelab {

StageToolTitle::StageToolTitle(QDockWidget* dock)
    : QWidget(dock)
{
    setObjectName(QStringLiteral("stageToolTitle"));
    setAutoFillBackground(true);
    QPalette p = palette(); // the stage bar's colours
    p.setColor(QPalette::Window, QColor(0x1d, 0x22, 0x2c));
    p.setColor(QPalette::WindowText, Qt::white);
    p.setColor(QPalette::ButtonText, Qt::white);
    setPalette(p);
    m_title = new QLabel(dock->windowTitle(), this);
    QFont bold = font();
    bold.setBold(true);
    m_title->setFont(bold);
    auto* close = new QToolButton(this);
    close->setObjectName(QStringLiteral("stageToolClose"));
    close->setIcon(style()->standardIcon(QStyle::SP_TitleBarCloseButton));
    close->setToolTip(tr("Close (the tool's key again)"));
    close->setAutoRaise(true);
    close->setFocusPolicy(Qt::NoFocus);
    connect(close, &QToolButton::clicked, dock, &QDockWidget::close);
    connect(dock, &QDockWidget::windowTitleChanged, m_title, &QLabel::setText);
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(8, 4, 4, 4);
    row->addWidget(m_title, 1);
    row->addWidget(close);
    setCursor(Qt::SizeAllCursor); // the bar moves the panel
}

void StageToolTitle::attach(QDockWidget* dock)
{
    if (!qobject_cast<StageToolTitle*>(dock->titleBarWidget()))
        dock->setTitleBarWidget(new StageToolTitle(dock));
}

void StageToolTitle::detach(QDockWidget* dock)
{
    if (auto* bar = qobject_cast<StageToolTitle*>(dock->titleBarWidget())) {
        dock->setTitleBarWidget(nullptr);
        bar->deleteLater();
    }
}

void StageToolTitle::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange && m_title) {
        QFont bold = font();
        bold.setBold(true);
        m_title->setFont(bold);
    }
}

} // namespace forcelab
