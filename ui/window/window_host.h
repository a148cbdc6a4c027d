#pragma once
// Owns the main window and swaps it for a new one when the language
// changes: every text of the program is made once, in the language of the
// moment, so a new window in the new language replaces the old one. What
// the class was doing stays: the lesson, the world as it is (balls, clock,
// settings), the selected ball, the window's place and size, the panels'
// layout and the stage view. The undo history and the recorded past start
// afresh from there.
#include <QObject>
#include <QString>

#include <memory>

namespace forcelab {

class MainWindow;

class WindowHost : public QObject {
    Q_OBJECT
public:
    /// Applies the remembered language (unless `languageApplied`: the caller
    /// chose one for this run) and opens `lesson` (MainWindow's meaning).
    explicit WindowHost(const QString& lesson = {}, bool languageApplied = false, QObject* parent = nullptr);
    ~WindowHost() override;

    MainWindow* window() const { return m_window.get(); }

    /// Applies `code` (a shipped language), remembers it and rebuilds the
    /// window in it. False, with nothing changed, for an unknown code.
    bool switchLanguage(const QString& code);

signals:
    /// A new window replaced the old one (which is gone).
    void windowReplaced(MainWindow* window);

private:
    void adopt(MainWindow* window);

    std::unique_ptr<MainWindow> m_window;
};

} // namespace forcelab
