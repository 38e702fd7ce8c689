// HeadingDial offscreen: the needle points at the heading (clockwise from north), values
// wrap, read-outs, the no-data state, and repaints only on visible changes.
#include "attitude/heading_dial.h"
#include "../common/test_main.h"

#include <QImage>
#include <QTest>

#include <cmath>

using imudesk::ui::HeadingDial;

namespace {

QImage render(HeadingDial &d)
{
    QImage img(d.size(), QImage::Format_ARGB32);
    img.fill(Qt::white);
    d.render(&img);
    return img;
}

// Red needle pixels at 45 % of the radius in the given compass direction.
bool needleAt(const QImage &img, const HeadingDial &d, double headingDeg)
{
    const QFontMetrics fm(d.font());
    const double side = std::min(double(d.width()), double(d.height() - (2 * fm.height() + 8))) - 8.0;
    const QPointF c(d.width() / 2.0, 4.0 + side / 2.0);
    const double a = headingDeg * M_PI / 180.0;
    const QPoint at = (c + QPointF(std::sin(a), -std::cos(a)) * side / 2.0 * 0.45).toPoint();
    const QColor px = img.pixelColor(at);
    return px.red() > 180 && px.green() < 90 && px.blue() < 90;
}

class PaintCounter : public QObject {
public:
    int paints = 0;
    bool eventFilter(QObject *, QEvent *e) override
    {
        if (e->type() == QEvent::Paint)
            ++paints;
        return false;
    }
};

} // namespace

class TstHeadingDial : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void needleDirection_data()
    {
        QTest::addColumn<double>("heading");
        QTest::addColumn<double>("shown");
        QTest::newRow("north") << 0.0 << 0.0;
        QTest::newRow("east") << 90.0 << 90.0;
        QTest::newRow("manual 2.4: 313.71") << 313.71 << 313.71;
        QTest::newRow("-90 wraps to west") << -90.0 << 270.0;
        QTest::newRow("540 wraps to south") << 540.0 << 180.0;
    }
    void needleDirection()
    {
        QFETCH(double, heading);
        QFETCH(double, shown);
        HeadingDial d;
        d.resize(260, 300);
        d.setAttitude(heading, -26.8, 33.65);
        QCOMPARE(d.heading(), shown);
        const QImage img = render(d);
        QVERIFY(needleAt(img, d, shown));
        QVERIFY(!needleAt(img, d, shown + 90));
        QVERIFY(!needleAt(img, d, shown + 180)); // the tail is grey
        QCOMPARE(d.headingText(), QStringLiteral("%1°").arg(shown, 0, 'f', 1));
        QCOMPARE(d.tiltText(), QStringLiteral("pitch -26.80°  roll 33.65°"));
    }

    void noData()
    {
        HeadingDial d;
        d.resize(200, 240);
        QVERIFY(!d.hasData());
        QCOMPARE(d.headingText(), QStringLiteral("no data"));
        QVERIFY(d.tiltText().isEmpty());
        for (double h : {0.0, 90.0, 180.0, 270.0})
            QVERIFY(!needleAt(render(d), d, h));
        d.setAttitude(10, 0, 0);
        QVERIFY(d.hasData());
        d.setAttitude(std::nan(""), 0, 0); // ignored
        QCOMPARE(d.heading(), 10.0);
        d.clear();
        QVERIFY(!d.hasData());
    }

    void repaintsOnlyOnChange()
    {
        HeadingDial d;
        d.resize(200, 240);
        PaintCounter counter;
        d.installEventFilter(&counter);
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        d.setAttitude(100.0, 1.0, 2.0);
        QTRY_VERIFY(counter.paints > 0);
        QTest::qWait(50); // duration under test: 50 ms without a change, the baseline of the count
        const int before = counter.paints;
        d.setAttitude(100.01, 1.001, 2.001); // below the shown resolution
        QTest::qWait(50); // duration under test: 50 ms after a change too small to show, no paint
        QCOMPARE(counter.paints, before);
        d.setAttitude(101.0, 1.0, 2.0);
        QTRY_VERIFY(counter.paints > before);
    }
};

IMUDESK_TEST_MAIN(TstHeadingDial)
#include "tst_heading_dial.moc"
