#pragma once
// The layout test's eye (issue 14), shared by every window that is judged by it (tst_layout,
// tst_station_view): every visible widget inside the window and no label cut short.
#include <QAbstractScrollArea>
#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QFontMetrics>
#include <QGraphicsView>
#include <QLabel>
#include <QMainWindow>
#include <QScrollArea>
#include <QStringList>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextDocumentFragment>
#include <QWidget>

#include <algorithm>

namespace imudesk::test::layout {

struct Options {
    // Widgets inside a QScrollArea's viewport are checked too (a grid that must fit without
    // scrolling); those inside a list's, an editor's or a graphics view's never are.
    bool checkScrollAreas = false;
    // A label's lines must also fit its height (labels that set several lines themselves).
    bool checkLineHeights = false;
};

inline bool insideScrolledContent(const QWidget *w, const QWidget *top, const Options &o = {})
{
    for (const QWidget *p = w->parentWidget(); p && p != top; p = p->parentWidget()) {
        if (qobject_cast<const QGraphicsView *>(p))
            return true;
        if (const auto *area = qobject_cast<const QAbstractScrollArea *>(p->parentWidget()))
            if (area->viewport() == p && !(o.checkScrollAreas && qobject_cast<const QScrollArea *>(area)))
                return true;
    }
    return false;
}

// Qt parks what is behind a tab (a dock that is not the current tab, a spare tab bar) outside
// its main window instead of hiding it: not something the user can see, so not a problem.
inline bool parkedByQt(const QWidget *w)
{
    for (const QWidget *p = w; p; p = p->parentWidget()) {
        const auto *main = qobject_cast<const QMainWindow *>(p->parentWidget());
        if (!main)
            continue;
        const bool dock = qobject_cast<const QDockWidget *>(p) && !p->isWindow();
        if ((dock || qobject_cast<const QTabBar *>(p)) && !main->rect().intersects(p->geometry()))
            return true;
    }
    return false;
}

// Every visible widget inside `top`, and no label cut short: one line per problem.
inline QStringList cutOrOutside(QWidget &top, const Options &o = {})
{
    QStringList problems;
    const QRect window = top.rect().adjusted(-1, -1, 1, 1);
    for (QWidget *child : top.findChildren<QWidget *>()) {
        // A floating dock is a window of its own: judged on its own (cutOrOutside(dock)).
        if (!child->isVisible() || child->isWindow() || child->window() != top.window()
            || insideScrolledContent(child, &top, o) || parkedByQt(child))
            continue;
        const QRect r(child->mapTo(&top, QPoint(0, 0)), child->size());
        if (!window.contains(r))
            problems << QStringLiteral("%1 \"%2\" outside the window: %3,%4 %5x%6")
                            .arg(QString::fromLatin1(child->metaObject()->className()), child->objectName())
                            .arg(r.x())
                            .arg(r.y())
                            .arg(r.width())
                            .arg(r.height());
        const auto *label = qobject_cast<QLabel *>(child);
        if (!label || label->text().isEmpty())
            continue;
        if (label->wordWrap()) {
            // A wrapped text needs its height for this width.
            const int needed = label->heightForWidth(label->width());
            if (needed > label->height() + 2)
                problems << QStringLiteral("wrapped label \"%1\" cut: needs %2 px high, has %3")
                                .arg(label->text().left(60))
                                .arg(needed)
                                .arg(label->height());
            continue;
        }
        const QString text = Qt::mightBeRichText(label->text())
            ? QTextDocumentFragment::fromHtml(label->text()).toPlainText()
            : QString(label->text()).remove(QLatin1Char('&'));
        const QStringList lines = text.split(QLatin1Char('\n'));
        int needed = 0;
        for (const QString &line : lines)
            needed = std::max(needed, label->fontMetrics().horizontalAdvance(line));
        if (needed > label->contentsRect().width() + 1)
            problems << QStringLiteral("label \"%1\" cut: needs %2 px, has %3").arg(text).arg(needed).arg(
                            label->contentsRect().width());
        if (!o.checkLineHeights)
            continue;
        // As QLabel sets lines: one font height, and a line spacing more for each further line.
        const int high = label->fontMetrics().height() + int(lines.size() - 1) * label->fontMetrics().lineSpacing();
        if (high > label->contentsRect().height() + 2)
            problems << QStringLiteral("label \"%1\" cut: needs %2 px high, has %3")
                            .arg(text)
                            .arg(high)
                            .arg(label->contentsRect().height());
    }
    return problems;
}

// Waits, at most timeoutMs, until the layouts have caught up: every widget of `top` keeps its
// place and visibility over three looks in a row, ~10 ms apart.
inline bool layoutSettled(const QWidget &top, int timeoutMs = 5000)
{
    const auto places = [&top] {
        QList<QRect> out;
        for (const QWidget *child : top.findChildren<QWidget *>())
            out << (child->isVisible() ? QRect(child->mapTo(&top, QPoint(0, 0)), child->size()) : QRect());
        return out;
    };
    QList<QRect> last;
    int same = 0;
    return imudesk::test::waitFor(
        [&] {
            QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
            QList<QRect> now = places();
            same = now == last ? same + 1 : 0;
            last = std::move(now);
            return same >= 3;
        },
        timeoutMs);
}

// A layout test's rows: every size in English and in Simplified Chinese (columns "size" and
// "language").
inline void addSizesAndLanguages(std::initializer_list<QSize> sizes)
{
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("language");
    for (const QString &lang : {QStringLiteral("en"), QStringLiteral("zh_CN")})
        for (const QSize &size : sizes)
            QTest::addRow("%dx%d %s", size.width(), size.height(), qPrintable(lang)) << size << lang;
}

// Points the offscreen platform at one screen of this size in pixels (its default is 800x600).
// The configuration file goes into dir, which must outlive the application; false when it
// cannot be written.
inline bool useOffscreenScreen(const QTemporaryDir &dir, QSize screen, const QString &name)
{
    const QString config = dir.filePath(QStringLiteral("screen.json"));
    QFile file(config);
    if (!file.open(QIODevice::WriteOnly))
        return false;
    file.write(QStringLiteral("{\"screens\": [{\"name\": \"%1\", \"x\": 0, \"y\": 0, \"width\": %2, "
                              "\"height\": %3, \"logicalDpi\": 96, \"logicalBaseDpi\": 96, \"dpr\": 1}]}")
                   .arg(name)
                   .arg(screen.width())
                   .arg(screen.height())
                   .toLatin1());
    file.close();
    qputenv("QT_QPA_PLATFORM", "offscreen:configfile=" + config.toLocal8Bit());
    return true;
}

// Runs a window's test object on an offscreen screen of this size, with settings of its own
// (organisation ImuDeskTest, application name).
template <class TestObject>
int runOnOffscreenScreen(int argc, char **argv, QSize screen, const QString &name)
{
    QTemporaryDir dir;
    if (!useOffscreenScreen(dir, screen, name))
        return 2;
    QApplication app(argc, argv);
    app.setOrganizationName(QStringLiteral("ImuDeskTest"));
    app.setApplicationName(name);
    TestObject test;
    return QTest::qExec(&test, argc, argv);
}

} // namespace imudesk::test::layout
