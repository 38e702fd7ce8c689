#pragma once
// Help ▸ User guide and Help ▸ Keyboard shortcuts. The guide is docs/USER_GUIDE.md, built
// into the program with the pictures it shows (qrc:/docs/, the guide's own relative paths), a
// table of contents made from its headings beside it (a click shows that section). The guide is
// written in English: in another language the dialog's own words are translated and a line
// above the guide says that its text is not (yet). The shortcuts are read from the window's own
// actions, so the list cannot drift from the menus.
#include <QDialog>
#include <QList>
#include <QString>

class QAction;
class QLabel;
class QTableWidget;
class QTextBrowser;
class QTreeWidget;
class QTreeWidgetItem;

namespace imudesk::ui {

class UserGuideDialog : public QDialog {
    Q_OBJECT
public:
    explicit UserGuideDialog(QWidget *parent = nullptr);
    QTextBrowser *browser() const { return m_browser; }
    QTreeWidget *contents() const { return m_contents; }
    QLabel *languageNote() const { return m_note; }
    // The guide's Markdown, its pictures named as in the source tree (screenshots/...); empty
    // when the resource is missing.
    static QString guideMarkdown();
    // Scrolls the guide to a heading of the table of contents.
    void showSection(const QTreeWidgetItem *item);

protected:
    void changeEvent(QEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void retranslateUi();
    void fillContents();
    // Each picture at most the guide's width (two side by side in a table), never larger than it is.
    void fitPictures();

    QTextBrowser *m_browser = nullptr;
    QTreeWidget *m_contents = nullptr;
    QLabel *m_note = nullptr;
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
