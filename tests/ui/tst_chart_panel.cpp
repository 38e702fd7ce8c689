// ChartPanel, ChartView and ComparisonChart offscreen: decimated series, hidden axes,
// pause, PNG export, crosshair read-out, gaps, translation hooks, settings.
#include "charts/chart_panel.h"
#include "charts/chart_settings.h"
#include "charts/chart_view.h"
#include "charts/comparison_chart.h"
#include "charts/plot_canvas.h"
#include "plot/axis_scaling.h"
#include "plot/minmax_decimator.h"
#include "../common/test_main.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QLineSeries>
#include <QMainWindow>
#include <QMouseEvent>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QAction>
#include <QLabel>
#include <QLegendMarker>
#include <QDoubleSpinBox>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QTranslator>
#include <QValueAxis>

#include <cmath>

using imudesk::model::Sample;
using imudesk::plot::Channel;
using imudesk::plot::ChannelHistory;
using imudesk::plot::MinMaxDecimator;
using imudesk::plot::TimeAxis;
using imudesk::ui::ChartKind;
using imudesk::ui::ChartPanel;
using imudesk::ui::ChartSettings;
using imudesk::ui::ChartView;
using imudesk::ui::PlotCanvas;
using imudesk::ui::ComparisonChart;
namespace model = imudesk::model;

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr uint32_t kHi91Fields = model::FieldAcc | model::FieldGyr | model::FieldMag | model::FieldEuler |
                                 model::FieldQuat | model::FieldPressure | model::FieldTemperature |
                                 model::FieldDeviceTime;
constexpr int64_t kHostStartNs = 7'000'000'000;
constexpr double kDeviceStartMs = 1000.0;

// Sample i of a 1 kHz stream: acc x = sin(2 pi t), acc y = cos(2 pi t), acc z = 1 G, t = i ms.
Sample sineSample(int i, uint32_t fields = kHi91Fields, double deviceMs = -1.0)
{
    const double t = i / 1000.0;
    Sample s;
    s.source = "HI91";
    s.fields = fields;
    s.hostTimeNs = kHostStartNs + int64_t(i) * 1'000'000;
    s.deviceTimeMs = deviceMs >= 0.0 ? deviceMs : kDeviceStartMs + i;
    s.acc = {std::sin(kTwoPi * t), std::cos(kTwoPi * t), 1.0};
    s.gyr = {10.0, -10.0, 0.5};
    s.mag = {20.0, -5.0, 40.0};
    s.roll = 1.0;
    s.pitch = -2.0;
    s.yaw = 90.0 + t;
    s.quat = {1.0, 0.0, 0.0, 0.0};
    s.pressurePa = 101325.0;
    s.temperatureC = 25.0;
    return s;
}

// Feeds samples [from, to) the way a workspace does: 33 ms of samples per tick, refresh after each.
void feed(ChartPanel &panel, int from, int to, bool refreshEachTick = true, uint32_t fields = kHi91Fields)
{
    std::vector<Sample> batch;
    for (int i = from; i < to; ++i) {
        batch.push_back(sineSample(i, fields));
        if (batch.size() == 33 || i + 1 == to) {
            panel.appendSamples(batch);
            batch.clear();
            if (refreshEachTick)
                panel.refresh();
        }
    }
}

// Returns a translation for every source text, so a test can see tr() at work.
class MarkingTranslator : public QTranslator {
public:
    bool isEmpty() const override { return false; }
    QString translate(const char *, const char *sourceText, const char * = nullptr, int = -1) const override
    {
        return QStringLiteral("«") + QString::fromUtf8(sourceText) + QStringLiteral("»");
    }
};

qsizetype breaksIn(const QList<QPointF> &points)
{
    return std::count_if(points.begin(), points.end(), MinMaxDecimator::isBreak);
}

} // namespace

class TstChartPanel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // The Euler chart's legend lists magnetic roll only once a device sends it (an HEC495's
    // read-all record): beside a module's angles it would name a line that never comes.
    void legendListsWhatTheDeviceSends()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        ChartView *euler = panel.chart(ChartKind::Euler);
        QCOMPARE(euler->canvas()->lineCount(), 4); // roll, pitch, yaw, magnetic roll
        panel.refresh();
        for (int line = 0; line < 4; ++line)
            QVERIFY(euler->canvas()->isLineListed(line)); // nothing yet: every quantity it can show
        feed(panel, 0, 500);
        QVERIFY(euler->canvas()->isLineListed(0) && euler->canvas()->isLineListed(2));
        QVERIFY(!euler->canvas()->isLineListed(3));
        QVERIFY(euler->canvas()->legendEntryRect(3).isEmpty());
        QVERIFY(!euler->canvas()->legendEntryRect(2).isEmpty());
        feed(panel, 500, 600, true, kHi91Fields | model::FieldMagRoll);
        QVERIFY(euler->canvas()->isLineListed(3));
        QVERIFY(!euler->canvas()->legendEntryRect(3).isEmpty());
    }
    void seriesAreDecimated()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        feed(panel, 0, 10000); // 1 kHz for 10 s
        panel.refresh();
        QCOMPARE(panel.history().size(), size_t(10000));

        ChartView *acc = panel.chart(ChartKind::Accelerometer);
        const int width = acc->drawnWidthPx(); // the plot area's width when it was drawn (two charts a row)
        QVERIFY2(width > 350 && std::abs(width - acc->plotWidthPx()) < 20, qPrintable(QString::number(width)));
        const QList<QPointF> &xPoints = acc->linePoints(Channel::AccX);
        QVERIFY(acc->canvas()->isLineVisible(0));
        // Dense data: every pixel column has points, at most 4 of them.
        QVERIFY2(xPoints.size() >= width && xPoints.size() <= 4 * width,
                 qPrintable(QStringLiteral("%1 points for %2 px").arg(xPoints.size()).arg(width)));
        QVERIFY(xPoints.size() <= 4 * acc->width());
        QCOMPARE(breaksIn(xPoints), qsizetype(0));
        // The sine's extremes survive decimation; the window is the newest 10 s of the device clock.
        double lo = 1e9, hi = -1e9;
        for (const QPointF &p : xPoints) {
            lo = std::min(lo, p.y());
            hi = std::max(hi, p.y());
        }
        QVERIFY(hi > 0.9999 && lo < -0.9999);
        // The window ends at the newest sample, give or take the pixel column a chart waits for
        // before it moves again.
        const double newest = (kDeviceStartMs + 9999) / 1000.0;
        const double column = 10.0 / width;
        QVERIFY2(acc->canvas()->xMax() <= newest && acc->canvas()->xMax() > newest - column,
                 qPrintable(QString::number(acc->canvas()->xMax(), 'f', 4)));
        QCOMPARE(acc->canvas()->xMax() - acc->canvas()->xMin(), 10.0);
        QVERIFY(acc->canvas()->yMin() < -1.0 && acc->canvas()->yMax() > 1.0); // autoscale holds the data
        QVERIFY(panel.refreshCount() > 0);

        // The lines are really on screen: the plot area holds pixels of each axis colour, at
        // the places the points map to (the sine's top near the top of the autoscaled area).
        const QImage image = acc->canvas()->grab().toImage();
        const QRect area = acc->canvas()->plotArea().toRect();
        QVERIFY(!area.isEmpty());
        for (Channel c : {Channel::AccX, Channel::AccY, Channel::AccZ}) {
            const QRgb wanted = ChartView::colour(c).rgb();
            int hits = 0;
            for (int y = area.top(); y <= area.bottom(); ++y)
                for (int x = area.left(); x <= area.right(); ++x)
                    hits += (image.pixel(x, y) & 0xffffff) == (wanted & 0xffffff);
            QVERIFY2(hits > area.width() / 2, qPrintable(QStringLiteral("%1 pixels of axis %2").arg(hits).arg(int(c))));
        }
        const QPointF top = acc->canvas()->toPixel(QPointF(acc->canvas()->xMin(), acc->canvas()->yMax()));
        QVERIFY(std::abs(top.x() - area.left()) <= 1.0 && std::abs(top.y() - area.top()) <= 1.0);
    }

    void refreshesOnlyVisibleChangedCharts()
    {
        ChartPanel panel;
        panel.resize(1200, 700);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        feed(panel, 0, 2000, false);
        panel.refresh();
        ChartView *acc = panel.chart(ChartKind::Accelerometer);
        ChartView *temperature = panel.chart(ChartKind::Temperature);
        QCOMPARE(acc->redrawCount(), 1);
        QCOMPARE(temperature->redrawCount(), 0); // not chosen: not on screen
        const int count = panel.refreshCount();
        QVERIFY(count >= 1 && count < imudesk::ui::kChartKindCount);

        // Nothing new: nothing redrawn.
        panel.refresh();
        QCOMPARE(panel.refreshCount(), count);
        // Less than a pixel column of news (1 ms; a 10 s window has ~9 ms columns): not yet.
        panel.appendSamples({sineSample(2000)});
        panel.refresh();
        QCOMPARE(panel.refreshCount(), count);
        // 100 ms more: redrawn.
        feed(panel, 2001, 2100, false);
        panel.refresh();
        QCOMPARE(panel.refreshCount(), 2 * count);

        // Chosen in the toolbar's chart menu, the temperature chart joins the grid and catches up.
        QVERIFY(temperature->isHidden());
        panel.chartAction(ChartKind::Temperature)->trigger();
        QCoreApplication::processEvents();
        QVERIFY(!temperature->isHidden());
        panel.refresh();
        QCOMPARE(temperature->redrawCount(), 1);
        const qsizetype points = temperature->linePoints(Channel::Temperature).size();
        QVERIFY(points > 0 && points <= 4 * temperature->drawnWidthPx());

        // A hidden panel draws nothing.
        panel.hide();
        const int hiddenCount = panel.refreshCount();
        feed(panel, 2100, 4000);
        QCOMPARE(panel.refreshCount(), hiddenCount);
    }

    void hidingAnAxisHidesItsSeries()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        feed(panel, 0, 3000);
        ChartView *acc = panel.chart(ChartKind::Accelerometer);
        QVERIFY(acc->linePoints(Channel::AccY).size() > 0);
        QSignalSpy changed(&panel, &ChartPanel::settingsChanged);
        const QRectF entry = acc->canvas()->legendEntryRect(1);
        QVERIFY(!entry.isEmpty());
        QTest::mouseClick(acc->canvas(), Qt::LeftButton, {}, entry.center().toPoint()); // a click on the legend entry
        QCOMPARE(changed.count(), 1);
        QVERIFY(!acc->isChannelVisible(Channel::AccY));
        panel.refresh();
        QVERIFY(!acc->canvas()->isLineVisible(1));
        QCOMPARE(acc->linePoints(Channel::AccY).size(), qsizetype(0));
        QVERIFY(acc->canvas()->isLineVisible(0));
        QVERIFY(acc->linePoints(Channel::AccX).size() > 0);
        QVERIFY(panel.settings().isHidden(Channel::AccY));
        QVERIFY(!panel.settings().isHidden(Channel::AccX));
        // The hidden axis keeps its legend entry (dimmed), to be switched back on.
        QCOMPARE(acc->canvas()->legendEntryRect(1), entry);
        // Shown again: drawn again.
        QTest::mouseClick(acc->canvas(), Qt::LeftButton, {}, entry.center().toPoint());
        panel.refresh();
        QVERIFY(acc->canvas()->isLineVisible(1));
        QVERIFY(acc->linePoints(Channel::AccY).size() > 0);
    }

    void pauseFreezesTheXRange()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        feed(panel, 0, 5000);
        ChartView *acc = panel.chart(ChartKind::Accelerometer);
        acc->setPaused(true);
        QVERIFY(acc->isPaused());
        panel.refresh();
        const double min = acc->canvas()->xMin(), max = acc->canvas()->xMax();
        const QList<QPointF> frozen = acc->linePoints(Channel::AccX);
        feed(panel, 5000, 8000); // recording goes on
        QCOMPARE(panel.history().size(), size_t(8000));
        QCOMPARE(acc->canvas()->xMin(), min);
        QCOMPARE(acc->canvas()->xMax(), max);
        QCOMPARE(acc->linePoints(Channel::AccX).size(), frozen.size());
        // The other charts kept moving.
        QCOMPARE(panel.chart(ChartKind::Gyroscope)->canvas()->xMax(), (kDeviceStartMs + 7999) / 1000.0);
        // A longer window while paused keeps the right edge.
        acc->setWindowSeconds(30);
        panel.refresh();
        QCOMPARE(acc->canvas()->xMax(), max);
        QCOMPARE(acc->canvas()->xMin(), max - 30.0);
        // Resumed: back to the newest data.
        acc->setPaused(false);
        QVERIFY(!acc->isPaused());
        panel.refresh();
        QCOMPARE(acc->canvas()->xMax(), (kDeviceStartMs + 7999) / 1000.0);

        // The toolbar's Pause freezes every chart at once, and Run lets them all go on.
        panel.pauseAction()->trigger();
        QVERIFY(panel.isPaused());
        for (ChartKind k : {ChartKind::Accelerometer, ChartKind::Gyroscope, ChartKind::Euler})
            QVERIFY(panel.chart(k)->isPaused());
        panel.refresh();
        const double frozenMax = panel.chart(ChartKind::Gyroscope)->canvas()->xMax();
        feed(panel, 8000, 9000);
        QCOMPARE(panel.chart(ChartKind::Gyroscope)->canvas()->xMax(), frozenMax);
        panel.pauseAction()->trigger();
        QVERIFY(!panel.isPaused() && !acc->isPaused());
        panel.refresh();
        QCOMPARE(panel.chart(ChartKind::Gyroscope)->canvas()->xMax(), (kDeviceStartMs + 8999) / 1000.0);
        // One window for all charts from the toolbar.
        panel.windowCombo()->setCurrentIndex(panel.windowCombo()->findData(30.0));
        for (ChartKind k : {ChartKind::Accelerometer, ChartKind::Gyroscope, ChartKind::Magnetometer})
            QCOMPARE(panel.chart(k)->windowSeconds(), 30.0);
    }

    void savePngWritesTheChart()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        feed(panel, 0, 3000);
        ChartView *acc = panel.chart(ChartKind::Accelerometer);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("acc.png"));
        QString error;
        QVERIFY2(acc->savePng(path, &error), qPrintable(error));
        QVERIFY(QFileInfo(path).size() > 0);
        QImage image(path);
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), acc->canvas()->size() * acc->canvas()->devicePixelRatio());
        // Not all one colour: the chart is in it.
        QVERIFY(image.pixel(image.width() / 2, image.height() / 2) != image.pixel(2, 2) ||
                image.pixel(image.width() / 3, image.height() / 3) != image.pixel(2, 2));

        const QString bad = dir.filePath(QStringLiteral("no/such/dir/acc.png"));
        QVERIFY(!acc->savePng(bad, &error));
        QVERIFY2(error.contains(QStringLiteral("acc.png")), qPrintable(error));
        QVERIFY(!QFileInfo::exists(bad));
    }

    // "Save all as PNG…" through its file dialog: the file is written and the window's status
    // bar says in which folder and how many charts it holds (no box to click away).
    void saveAllSaysWhere()
    {
        QMainWindow window;
        auto *panel = new ChartPanel(&window);
        window.setCentralWidget(panel);
        window.resize(1200, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        feed(*panel, 0, 3000);
        int shown = 0;
        for (int k = 0; k < imudesk::ui::kChartKindCount; ++k)
            shown += panel->chart(ChartKind(k))->isVisible() ? 1 : 0;
        QVERIFY(shown > 1);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("all.png"));
        // What the toolbar's action does once its file dialog has a name (the dialog itself is
        // Qt's): save, then say where.
        QSignalSpy saved(panel, &ChartPanel::pngSaved);
        QString error;
        QVERIFY2(panel->saveAllPngAndSay(path, &error), qPrintable(error));
        QVERIFY(QFileInfo(path).size() > 0);
        QTRY_COMPARE_WITH_TIMEOUT(saved.count(), 1, 2000);
        const QString message = window.statusBar()->currentMessage();
        QVERIFY2(message.contains(QDir::toNativeSeparators(dir.path())), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("all.png")), qPrintable(message));
        QVERIFY2(message.contains(QString::number(shown)), qPrintable(message));
        QCOMPARE(saved.at(0).at(0).toString(), path);
    }

    void crosshairReadsTheValues()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        feed(panel, 0, 10000);
        ChartView *acc = panel.chart(ChartKind::Accelerometer);
        QVERIFY(!acc->isCrosshairVisible());
        QVERIFY(acc->readoutLabel()->isHidden()); // until the toolbar's cursor is on
        // x = 5.125 s on the device clock is sample 4125: phase 2 pi 4.125, sin = cos = 0.7071.
        acc->showCrosshairAt(5.125);
        QVERIFY(acc->isCrosshairVisible());
        QCOMPARE(acc->crosshairText(), QStringLiteral("t = 5.125 s   X 0.7071 G   Y 0.7071 G   Z 1.0000 G"));
        // Hidden axes drop out of the read-out.
        acc->setChannelVisible(Channel::AccZ, false);
        QCOMPARE(acc->crosshairText(), QStringLiteral("t = 5.125 s   X 0.7071 G   Y 0.7071 G"));
        // Other units.
        ChartView *gyr = panel.chart(ChartKind::Gyroscope);
        QCOMPARE(gyr->readoutAt(3.0), QStringLiteral("t = 3.000 s   X 10.000 deg/s   Y -10.000 deg/s   Z 0.500 deg/s"));
        // Outside the data: no value.
        QVERIFY(gyr->readoutAt(50.0).contains(QStringLiteral("X \u2014 deg/s")));

        // With the toolbar's cursor on, the mouse drives it over the plot area, every chart's
        // at the same time, and leaving hides it.
        panel.cursorAction()->trigger();
        QVERIFY(!acc->readoutLabel()->isHidden());
        const QRectF plot = acc->canvas()->plotArea();
        const QPoint inside = plot.center().toPoint();
        QMouseEvent move(QEvent::MouseMove, QPointF(inside), acc->canvas()->mapToGlobal(QPointF(inside)),
                         Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        acc->hideCrosshair();
        QCoreApplication::sendEvent(acc->canvas(), &move);
        QVERIFY(acc->isCrosshairVisible());
        const double middle = 0.5 * (acc->canvas()->xMin() + acc->canvas()->xMax());
        const auto match = QRegularExpression(QStringLiteral("^t = ([0-9.]+) s")).match(acc->crosshairText());
        QVERIFY2(match.hasMatch(), qPrintable(acc->crosshairText()));
        const double pixelTime = (acc->canvas()->xMax() - acc->canvas()->xMin()) / plot.width();
        QVERIFY2(std::abs(match.captured(1).toDouble() - middle) <= 2 * pixelTime, qPrintable(acc->crosshairText()));
        QVERIFY(gyr->isCrosshairVisible());
        QCOMPARE(gyr->crosshairText().section(QStringLiteral("   "), 0, 0), match.captured(0));
        QVERIFY(gyr->crosshairText().contains(QStringLiteral("deg/s")));
        QEvent leave(QEvent::Leave);
        QCoreApplication::sendEvent(acc->canvas(), &leave);
        QVERIFY(!acc->isCrosshairVisible() && !gyr->isCrosshairVisible());
        // Cursor off: the read-out lines go, the mouse moves no crosshair.
        panel.cursorAction()->trigger();
        QVERIFY(acc->readoutLabel()->isHidden());
        QCoreApplication::sendEvent(acc->canvas(), &move);
        QVERIFY(!acc->isCrosshairVisible());
    }

    void canvasTicksLabelsAndMapping()
    {
        PlotCanvas canvas;
        canvas.resize(600, 300);
        canvas.setTitle(QStringLiteral("Accelerometer"));
        canvas.setAxisTitles(QStringLiteral("Device time (s)"), QStringLiteral("Acceleration (G)"));
        const int x = canvas.addLine(Qt::red, QStringLiteral("X"));
        canvas.addLine(Qt::green, QStringLiteral("Y"));
        canvas.setXRange(12.3, 22.3, 2.0, 0);
        canvas.setYRange(-0.25, 0.75, 0.25, 2);
        // Ticks on multiples of the step, inside the range; no "-0.00".
        QCOMPARE(canvas.xTickLabels(), QStringList({QStringLiteral("14"), QStringLiteral("16"), QStringLiteral("18"),
                                                    QStringLiteral("20"), QStringLiteral("22")}));
        QCOMPARE(canvas.yTickLabels(), QStringList({QStringLiteral("-0.25"), QStringLiteral("0.00"),
                                                    QStringLiteral("0.25"), QStringLiteral("0.50"), QStringLiteral("0.75")}));
        canvas.setYRange(-1e-12, 1.0, 0.5, 1);
        QCOMPARE(canvas.yTickLabels().front(), QStringLiteral("0.0"));
        // Values and pixels map both ways over the plot area.
        const QRectF area = canvas.plotArea();
        QVERIFY(area.width() > 300 && area.height() > 150);
        QVERIFY(canvas.rect().contains(area.toRect()));
        QCOMPARE(canvas.toPixel(QPointF(12.3, 1.0)), area.topLeft());
        const QPointF back = canvas.toValue(canvas.toPixel(QPointF(17.0, 0.4)));
        QVERIFY(std::abs(back.x() - 17.0) < 1e-9 && std::abs(back.y() - 0.4) < 1e-9);
        // A wider value label widens the margin; a narrower one keeps it (the plot does not jitter).
        QSignalSpy moved(&canvas, &PlotCanvas::plotAreaChanged);
        canvas.setYRange(-2000.0, 2000.0, 1000.0, 0);
        QCOMPARE(moved.count(), 1);
        const QRectF wide = canvas.plotArea();
        QVERIFY(wide.left() > area.left());
        canvas.setYRange(-1.0, 1.0, 0.5, 1);
        QCOMPARE(canvas.plotArea(), wide);
        // The legend's entries sit right of the plot; a click on one asks to switch its line.
        const QRectF entry = canvas.legendEntryRect(x);
        QVERIFY(entry.left() > wide.right() && canvas.rect().contains(entry.toRect()));
        QSignalSpy clicked(&canvas, &PlotCanvas::legendClicked);
        QTest::mouseClick(&canvas, Qt::LeftButton, {}, entry.center().toPoint());
        QCOMPARE(clicked.count(), 1);
        QCOMPARE(clicked.front().front().toInt(), x);
        canvas.setLegendVisible(false);
        QVERIFY(canvas.legendEntryRect(x).isEmpty());
        QVERIFY(canvas.plotArea().right() > wide.right());
        // The crosshair is drawn only inside the range.
        canvas.setCrosshair(15.0);
        QVERIFY(canvas.isCrosshairDrawn());
        canvas.setCrosshair(40.0);
        QVERIFY(!canvas.isCrosshairDrawn());
        // The lines are painted where the points map to; a NaN breaks a line.
        canvas.setPoints(x, {QPointF(13.0, 0.0), QPointF(21.0, 0.0)});
        canvas.setCrosshair(std::nullopt);
        const QImage image = canvas.grab().toImage();
        const QPoint mid = canvas.toPixel(QPointF(17.0, 0.0)).toPoint();
        QCOMPARE(image.pixel(mid) & 0xffffff, QColor(Qt::red).rgb() & 0xffffff);
        canvas.setPoints(x, {QPointF(13.0, 0.0), QPointF(qQNaN(), qQNaN()), QPointF(21.0, 0.0)});
        const QImage broken = canvas.grab().toImage();
        QVERIFY((broken.pixel(mid) & 0xffffff) != (QColor(Qt::red).rgb() & 0xffffff));
    }

    void gapsAndRestartsBreakTheLine()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        // 2 s, then 300 ms of lost frames (device clock jumps), then 2 s, then the device reboots.
        std::vector<Sample> batch;
        for (int i = 0; i < 2000; ++i)
            batch.push_back(sineSample(i));
        for (int i = 2000; i < 4000; ++i)
            batch.push_back(sineSample(i, kHi91Fields, kDeviceStartMs + i + 300));
        panel.appendSamples(batch);
        panel.refresh();
        ChartView *acc = panel.chart(ChartKind::Accelerometer);
        QCOMPARE(breaksIn(acc->linePoints(Channel::AccX)), qsizetype(1));
        // In the gap there is no value to read.
        const double inGap = (kDeviceStartMs + 2000 + 150) / 1000.0;
        QVERIFY(acc->readoutAt(inGap).contains(QStringLiteral("X \u2014 G")));
        // On the host clock the samples arrived without a pause, but the device's gap still breaks the line.
        panel.setTimeAxis(TimeAxis::Host);
        panel.refresh();
        // (1 ms of host time between the two sides is narrower than a pixel column: joined or broken.)
        QVERIFY(breaksIn(acc->linePoints(Channel::AccX)) <= 1);
        QCOMPARE(acc->canvas()->xMax(), 3.999);

        panel.setTimeAxis(TimeAxis::Device);
        batch.clear();
        for (int i = 4500; i < 5500; ++i) {
            // Rebooted: 500 ms without frames, then the device clock restarts at 5 ms.
            batch.push_back(sineSample(i, kHi91Fields, 5.0 + (i - 4500)));
        }
        panel.appendSamples(batch);
        panel.refresh();
        QCOMPARE(panel.history().segmentCount(), 2);
        QCOMPARE(breaksIn(acc->linePoints(Channel::AccX)), qsizetype(2));
        // The newest data is shown on the device's own (new) clock, the older to its left.
        QCOMPARE(acc->canvas()->xMax(), 1.004);
        const QList<QPointF> points = acc->linePoints(Channel::AccX);
        QVERIFY(points.first().x() < 0.0);
    }

    void chartsWithoutDataAreHidden()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        // Four charts by default; the others when chosen.
        QVERIFY(panel.chart(ChartKind::Temperature)->isHidden());
        QCOMPARE(panel.gridColumns(), 2);
        for (int k = 0; k < imudesk::ui::kChartKindCount; ++k)
            panel.setChartChosen(ChartKind(k), true);
        // Before any data every chosen chart shows, but the compass's relative field, which only
        // an HEC495 sends: its chart waits for its data.
        for (int k = 0; k < imudesk::ui::kChartKindCount; ++k)
            QCOMPARE(panel.chart(ChartKind(k))->isHidden(), ChartKind(k) == ChartKind::MagneticRelative);
        // An HI83 without a barometer.
        feed(panel, 0, 500, true, kHi91Fields & ~uint32_t(model::FieldPressure));
        QVERIFY(panel.chart(ChartKind::Pressure)->isHidden());
        QVERIFY(panel.chart(ChartKind::MagneticRelative)->isHidden());
        QVERIFY(!panel.chart(ChartKind::Accelerometer)->isHidden());
        QVERIFY(!panel.chart(ChartKind::Temperature)->isHidden());
        QCOMPARE(panel.chart(ChartKind::Pressure)->redrawCount(), 0);
        QVERIFY(panel.chart(ChartKind::Accelerometer)->linePoints(Channel::AccX).size() > 0);
        panel.clear();
        panel.appendSamples({sineSample(0)}); // refilled before the next tick: still a redraw
        panel.refresh();
        QCOMPARE(panel.chart(ChartKind::Accelerometer)->linePoints(Channel::AccX).size(), qsizetype(1));
        panel.clear();
        panel.refresh();
        QVERIFY(!panel.chart(ChartKind::Pressure)->isHidden());
        QCOMPARE(panel.chart(ChartKind::Accelerometer)->linePoints(Channel::AccX).size(), qsizetype(0));
    }

    // Issue 53 point 6: a chart whose quantity stops arriving while other data goes on (an
    // HEC495 streaming its angles after its first polled records) says why on the chart, and
    // offers the device's switch when its family gives one; the note goes when the data comes.
    void saysWhyAChartStaysEmpty()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        ChartView *acc = panel.chart(ChartKind::Accelerometer);
        ChartView *euler = panel.chart(ChartKind::Euler);
        const uint32_t anglesOnly = model::FieldEuler | model::FieldDeviceTime;
        feed(panel, 0, 1000);
        QVERIFY(!acc->hasNote());
        // Angles alone: within kMissingAfterS nothing is said yet, then the accelerometer says so.
        feed(panel, 1000, 2500, true, anglesOnly);
        QVERIFY(!acc->hasNote());
        feed(panel, 2500, 4000, true, anglesOnly);
        QVERIFY(!acc->isHidden());
        QVERIFY(acc->hasNote());
        QCOMPARE(acc->noteText(), ChartPanel::missingText(ChartKind::Accelerometer));
        QVERIFY2(acc->noteText().contains(QStringLiteral("carries no acceleration at its current setting")),
                 qPrintable(acc->noteText()));
        QVERIFY(acc->findChild<QWidget *>(QStringLiteral("chartNote"))->isVisible());
        QVERIFY(panel.chart(ChartKind::Gyroscope)->hasNote());
        QVERIFY(!euler->hasNote());
        // Nothing to offer: no button.
        QVERIFY(acc->noteButton()->isHidden());

        // The family offers a switch for the accelerometer and the gyroscope.
        int switched = 0;
        panel.offerOutputSwitch((1u << int(ChartKind::Accelerometer)) | (1u << int(ChartKind::Gyroscope)),
                                [] { return QStringLiteral("All data"); }, [&switched] { ++switched; });
        panel.refresh();
        QVERIFY(acc->hasNote());
        QVERIFY(acc->noteButton()->isVisible());
        QCOMPARE(acc->noteButton()->text(), QStringLiteral("All data"));
        // The note lies over the plot area, within the chart.
        const QWidget *note = acc->findChild<QWidget *>(QStringLiteral("chartNote"));
        QVERIFY(acc->canvas()->rect().contains(note->geometry()));
        QTest::mouseClick(acc->noteButton(), Qt::LeftButton);
        QCOMPARE(switched, 1);
        // Clicked once: both charts' buttons wait for the data (kSwitchWaitS).
        feed(panel, 4000, 4100, true, anglesOnly);
        QVERIFY(!acc->noteButton()->isEnabled());
        QVERIFY(!panel.chart(ChartKind::Gyroscope)->noteButton()->isEnabled());
        // The data comes: the notes go.
        feed(panel, 4100, 4200);
        QVERIFY(!acc->hasNote());
        QVERIFY(!panel.chart(ChartKind::Gyroscope)->hasNote());

        // A device that never sent acceleration: with the offer its chart shows, and says why.
        panel.clear();
        feed(panel, 0, 3000, true, anglesOnly);
        QVERIFY(!acc->isHidden());
        QVERIFY(acc->hasNote());
        QVERIFY(acc->noteButton()->isEnabled());
        QVERIFY(panel.chart(ChartKind::Magnetometer)->isHidden()); // not offered: hidden as before
        // Without the offer (the link went) it is hidden again.
        panel.offerOutputSwitch(0, {}, {});
        panel.refresh();
        QVERIFY(acc->isHidden());
    }

    void timeAxisForAllCharts()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        feed(panel, 0, 3000);
        QSignalSpy changed(&panel, &ChartPanel::settingsChanged);
        panel.timeAxisCombo()->setCurrentIndex(panel.timeAxisCombo()->findData(int(TimeAxis::Host)));
        QCOMPARE(panel.timeAxis(), TimeAxis::Host);
        QCOMPARE(changed.count(), 1);
        panel.refresh();
        for (int k = 0; k < imudesk::ui::kChartKindCount; ++k) {
            ChartView *chart = panel.chart(ChartKind(k));
            QCOMPARE(chart->timeAxis(), TimeAxis::Host);
            QCOMPARE(chart->canvas()->xTitle(), ChartView::timeAxisTitle(TimeAxis::Host));
        }
        QCOMPARE(panel.chart(ChartKind::Accelerometer)->canvas()->xMax(), 2.999); // s since the first sample
        QCOMPARE(panel.settings().timeAxis, TimeAxis::Host);
    }

    void axisTitlesAreTranslatable()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        // English: quantity and unit.
        QCOMPARE(panel.chart(ChartKind::Accelerometer)->canvas()->yTitle(), QStringLiteral("Acceleration (G)"));
        QCOMPARE(panel.chart(ChartKind::Gyroscope)->canvas()->yTitle(), QStringLiteral("Angular velocity (deg/s)"));
        QCOMPARE(panel.chart(ChartKind::Magnetometer)->canvas()->yTitle(), QStringLiteral("Magnetic field (µT)"));
        QCOMPARE(panel.chart(ChartKind::Euler)->canvas()->yTitle(), QStringLiteral("Angle (deg)"));
        QCOMPARE(panel.chart(ChartKind::Quaternion)->canvas()->yTitle(), QStringLiteral("Quaternion component"));
        QCOMPARE(panel.chart(ChartKind::Pressure)->canvas()->yTitle(), QStringLiteral("Pressure (Pa)"));
        QCOMPARE(panel.chart(ChartKind::Temperature)->canvas()->yTitle(), QStringLiteral("Temperature (°C)"));
        QCOMPARE(panel.chart(ChartKind::Accelerometer)->canvas()->xTitle(), QStringLiteral("Device time (s)"));

        // Every visible text goes through tr(): a translator that marks everything shows up everywhere.
        MarkingTranslator marker;
        QVERIFY(QCoreApplication::installTranslator(&marker));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        QCoreApplication::processEvents();
        ChartView *acc = panel.chart(ChartKind::Accelerometer);
        QCOMPARE(acc->canvas()->yTitle(), QStringLiteral("«%1 (%2)»").arg(QStringLiteral("«Acceleration»"), QStringLiteral("«G»")));
        QCOMPARE(acc->canvas()->xTitle(), QStringLiteral("«Device time (s)»"));
        QCOMPARE(acc->canvas()->title(), QStringLiteral("«Accelerometer»"));
        QCOMPARE(panel.pauseAction()->text(), QStringLiteral("«Pause»"));
        QCOMPARE(panel.windowCombo()->currentText(), QStringLiteral("«10 s»"));
        QVERIFY(panel.cursorAction()->text().startsWith(QStringLiteral("«")));
        QVERIFY(acc->autoScaleAction()->text().startsWith(QStringLiteral("«")));
        QVERIFY(panel.timeAxisCombo()->itemText(0).startsWith(QStringLiteral("«")));
        QVERIFY(panel.timeAxisCombo()->itemText(1).startsWith(QStringLiteral("«")));
        QCoreApplication::removeTranslator(&marker);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        QCoreApplication::processEvents();
        QCOMPARE(acc->canvas()->xTitle(), QStringLiteral("Device time (s)"));
        QCOMPARE(panel.windowCombo()->currentText(), QStringLiteral("10 s"));
    }

    void fixedScale()
    {
        ChartPanel panel;
        panel.resize(1200, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        feed(panel, 0, 1000);
        ChartView *acc = panel.chart(ChartKind::Accelerometer);
        acc->setAutoScale(false);
        acc->setFixedRange(-4.0, 4.0);
        acc->setFixedRange(3.0, 1.0); // ignored: min must be below max
        panel.refresh();
        QCOMPARE(acc->canvas()->yMin(), -4.0);
        QCOMPARE(acc->canvas()->yMax(), 4.0);
        const QWidget *minSpin = acc->minSpin(); // in the chart's context menu
        QVERIFY(minSpin && minSpin->isEnabled() && minSpin->toolTip().contains(QStringLiteral("G")));
        QVERIFY(!acc->autoScaleAction()->isChecked());
        acc->setAutoScale(true);
        panel.refresh();
        QVERIFY(acc->canvas()->yMax() < 4.0 && acc->canvas()->yMax() > 1.0);
        QVERIFY(!minSpin->isEnabled());
    }

    void axisScaling()
    {
        using imudesk::plot::AxisScaling;
        QCOMPARE(AxisScaling::niceStep(2.4, 5), 0.5);
        QCOMPARE(AxisScaling::niceStep(10.0, 5), 2.0);
        QCOMPARE(AxisScaling::niceStep(0.004, 5), 0.001);
        QCOMPARE(AxisScaling::niceStep(700.0, 5), 200.0);
        QCOMPARE(AxisScaling::timeTickInterval(2.0), 0.5);
        QCOMPARE(AxisScaling::timeTickInterval(10.0), 2.0);
        QCOMPARE(AxisScaling::timeTickInterval(600.0), 120.0);
        QCOMPARE(AxisScaling::decimalsFor(0.5), 1);
        QCOMPARE(AxisScaling::decimalsFor(2.0), 0);
        QCOMPARE(AxisScaling::decimalsFor(0.001), 3);
        QCOMPARE(AxisScaling::decimalsFor(0.25), 1);
        // Autoscale: widens at once, keeps a range that still fits, narrows when far too wide.
        const AxisScaling::Range first = AxisScaling::autoRange({}, false, -1.0, 1.0, 0.01);
        QCOMPARE(first.min, -1.2);
        QCOMPARE(first.max, 1.2);
        QVERIFY(AxisScaling::autoRange(first, true, -0.8, 0.9, 0.01) == first);
        QVERIFY(AxisScaling::autoRange(first, true, -0.1, 0.1, 0.01).span() < 0.5);
        QVERIFY(AxisScaling::autoRange(first, true, -1.0, 1.5, 0.01).max > 1.5);
        // Flat data still gets the minimum span.
        const AxisScaling::Range flat = AxisScaling::autoRange({}, false, 25.0, 25.0, 0.02);
        QVERIFY(flat.min < 25.0 && flat.max > 25.0 && flat.span() >= 0.02);
    }

    void settingsRoundTrip()
    {
        QTemporaryDir dir;
        QSettings file(dir.filePath(QStringLiteral("charts.ini")), QSettings::IniFormat);
        ChartSettings s;
        s.windowSeconds.fill(120); // the panel has one window for every chart
        s.timeAxis = TimeAxis::Host;
        s.hiddenCharts = 1u << int(ChartKind::Magnetometer); // and the quaternion, pressure, temperature chosen
        s.hiddenChannels = imudesk::plot::channelBit(Channel::QuatW) | imudesk::plot::channelBit(Channel::MagZ);
        file.beginGroup(QStringLiteral("COM3")); // one group per device, the owner's choice
        s.save(file);
        file.endGroup();
        file.sync();
        QCOMPARE(file.value(QStringLiteral("COM3/ui/v1/charts/timeAxis")).toString(), QStringLiteral("host"));

        ChartSettings back;
        file.beginGroup(QStringLiteral("COM3"));
        back.load(file);
        file.endGroup();
        QVERIFY(back == s);

        // Unknown values fall back to the defaults.
        file.setValue(QLatin1String(ChartSettings::kWindowKeys[0]), 7.0);
        file.setValue(QLatin1String(ChartSettings::kTimeAxisKey), QStringLiteral("sundial"));
        ChartSettings fallback;
        fallback.load(file);
        QCOMPARE(fallback.windowSeconds[0], ChartSettings::kDefaultWindowSeconds);
        QCOMPARE(fallback.timeAxis, TimeAxis::Device);

        // A panel takes them and gives them back, without announcing a change it was told about.
        ChartPanel panel;
        QSignalSpy changed(&panel, &ChartPanel::settingsChanged);
        panel.setSettings(s);
        QCOMPARE(changed.count(), 0);
        QVERIFY(panel.settings() == s);
        QCOMPARE(panel.windowCombo()->currentData().toDouble(), 120.0);
        QVERIFY(!panel.chart(ChartKind::Quaternion)->isChannelVisible(Channel::QuatW));
        QVERIFY(!panel.isChartChosen(ChartKind::Magnetometer) && panel.isChartChosen(ChartKind::Temperature));
        QVERIFY(!panel.chartAction(ChartKind::Magnetometer)->isChecked());
    }

    void comparisonOverlaysDevices()
    {
        // Two devices: B started 2 s after A, with its own device clock.
        ChannelHistory a, b;
        for (int i = 0; i < 6000; ++i) {
            a.append(sineSample(i));
            if (i >= 2000) {
                Sample s = sineSample(i, kHi91Fields, 50.0 + i);
                s.yaw = 180.0;
                b.append(s);
            }
        }
        ComparisonChart chart;
        chart.resize(1000, 500);
        chart.show();
        QVERIFY(QTest::qWaitForWindowExposed(&chart));
        chart.setSources({{QStringLiteral("COM3"), &a}, {QStringLiteral("COM4"), &b}});
        chart.setChannel(Channel::Yaw);
        QVERIFY(chart.refresh());
        QVERIFY(!chart.refresh()); // nothing new
        QCOMPARE(chart.series(0)->name(), QStringLiteral("COM3"));
        QCOMPARE(chart.series(1)->name(), QStringLiteral("COM4"));
        QCOMPARE(chart.sourceOffset(0), 0.0);
        QCOMPARE(chart.sourceOffset(1), 2.0);
        // One host time axis: both end at the same instant.
        QCOMPARE(chart.series(0)->points().last().x(), 5.999);
        QCOMPARE(chart.series(1)->points().last().x(), 5.999);
        QCOMPARE(chart.series(1)->points().first().x(), 2.0);
        QCOMPARE(chart.axisX()->max(), 5.999);
        QCOMPARE(chart.series(1)->points().last().y(), 180.0);
        const int width = chart.drawnWidthPx();
        QVERIFY(chart.series(0)->count() <= 4 * width && chart.series(1)->count() <= 4 * width);
        QCOMPARE(chart.axisY()->titleText(), QStringLiteral("Yaw (deg)"));
        // Another channel from the combo.
        chart.channelCombo()->setCurrentIndex(chart.channelCombo()->findData(int(Channel::AccX)));
        QCOMPARE(chart.channel(), Channel::AccX);
        QCOMPARE(chart.axisY()->titleText(), QStringLiteral("Acceleration X (G)"));
        QVERIFY(chart.refresh());
        QVERIFY(chart.series(1)->count() > 0);
        // New data on one source is enough to redraw.
        for (int i = 6000; i < 6100; ++i)
            b.append(sineSample(i, kHi91Fields, 50.0 + i));
        QVERIFY(chart.refresh());
        QCOMPARE(chart.axisX()->max(), 6.099);
        QTemporaryDir dir;
        QString error;
        QVERIFY2(chart.savePng(dir.filePath(QStringLiteral("cmp.png")), &error), qPrintable(error));
        chart.setSources({});
        QVERIFY(chart.refresh());
        QCOMPARE(chart.series(0), nullptr);
    }
};

IMUDESK_TEST_MAIN(TstChartPanel)
#include "tst_chart_panel.moc"
