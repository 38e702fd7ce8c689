// CanMonitorWidget offscreen: rows from the manual's PCAN-View capture (8.27), filter and
// pause from the controls, CSV export, and the send line (valid and invalid frames).
#include "bus/can_monitor_widget.h"
#include "../common/test_main.h"

#include <QApplication>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

using imudesk::protocol::can::CanFrame;
using imudesk::ui::CanMonitorWidget;

namespace {
imudesk::device::CanFrameEvents capture(qint64 t0, int n)
{
    imudesk::device::CanFrameEvents ev;
    for (int i = 0; i < n; ++i) {
        ev.append({CanFrame::fromHex(0x188, false, "9BFF9400BD03"), t0 + i * 10000000LL, false});
        ev.append({CanFrame::fromHex(0x388, false, "48027B031701"), t0 + i * 10000000LL, false});
    }
    return ev;
}
template <typename T> T *child(QWidget &w, const QString &text)
{
    for (T *c : w.findChildren<T *>())
        if (c->text() == text)
            return c;
    return nullptr;
}
} // namespace

class TstCanMonitorWidget : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void showsFiltersPauses()
    {
        CanMonitorWidget w;
        w.resize(800, 400);
        w.show();
        w.addEvents(capture(0, 10));
        QCOMPARE(w.table()->model()->rowCount(), 2);
        auto *filter = w.findChild<QLineEdit *>();
        QVERIFY(filter);
        QTest::keyClicks(filter, QStringLiteral("euler"));
        QCOMPARE(w.table()->model()->rowCount(), 1);
        filter->clear();
        auto *pause = child<QToolButton>(w, QStringLiteral("Pause"));
        QVERIFY(pause);
        pause->click();
        QVERIFY(w.model()->isPaused());
        w.addEvents(capture(100000000, 5));
        QCOMPARE(w.model()->totalFrames(), uint64_t(20));
        pause->click();
        w.addEvents(capture(200000000, 5));
        QCOMPARE(w.model()->totalFrames(), uint64_t(30));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("frames.csv"));
        QVERIFY(w.exportCsv(path));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readAll().contains("188,std,rx,6,9B FF 94 00 BD 03"));
        child<QPushButton>(w, QStringLiteral("Clear"))->click();
        QCOMPARE(w.table()->model()->rowCount(), 0);
    }

    void sendLine()
    {
        CanMonitorWidget w;
        QSignalSpy spy(&w, &CanMonitorWidget::sendFrameRequested);
        const auto edits = w.findChildren<QLineEdit *>();
        QLineEdit *id = nullptr, *data = nullptr;
        for (auto *e : edits) {
            if (e->placeholderText().startsWith(QStringLiteral("ID")))
                id = e;
            if (e->placeholderText().startsWith(QStringLiteral("data")))
                data = e;
        }
        QVERIFY(id && data);
        id->setText(QStringLiteral("608"));
        data->setText(QStringLiteral("2B 00 18 05 0A 00 00 00"));
        child<QPushButton>(w, QStringLiteral("Send"))->click();
        QCOMPARE(spy.size(), 1);
        const auto f = spy.at(0).at(0).value<CanFrame>();
        QCOMPARE(f, CanFrame::fromHex(0x608, false, "2B0018050A000000"));
        id->setText(QStringLiteral("0CEF0855"));
        child<QPushButton>(w, QStringLiteral("Send"))->click();
        QCOMPARE(spy.size(), 1); // 29-bit ID without "Extended": refused
        QString error;
        QVERIFY(!CanMonitorWidget::parseFrame(QStringLiteral("123"), QStringLiteral("0102030405060708 09"), false, false, &error));
        QVERIFY(error.contains(QStringLiteral("8 bytes")));
        QVERIFY(CanMonitorWidget::parseFrame(QStringLiteral("0x0CEF0855"), QStringLiteral("37,01,06,00,64,00,00,00"), true, false, &error));
    }
};

IMUDESK_TEST_MAIN(TstCanMonitorWidget)
#include "tst_can_monitor_widget.moc"
