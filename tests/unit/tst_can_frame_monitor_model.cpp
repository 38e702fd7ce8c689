// The CAN frame monitor model: one row per identifier with count, cycle time, last data and
// meaning (the manual's 8.27 PCAN-View capture as input), filter, pause, bound, CSV export.
#include "itemmodels/can_frame_monitor_model.h"
#include "../common/test_main.h"

#include <QAbstractItemModelTester>
#include <QBuffer>
#include <QSignalSpy>
#include <QTest>

using namespace imudesk;
using imudesk::models::CanFrameMonitorModel;
using imudesk::protocol::can::CanFrame;

namespace {
device::CanFrameEvents capture(int periods, qint64 t0Ns = 0)
{
    // 8.27: 188h..488h every 10 ms, 688h every 100 ms.
    device::CanFrameEvents ev;
    for (int i = 0; i < periods; ++i) {
        const qint64 t = t0Ns + qint64(i) * 10000000;
        ev.append({CanFrame::fromHex(0x188, false, "9BFF9400BD03"), t, false});
        ev.append({CanFrame::fromHex(0x288, false, "000000000000"), t, false});
        ev.append({CanFrame::fromHex(0x388, false, "48027B031701"), t, false});
        ev.append({CanFrame::fromHex(0x488, false, "E026FB020E021A01"), t, false});
        if (i % 10 == 0)
            ev.append({CanFrame::fromHex(0x688, false, "00000000"), t, false});
    }
    return ev;
}
int rowOf(const CanFrameMonitorModel &m, uint id)
{
    for (int r = 0; r < m.rowCount(); ++r)
        if (m.index(r, 0).data(CanFrameMonitorModel::IdRole).toUInt() == id)
            return r;
    return -1;
}
} // namespace

class TstCanFrameMonitorModel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void rowsCountsPeriods()
    {
        CanFrameMonitorModel m;
        QAbstractItemModelTester tester(&m, QAbstractItemModelTester::FailureReportingMode::QtTest);
        // Fed in random-sized batches: the result must not depend on the chunking.
        const auto all = capture(270);
        int at = 0, step = 1;
        while (at < all.size()) {
            m.addEvents(all.mid(at, step));
            at += step;
            step = step % 17 + 3;
        }
        QCOMPARE(m.rowCount(), 5);
        const int r188 = rowOf(m, 0x188);
        QVERIFY(r188 >= 0);
        QCOMPARE(m.index(r188, CanFrameMonitorModel::ColCount).data().toULongLong(), 270ull);
        QCOMPARE(m.index(r188, CanFrameMonitorModel::ColId).data().toString(), QStringLiteral("188h"));
        QCOMPARE(m.index(r188, CanFrameMonitorModel::ColData).data().toString(), QStringLiteral("9B FF 94 00 BD 03"));
        QCOMPARE(m.index(r188, CanFrameMonitorModel::ColDlc).data().toInt(), 6);
        QVERIFY(qAbs(m.index(r188, 0).data(CanFrameMonitorModel::PeriodMsRole).toDouble() - 10.0) < 1e-6);
        const int r688 = rowOf(m, 0x688);
        QCOMPARE(m.index(r688, CanFrameMonitorModel::ColCount).data().toULongLong(), 27ull);
        QVERIFY(qAbs(m.index(r688, 0).data(CanFrameMonitorModel::PeriodMsRole).toDouble() - 100.0) < 1e-6);
        QVERIFY(m.index(r188, CanFrameMonitorModel::ColMeaning).data().toString().contains(QStringLiteral("TPDO1")));
        QVERIFY(m.index(rowOf(m, 0x488), CanFrameMonitorModel::ColMeaning).data().toString().contains(QStringLiteral("0.9952")));
    }

    void filterPauseBound()
    {
        CanFrameMonitorModel m;
        QAbstractItemModelTester tester(&m, QAbstractItemModelTester::FailureReportingMode::QtTest);
        m.addEvents(capture(3));
        m.setFilter(QStringLiteral("TPDO2"));
        QCOMPARE(m.rowCount(), 1);
        QCOMPARE(m.index(0, 0).data(CanFrameMonitorModel::IdRole).toUInt(), 0x288u);
        m.setFilter(QStringLiteral("88"));
        QCOMPARE(m.rowCount(), 5);
        m.setFilter(QStringLiteral("pressure"));
        QCOMPARE(m.rowCount(), 1);
        // New rows that do not match stay hidden but are counted.
        m.addEvents({{CanFrame::fromHex(0x0CFF3408, true, "0000000000080000"), 0, false}});
        QCOMPARE(m.rowCount(), 1);
        m.setFilter(QString());
        QCOMPARE(m.rowCount(), 6);
        QSignalSpy changed(&m, &CanFrameMonitorModel::dataChanged);
        m.setPaused(true);
        m.addEvents(capture(2));
        QCOMPARE(changed.size(), 0);
        QCOMPARE(m.framesWhilePaused(), uint64_t(capture(2).size()));
        m.setPaused(false);
        m.addEvents(capture(1));
        QCOMPARE(changed.size(), 1); // one dataChanged per batch
        m.setMaxRows(6);
        m.addEvents({{CanFrame::fromHex(0x123, false, "01"), 0, false}, {CanFrame::fromHex(0x188, false, "01"), 0, true}});
        QCOMPARE(m.rowCount(), 6);
        QCOMPARE(m.framesOverLimit(), uint64_t(2));
        m.clear();
        QCOMPARE(m.rowCount(), 0);
    }

    void csvExport()
    {
        CanFrameMonitorModel m;
        m.addEvents(capture(2));
        m.addEvents({{CanFrame::fromHex(0x608, false, "2B00180564000000"), 0, true}});
        QBuffer buf;
        buf.open(QIODevice::WriteOnly);
        QVERIFY(m.exportCsv(&buf));
        const QStringList lines = QString::fromUtf8(buf.data()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 7);
        QCOMPARE(lines[0], QStringLiteral("id,type,direction,dlc,data,period_ms,count,meaning"));
        QVERIFY(lines[1].startsWith(QStringLiteral("188,std,rx,6,9B FF 94 00 BD 03,10.000,2,")));
        QVERIFY(lines[6].startsWith(QStringLiteral("608,std,tx,8,2B 00 18 05 64 00 00 00,")));
        QVERIFY(lines[6].contains(QStringLiteral("0x1800.05 = 100")));
        QString error;
        QVERIFY(!m.exportCsv(QStringLiteral("/nonexistent-dir/x.csv"), &error));
        QVERIFY(error.contains(QStringLiteral("/nonexistent-dir/x.csv")));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCanFrameMonitorModel)
#include "tst_can_frame_monitor_model.moc"
