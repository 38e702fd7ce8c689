#pragma once
// Help ▸ User guide and Help ▸ Keyboard shortcuts. The guide is docs/USER_GUIDE.md, built
// into the program (its pictures of the window are left out: the window is beside it). The
// shortcuts are read from the window's own actions, so the list cannot drift from the menus.
#include <QDialog>
#include <QList>
#include <QString>

class QAction;
class QTableWidget;
class QTextBrowser;

namespace imudesk::ui {

class UserGuideDialog : public QDialog {
    Q_OBJECT
public:
    explicit UserGuideDialog(QWidget *parent = nullptr);
    QTextBrowser *browser() const { return m_browser; }
    // The guide's Markdown without its screenshots; empty when the resource is missing.
    static QString guideMarkdown();

private:
    QTextBrowser *m_browser = nullptr;
};

class ShortcutsDialog : public QDialog {
    Q_OBJECT
public:
    // One row per action that has a shortcut: what it does (its menu text) and the keys.
    ShortcutsDialog(const QList<QAction *> &actions, QWidget *parent = nullptr);
    QTableWidget *table() const { return m_table; }

private:
    QTableWidget *m_table = nullptr;
};

} // namespace imudesk::ui
