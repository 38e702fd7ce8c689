// AttitudeWidget offscreen: renders into images at a fixed size and camera and checks
// where the coloured axes and the top-face print land, the read-outs in both display
// frames, the no-data state, repaint-on-change only, and the camera controls.
#include "attitude/attitude_widget.h"
#include "model/attitude.h"
#include "../common/test_main.h"

#include <QApplication>
#include <QImage>
#include <QMouseEvent>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <functional>
#include <memory>

using imudesk::model::Euler;
using imudesk::model::Quat;
using imudesk::ui::AttitudeWidget;

namespace {

constexpr int kWidth = 480, kHeight = 380;

Quat axisAngle(double deg, double x, double y, double z)
{
    const double h = 0.5 * deg * imudesk::model::kDegToRad;
    const double n = std::sqrt(x * x + y * y + z * z);
    return Quat{std::cos(h), std::sin(h) * x / n, std::sin(h) * y / n, std::sin(h) * z / n};
}

const Quat kHi91{-0.485922, -0.14982, 0.0380868, 0.860223};

struct Blob {
    int count = 0;
    QPointF centroid;
};

// Pixels of one colour class and their centroid (the read-out panel is left out).
Blob find(const QImage &image, const std::function<bool(const QColor &)> &match)
{
    Blob b;
    double sx = 0, sy = 0;
    for (int y = 0; y < image.height(); ++y) {
        const QRgb *line = reinterpret_cast<const QRgb *>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x) {
            if (x < 170 && y < 120)
                continue; // read-out panel
            if (!match(QColor::fromRgb(line[x])))
                continue;
            ++b.count;
            sx += x;
            sy += y;
        }
    }
    if (b.count > 0)
        b.centroid = QPointF(sx / b.count, sy / b.count);
    return b;
}

bool isX(const QColor &c)
{
    return c.red() > 170 && c.green() < 110 && c.blue() < 110 && c.red() - c.green() > 90;
}
bool isY(const QColor &c)
{
    return c.green() > 120 && c.red() < 110 && c.blue() < 120 && c.green() - c.red() > 60;
}
bool isZ(const QColor &c)
{
    return c.blue() > 170 && c.red() < 110 && c.green() < 160 && c.blue() - c.red() > 90;
}
bool isMark(const QColor &c) // the amber print on the top face
{
    return c.red() > 170 && c.green() > 100 && c.green() < 215 && c.blue() < 90 && c.red() - c.blue() > 120;
}

double dist(const QPointF &a, const QPointF &b)
{
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}

QByteArray str(const QPointF &p)
{
    return "(" + QByteArray::number(p.x(), 'f', 1) + ", " + QByteArray::number(p.y(), 'f', 1) + ")";
}

// The value of one read-out line ("Yaw -122.5°"); NaN when missing.
double readout(const QString &text, const QString &name)
{
    const QRegularExpression re(QStringLiteral("^%1 (-?[0-9]+\\.[0-9])\u00b0$").arg(QRegularExpression::escape(name)),
                                QRegularExpression::MultilineOption);
    const auto m = re.match(text);
    return m.hasMatch() ? m.captured(1).toDouble() : std::nan("");
}

int differingPixels(const QImage &a, const QImage &b)
{
    if (a.size() != b.size())
        return a.width() * a.height();
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (a.pixel(x, y) != b.pixel(x, y))
                ++n;
    return n;
}

// Counts paints (repaint only when something changed).
class CountingWidget : public AttitudeWidget {
public:
    int paints = 0;

protected:
    void paintEvent(QPaintEvent *event) override
    {
        ++paints;
        AttitudeWidget::paintEvent(event);
    }
};

void flushPaints()
{
    for (int i = 0; i < 3; ++i) {
        QCoreApplication::sendPostedEvents();
        QCoreApplication::processEvents();
    }
}

} // namespace

class TestAttitudeWidget : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void identityLayout();
    void upsideDownHidesPrint();
    void yaw90MovesXTowardsY();
    void pitch90PointsYUp();
    void readouts();
    void nedReadouts();
    void nwuModule();
    void assumedWorldFrame();
    void noDataState();
    void repaintsOnlyOnChange();
    void ignoresInvalidQuaternions();
    void cameraControls();
    void screenPositions();
    void savePicture();

private:
    QImage render(const Quat *q, AttitudeWidget::DisplayFrame frame = AttitudeWidget::DisplayFrame::Enu);
    std::unique_ptr<AttitudeWidget> m_widget;
};

void TestAttitudeWidget::init()
{
    m_widget = std::make_unique<AttitudeWidget>();
    m_widget->setLocale(QLocale::c());
    m_widget->resize(kWidth, kHeight);
    m_widget->setCameraAngles(AttitudeWidget::kDefaultAzimuthDeg, AttitudeWidget::kDefaultElevationDeg);
}

QImage TestAttitudeWidget::render(const Quat *q, AttitudeWidget::DisplayFrame frame)
{
    if (q)
        m_widget->setQuaternion(*q);
    m_widget->setDisplayFrame(frame);
    QImage image = m_widget->grab().toImage().convertToFormat(QImage::Format_RGB32);
    if (image.size() != QSize(kWidth, kHeight))
        qWarning("unexpected image size %dx%d", image.width(), image.height());
    return image;
}

void TestAttitudeWidget::identityLayout()
{
    const Quat id;
    const QImage image = render(&id);
    QCOMPARE(image.size(), QSize(kWidth, kHeight));
    const QPointF centre = m_widget->screenPosition({});
    // The model is centred in its own area, beside the read-out panel (never under it).
    QCOMPARE(centre.x(), m_widget->sceneRect().center().x());
    QVERIFY(!m_widget->sceneRect().intersects(m_widget->readoutRect()));
    QVERIFY(m_widget->sceneRect().width() > kWidth / 2.0);

    const Blob mark = find(image, isMark);
    QVERIFY2(mark.count > 100, QByteArray::number(mark.count));
    QVERIFY2(mark.centroid.y() < centre.y() - 5, str(mark.centroid)); // the print is on the upper side

    const Blob x = find(image, isX);
    QVERIFY2(x.count > 50, QByteArray::number(x.count));
    QVERIFY2(x.centroid.x() > centre.x() + 30, str(x.centroid));

    const Blob z = find(image, isZ);
    QVERIFY2(z.count > 30, QByteArray::number(z.count));
    QVERIFY2(z.centroid.y() < centre.y() - 20, str(z.centroid)); // up is up
    QVERIFY2(std::abs(z.centroid.x() - centre.x()) < 10, str(z.centroid));

    const Blob y = find(image, isY);
    QVERIFY2(y.count > 30, QByteArray::number(y.count));
    // Seen from the south-east, north (forward) is further away: higher than east.
    QVERIFY2(y.centroid.y() < x.centroid.y() - 20, str(y.centroid) + " vs " + str(x.centroid));
}

void TestAttitudeWidget::upsideDownHidesPrint()
{
    const Quat flipped = axisAngle(180, 0, 1, 0); // roll 180: top face down
    const QImage image = render(&flipped);
    QCOMPARE(find(image, isMark).count, 0);
    const Blob z = find(image, isZ);
    QVERIFY2(z.count > 0 && z.centroid.y() > m_widget->screenPosition({}).y() + 10, str(z.centroid)); // Z points down
}

void TestAttitudeWidget::yaw90MovesXTowardsY()
{
    const Quat id;
    const QImage before = render(&id);
    const Blob x0 = find(before, isX), y0 = find(before, isY);
    const Quat yaw = axisAngle(90, 0, 0, 1); // counter-clockwise seen from above
    const QImage after = render(&yaw);
    const Blob x1 = find(after, isX), y1 = find(after, isY);
    QVERIFY(x1.count > 30 && y1.count > 30);
    QVERIFY2(dist(x1.centroid, y0.centroid) < 0.5 * dist(x1.centroid, x0.centroid),
             "X " + str(x1.centroid) + " Y was " + str(y0.centroid) + " X was " + str(x0.centroid));
    // Y now points west: to the left of the centre, as seen from the south-east.
    QVERIFY2(y1.centroid.x() < m_widget->sceneRect().center().x() - 20, str(y1.centroid));
}

void TestAttitudeWidget::pitch90PointsYUp()
{
    const Quat pitch = axisAngle(90, 1, 0, 0); // nose up
    const QImage image = render(&pitch);
    const Blob y = find(image, isY);
    QVERIFY2(y.count > 50, QByteArray::number(y.count));
    const QPointF d = y.centroid - m_widget->screenPosition({});
    QVERIFY2(d.y() < -40, str(y.centroid));
    QVERIFY2(std::abs(d.x()) < 0.2 * std::abs(d.y()), str(y.centroid));
    // Z now points south: towards the camera, down in the picture.
    const Blob z = find(image, isZ);
    QVERIFY2(z.count > 0 && z.centroid.y() > m_widget->screenPosition({}).y(), str(z.centroid));
}

void TestAttitudeWidget::readouts()
{
    const Quat id;
    m_widget->setQuaternion(id);
    QString text = m_widget->readoutText();
    QVERIFY2(text.startsWith(QStringLiteral("ENU 3-1-2\n")), qPrintable(text));
    for (const char *name : {"Roll", "Pitch", "Yaw", "Heading"})
        QCOMPARE(readout(text, QString::fromLatin1(name)), 0.0);
    QVERIFY(!text.contains(QStringLiteral("-0.0")));

    m_widget->setQuaternion(kHi91);
    text = m_widget->readoutText();
    QCOMPARE(readout(text, QStringLiteral("Roll")), 13.1);
    QCOMPARE(readout(text, QStringLiteral("Pitch")), 12.2);
    QCOMPARE(readout(text, QStringLiteral("Yaw")), -122.5);
    QCOMPARE(readout(text, QStringLiteral("Heading")), 122.5);
    QCOMPARE(text.count(QLatin1Char('\n')), 4);

    m_widget->setQuaternion(axisAngle(30, 0, 0, 1));
    text = m_widget->readoutText();
    QCOMPARE(readout(text, QStringLiteral("Yaw")), 30.0);
    QCOMPARE(readout(text, QStringLiteral("Heading")), 330.0);

    // Heading never shows 360.0.
    m_widget->setQuaternion(axisAngle(0.01, 0, 0, 1));
    QCOMPARE(readout(m_widget->readoutText(), QStringLiteral("Heading")), 0.0);
}

void TestAttitudeWidget::nedReadouts()
{
    QSignalSpy spy(m_widget.get(), &AttitudeWidget::displayFrameChanged);
    const Quat yaw30 = axisAngle(30, 0, 0, 1);
    const QImage enuImage = render(&yaw30, AttitudeWidget::DisplayFrame::Enu);
    const QString enu = m_widget->readoutText();
    const QImage nedImage = render(&yaw30, AttitudeWidget::DisplayFrame::Ned);
    const QString ned = m_widget->readoutText();
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(0).value<AttitudeWidget::DisplayFrame>(), AttitudeWidget::DisplayFrame::Ned);
    QCOMPARE(m_widget->displayFrame(), AttitudeWidget::DisplayFrame::Ned);
    QVERIFY(enu != ned);
    QVERIFY2(ned.startsWith(QStringLiteral("NED 3-2-1\n")), qPrintable(ned));
    QCOMPARE(readout(ned, QStringLiteral("Yaw")), -30.0);
    QCOMPARE(readout(ned, QStringLiteral("Heading")), 330.0);
    QCOMPARE(readout(ned, QStringLiteral("Roll")), 0.0);
    // Relabelled world axes and read-out: the picture changes, the module does not move.
    QVERIFY(differingPixels(enuImage, nedImage) > 100);
    QVERIFY(dist(find(enuImage, isX).centroid, find(nedImage, isX).centroid) < 1.0);

    // The HI91 frame: roll and pitch agree, yaw mirrored.
    m_widget->setQuaternion(kHi91);
    const QString hi91 = m_widget->readoutText();
    QCOMPARE(readout(hi91, QStringLiteral("Roll")), 13.1);
    QCOMPARE(readout(hi91, QStringLiteral("Pitch")), 12.2);
    QCOMPARE(readout(hi91, QStringLiteral("Yaw")), 122.5);
    QCOMPARE(readout(hi91, QStringLiteral("Heading")), 122.5);

    // A mixed attitude: every value comes from the NED-321 formulas.
    const Quat mixed = imudesk::model::quatFromEnu312(Euler{-20, 35, 50});
    m_widget->setQuaternion(mixed);
    const Euler n = imudesk::model::eulerNed321(imudesk::model::enuToNed(mixed));
    const QString t = m_widget->readoutText();
    QCOMPARE(readout(t, QStringLiteral("Roll")), std::round(n.roll * 10) / 10);
    QCOMPARE(readout(t, QStringLiteral("Pitch")), std::round(n.pitch * 10) / 10);
    QCOMPARE(readout(t, QStringLiteral("Yaw")), std::round(n.yaw * 10) / 10);
    QCOMPARE(readout(t, QStringLiteral("Yaw")), -50.0);

    m_widget->setDisplayFrame(AttitudeWidget::DisplayFrame::Ned); // unchanged: no signal
    QCOMPARE(spy.count(), 1);
    m_widget->setDisplayFrame(AttitudeWidget::DisplayFrame::Enu);
    QCOMPARE(spy.count(), 2);
    QCOMPARE(readout(m_widget->readoutText(), QStringLiteral("Yaw")), 50.0);
}

// A module set to CONFIG IMU COORD 4 sends body -> NWU: the scene shows the same physical
// attitude as the ENU module (the box does not move), the read-out is NWU 3-1-2 (yaw 90 deg
// less) and the heading is unchanged.
void TestAttitudeWidget::nwuModule()
{
    const Quat enuQ = imudesk::model::quatFromEnu312(Euler{10, -5, 35});
    const QImage enuImage = render(&enuQ);
    const QString enuText = m_widget->readoutText();
    const Quat nwuQ = imudesk::model::enuToNwu(enuQ);
    m_widget->setWorldFrame(imudesk::model::WorldFrame::Nwu);
    const QImage nwuImage = render(&nwuQ);
    const QString nwuText = m_widget->readoutText();
    QVERIFY2(nwuText.startsWith(QStringLiteral("NWU 3-1-2\n")), qPrintable(nwuText));
    QCOMPARE(readout(nwuText, QStringLiteral("Yaw")), -55.0);
    QCOMPARE(readout(nwuText, QStringLiteral("Roll")), readout(enuText, QStringLiteral("Roll")));
    QCOMPARE(readout(nwuText, QStringLiteral("Heading")), readout(enuText, QStringLiteral("Heading")));
    QVERIFY(imudesk::model::angleBetweenDeg(m_widget->quaternion(), enuQ) < 1e-6);
    // The module is drawn where it was; only the triad's labels changed.
    // (within 2 px: the round trip through NWU changes the last bits, and with them the
    // antialiasing of the axis where the north label covers it; a 90 deg turn moves it ~100 px)
    QVERIFY(dist(find(enuImage, isX).centroid, find(nwuImage, isX).centroid) < 2.0);
    QVERIFY(dist(find(enuImage, isMark).centroid, find(nwuImage, isMark).centroid) < 2.0);
    QVERIFY(differingPixels(enuImage, nwuImage) > 50);
    // Taken as ENU, the same numbers would turn the module 90 deg.
    m_widget->setWorldFrame(imudesk::model::WorldFrame::Enu);
    QVERIFY(imudesk::model::angleBetweenDeg(m_widget->quaternion(), enuQ) > 80);
    QVERIFY(m_widget->readoutText().startsWith(QStringLiteral("ENU 3-1-2\n")));
    // NED stays the same physical attitude whichever frame the module sends.
    m_widget->setWorldFrame(imudesk::model::WorldFrame::Nwu);
    m_widget->setDisplayFrame(AttitudeWidget::DisplayFrame::Ned);
    QCOMPARE(readout(m_widget->readoutText(), QStringLiteral("Yaw")), -35.0);
}

// A module whose LOG COMCONFIG reply named no COORD: drawn in ENU, the default, with the
// read-out's title marked "(assumed)" and a warning under the scene (amber pixels).
void TestAttitudeWidget::assumedWorldFrame()
{
    const Quat q = imudesk::model::quatFromEnu312(Euler{10, -5, 35});
    const QImage plain = render(&q);
    QVERIFY(m_widget->frameWarning().isEmpty());
    m_widget->setWorldFrame(imudesk::model::WorldFrame::Enu, true);
    QVERIFY(m_widget->worldFrameAssumed());
    const QImage warned = render(&q);
    const QString text = m_widget->readoutText();
    QVERIFY2(text.startsWith(QStringLiteral("ENU 3-1-2 (assumed)\nWorld frame assumed ENU: the module's LOG COMCONFIG "
                                            "reply names no COORD\n")),
             qPrintable(text));
    QCOMPARE(readout(text, QStringLiteral("Yaw")), 35.0); // the numbers are the same
    QVERIFY(m_widget->toolTip().contains(QStringLiteral("names no COORD")));
    int amber = 0;
    for (int y = 0; y < warned.height(); ++y)
        for (int x = 0; x < warned.width(); ++x) {
            const QColor c = warned.pixelColor(x, y);
            amber += c.red() > 150 && c.green() > 60 && c.green() < 130 && c.blue() < 60 ? 1 : 0;
        }
    QVERIFY2(amber > 5, qPrintable(QString::number(amber)));
    QVERIFY(differingPixels(plain, warned) > 20);
    m_widget->setWorldFrame(imudesk::model::WorldFrame::Enu, false);
    QVERIFY(m_widget->readoutText().startsWith(QStringLiteral("ENU 3-1-2\nRoll")));
}

void TestAttitudeWidget::noDataState()
{
    QVERIFY(!m_widget->hasData());
    QCOMPARE(m_widget->readoutText(), QStringLiteral("No attitude yet"));
    const QImage empty = render(nullptr);
    QCOMPARE(find(empty, isX).count, 0); // all grey
    QCOMPARE(find(empty, isMark).count, 0);

    const Quat id;
    const QImage data = render(&id);
    QVERIFY(m_widget->hasData());
    QVERIFY(differingPixels(empty, data) > 500);
    QVERIFY(m_widget->readoutText() != QStringLiteral("No attitude yet"));

    m_widget->clear();
    QVERIFY(!m_widget->hasData());
    QCOMPARE(m_widget->readoutText(), QStringLiteral("No attitude yet"));
    QCOMPARE(differingPixels(empty, render(nullptr)), 0);
}

void TestAttitudeWidget::repaintsOnlyOnChange()
{
    CountingWidget w;
    w.resize(kWidth, kHeight);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QTRY_VERIFY(w.paints > 0);
    flushPaints();

    const Quat q = axisAngle(20, 0, 0, 1);
    w.paints = 0;
    w.setQuaternion(q);
    flushPaints();
    QCOMPARE(w.paints, 1); // the first value repaints

    w.setQuaternion(q);
    w.setQuaternion(q);
    w.setCameraAngles(w.cameraAzimuth(), w.cameraElevation());
    w.setDisplayFrame(w.displayFrame());
    flushPaints();
    QCOMPARE(w.paints, 1); // nothing changed

    w.setQuaternion(axisAngle(21, 0, 0, 1));
    flushPaints();
    QCOMPARE(w.paints, 2);
}

void TestAttitudeWidget::ignoresInvalidQuaternions()
{
    m_widget->setQuaternion(Quat{0, 0, 0, 0});
    QVERIFY(!m_widget->hasData());
    m_widget->setQuaternion(Quat{std::nan(""), 0, 0, 1});
    QVERIFY(!m_widget->hasData());
    m_widget->setQuaternion(Quat{2, 0, 0, 2}); // not normalised: accepted, stored normalised
    QVERIFY(m_widget->hasData());
    QVERIFY(std::abs(m_widget->quaternion().w - std::sqrt(0.5)) < 1e-12);
    QCOMPARE(readout(m_widget->readoutText(), QStringLiteral("Yaw")), 90.0);
    m_widget->setQuaternion(Quat{INFINITY, 0, 0, 0});
    QCOMPARE(readout(m_widget->readoutText(), QStringLiteral("Yaw")), 90.0);
}

void TestAttitudeWidget::cameraControls()
{
    const Quat id;
    const QImage standard = render(&id);
    m_widget->setCameraAngles(-90, 120); // wraps and clamps
    QCOMPARE(m_widget->cameraAzimuth(), 270.0);
    QCOMPARE(m_widget->cameraElevation(), AttitudeWidget::kMaxElevationDeg);
    m_widget->setCameraAngles(200, 20);
    const QImage turned = render(&id);
    QVERIFY(differingPixels(standard, turned) > 500);
    // From south-south-west the east-pointing X axis still points right.
    QVERIFY(find(turned, isX).centroid.x() > kWidth / 2.0 + 30);

    // Drag: right turns the camera clockwise, down raises it.
    m_widget->setCameraAngles(AttitudeWidget::kDefaultAzimuthDeg, AttitudeWidget::kDefaultElevationDeg);
    const QPointF start(200, 200), end(240, 220);
    QMouseEvent press(QEvent::MouseButtonPress, start, m_widget->mapToGlobal(start), Qt::LeftButton, Qt::LeftButton,
                      Qt::NoModifier);
    QApplication::sendEvent(m_widget.get(), &press);
    QMouseEvent move(QEvent::MouseMove, end, m_widget->mapToGlobal(end), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(m_widget.get(), &move);
    QMouseEvent release(QEvent::MouseButtonRelease, end, m_widget->mapToGlobal(end), Qt::LeftButton, Qt::NoButton,
                        Qt::NoModifier);
    QApplication::sendEvent(m_widget.get(), &release);
    QCOMPARE(m_widget->cameraAzimuth(), AttitudeWidget::kDefaultAzimuthDeg + 20.0);
    QCOMPARE(m_widget->cameraElevation(), AttitudeWidget::kDefaultElevationDeg + 10.0);
    // A move without the button does nothing.
    QMouseEvent hover(QEvent::MouseMove, start, m_widget->mapToGlobal(start), Qt::NoButton, Qt::NoButton,
                      Qt::NoModifier);
    QApplication::sendEvent(m_widget.get(), &hover);
    QCOMPARE(m_widget->cameraAzimuth(), AttitudeWidget::kDefaultAzimuthDeg + 20.0);

    QMouseEvent dbl(QEvent::MouseButtonDblClick, end, m_widget->mapToGlobal(end), Qt::LeftButton, Qt::LeftButton,
                    Qt::NoModifier);
    QApplication::sendEvent(m_widget.get(), &dbl);
    QCOMPARE(m_widget->cameraAzimuth(), AttitudeWidget::kDefaultAzimuthDeg);
    QCOMPARE(m_widget->cameraElevation(), AttitudeWidget::kDefaultElevationDeg);
    QCOMPARE(differingPixels(standard, render(&id)), 0);
}

void TestAttitudeWidget::screenPositions()
{
    const QPointF o = m_widget->screenPosition({});
    const QPointF up = m_widget->screenPosition({0, 0, 1});
    const QPointF east = m_widget->screenPosition({1, 0, 0});
    const QPointF north = m_widget->screenPosition({0, 1, 0});
    QVERIFY(std::abs(up.x() - o.x()) < 1e-9 && up.y() < o.y() - 10); // world up is drawn up
    // From the south-east: east comes towards the camera (down-right), north goes away (up-right).
    QVERIFY(east.x() > o.x() && east.y() > o.y());
    QVERIFY(north.x() > o.x() && north.y() < o.y());
    m_widget->setCameraAngles(180, 30); // from the south: east is straight right
    const QPointF east2 = m_widget->screenPosition({1, 0, 0});
    QVERIFY(east2.x() > o.x() + 10 && std::abs(east2.y() - m_widget->screenPosition({}).y()) < 1e-9);
}

void TestAttitudeWidget::savePicture()
{
    // For a human look: the HI91 example attitude, in the build directory.
    const QString dir = QCoreApplication::applicationDirPath();
    QVERIFY(render(&kHi91).save(dir + QStringLiteral("/attitude_widget_hi91.png")));
    const Quat id;
    QVERIFY(render(&id).save(dir + QStringLiteral("/attitude_widget_identity.png")));
    QVERIFY(render(&kHi91, AttitudeWidget::DisplayFrame::Ned).save(dir + QStringLiteral("/attitude_widget_hi91_ned.png")));
    m_widget->clear();
    QVERIFY(render(nullptr).save(dir + QStringLiteral("/attitude_widget_nodata.png")));
}

IMUDESK_TEST_MAIN(TestAttitudeWidget)
#include "tst_attitude_widget.moc"
