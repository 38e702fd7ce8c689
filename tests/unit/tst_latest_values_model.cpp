// LatestValuesModel: the manual's HI91 example, change detection, missing fields.
#include "../common/golden.h"
#include "../common/test_main.h"
#include "model/main_status.h"
#include "itemmodels/latest_values_model.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/witlink/all_data_record.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QTest>

#include <cmath>

using imudesk::model::Sample;
using imudesk::models::LatestValuesModel;
namespace hp = imudesk::protocol::hipnuc;

namespace {

// The v1.7.1 manual's HI91 example frame (section 5.11), decoded.
Sample manualSample()
{
    const auto frame = golden::bytes(golden::hi91Frame());
    hp::Hi91 h;
    if (frame.size() != 82 || !hp::decodeHi91(frame.data() + 6, 76, h))
        return {};
    return hp::toSample(h);
}

QString value(const LatestValuesModel &m, LatestValuesModel::Row row)
{
    return m.index(row, LatestValuesModel::ValueColumn).data().toString();
}

} // namespace

class TstLatestValuesModel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void modelTester()
    {
        LatestValuesModel m;
        QAbstractItemModelTester tester(&m, QAbstractItemModelTester::FailureReportingMode::QtTest);
        Sample s = manualSample();
        m.refresh(s);
        s.roll += 1;
        s.fields &= ~imudesk::model::FieldMag;
        m.refresh(s);
        m.refresh(std::nullopt);
        m.retranslate();
        QCOMPARE(m.rowCount(), int(LatestValuesModel::RowCount));
        QCOMPARE(m.columnCount(), 3);
    }

    void headersAndShape()
    {
        LatestValuesModel m;
        QCOMPARE(m.headerData(0, Qt::Horizontal).toString(), QStringLiteral("Quantity"));
        QCOMPARE(m.headerData(1, Qt::Horizontal).toString(), QStringLiteral("Value"));
        QCOMPARE(m.headerData(2, Qt::Horizontal).toString(), QStringLiteral("Unit"));
        QCOMPARE(m.index(LatestValuesModel::Roll, 0).data().toString(), QStringLiteral("Roll"));
        QCOMPARE(m.index(LatestValuesModel::GyrZ, 2).data().toString(), QStringLiteral("deg/s"));
        QCOMPARE(m.index(LatestValuesModel::MagX, 2).data().toString(), QStringLiteral("µT"));
        QCOMPARE(m.index(LatestValuesModel::AccY, 2).data().toString(), QStringLiteral("G"));
    }

    void insFieldsOnceSeen()
    {
        Sample s;
        s.source = "HI81";
        s.fields = imudesk::model::FieldPosition | imudesk::model::FieldVelocity | imudesk::model::FieldInsStatus;
        s.latitudeDeg = 39.9401294;
        s.longitudeDeg = -116.5;
        s.altitudeM = 52.996;
        s.velEnu = {1.25, -0.5, 0};
        s.insStatus = 3;
        LatestValuesModel m;
        QVERIFY(!m.everSeen(LatestValuesModel::Latitude));
        m.refresh(s);
        QVERIFY(m.everSeen(LatestValuesModel::Latitude));
        QVERIFY(m.everSeen(LatestValuesModel::VelEast));
        QVERIFY(!m.everSeen(LatestValuesModel::Heave));
        QCOMPARE(value(m, LatestValuesModel::Latitude), QStringLiteral("39.9401294"));
        QCOMPARE(value(m, LatestValuesModel::Longitude), QStringLiteral("-116.5000000"));
        QCOMPARE(value(m, LatestValuesModel::Altitude), QStringLiteral("52.996"));
        QCOMPARE(value(m, LatestValuesModel::VelEast), QStringLiteral("1.25"));
        QCOMPARE(m.index(LatestValuesModel::Altitude, 2).data().toString(), QStringLiteral("m"));
        QCOMPARE(m.index(LatestValuesModel::VelUp, 2).data().toString(), QStringLiteral("m/s"));
        QVERIFY(value(m, LatestValuesModel::InsStatus).startsWith(QLatin1String("3")));
        // A later HI91 without position keeps the rows offered, showing "—".
        Sample imu;
        imu.source = "HI91";
        imu.fields = imudesk::model::FieldAcc;
        m.refresh(imu);
        QVERIFY(m.everSeen(LatestValuesModel::Latitude));
        QCOMPARE(value(m, LatestValuesModel::Latitude), QStringLiteral("—"));
    }

    // NMEA: the GNSS fix with its satellites, and the UTC time of day (issue 21, point 1).
    void gnssFixAndUtcTime()
    {
        Sample s;
        s.source = "GGA";
        s.fields = imudesk::model::FieldGnss | imudesk::model::FieldPosition;
        s.gnssQuality = 4;
        s.gnssSatellites = 17;
        s.utcTimeOfDayS = 1 * 3600 + 2 * 60 + 3.5;
        s.latitudeDeg = 31.2083333;
        s.longitudeDeg = 121.4583333;
        s.altitudeM = std::nan("");
        LatestValuesModel m;
        m.refresh(s);
        QVERIFY(m.everSeen(LatestValuesModel::GnssFix) && m.everSeen(LatestValuesModel::UtcTime));
        QCOMPARE(value(m, LatestValuesModel::GnssFix), QStringLiteral("4 RTK fixed (17)"));
        QCOMPARE(value(m, LatestValuesModel::UtcTime), QStringLiteral("01:02:03.50"));
        QCOMPARE(value(m, LatestValuesModel::Altitude), QStringLiteral("—")); // an RMC-only position has none
        s.utcTimeOfDayS = 23 * 3600 + 59 * 60 + 59.994;
        m.refresh(s);
        QCOMPARE(value(m, LatestValuesModel::UtcTime), QStringLiteral("23:59:59.99"));
    }

    void headingAndHi83Rows()
    {
        using namespace imudesk::model;
        LatestValuesModel m;
        Sample hdt;
        hdt.source = "HDT";
        hdt.fields = FieldHeading;
        hdt.headingDeg = 296.04;
        m.refresh(hdt);
        QVERIFY(m.everSeen(LatestValuesModel::Heading));
        QCOMPARE(value(m, LatestValuesModel::Heading), QStringLiteral("296.0 true"));
        QVERIFY(!m.everSeen(LatestValuesModel::EventCounters));

        // An HI83 with bits 25, 28 and 30: those rows and no other HI83 row.
        hp::Hi83 h;
        h.bitmap = (1u << 25) | (1u << 28) | (1u << 30);
        h.eventCounter = {1200, 600, 12, 12};
        h.gnssStd = {1.5f, 0.05f, 0};
        h.gnssLonLatMsl = {121.458333, 31.208333, 40.0};
        m.refresh(hp::toSample(hp::Packet(h)));
        QVERIFY(m.everSeen(LatestValuesModel::EventCounters));
        QVERIFY(m.everSeen(LatestValuesModel::GnssAccuracy));
        QVERIFY(m.everSeen(LatestValuesModel::GnssPosition));
        QVERIFY(!m.everSeen(LatestValuesModel::KfAccBias));
        QVERIFY(!m.everSeen(LatestValuesModel::DualAntenna));
        QCOMPARE(value(m, LatestValuesModel::EventCounters), QStringLiteral("grav 1200 mag 600 pos 12 vel 12"));
        QCOMPARE(value(m, LatestValuesModel::GnssAccuracy), QStringLiteral("1.50  0.05"));
        QCOMPARE(value(m, LatestValuesModel::GnssPosition), QStringLiteral("31.2083330  121.4583330  40.00"));
        QCOMPARE(value(m, LatestValuesModel::KfAccBias), QStringLiteral("—"));
        QCOMPARE(m.index(LatestValuesModel::GnssAccuracy, LatestValuesModel::UnitColumn).data().toString(),
                 QStringLiteral("m, m/s"));
        QVERIFY(!m.index(LatestValuesModel::EventCounters, 0).data(Qt::ToolTipRole).toString().isEmpty());
    }

    // The HEC495's read-all record (manual 2.5): its relative field and magnetic roll get rows of
    // their own, never the uT magnetometer rows.
    void hec495RelativeFieldAndMagRoll()
    {
        LatestValuesModel m;
        imudesk::protocol::witlink::AllDataRecord r;
        r.mag = {0.5f, 0.8f, -1.25f};
        r.magRoll = 45.5f;
        r.heading = 120;
        m.refresh(r.toSample());
        for (auto row : {LatestValuesModel::MagRelX, LatestValuesModel::MagRelY, LatestValuesModel::MagRelZ,
                         LatestValuesModel::MagRoll})
            QVERIFY(m.everSeen(row));
        QVERIFY(!m.everSeen(LatestValuesModel::MagX));
        // One row per axis, as the chart of the relative field has one line per axis.
        QCOMPARE(value(m, LatestValuesModel::MagRelX), QStringLiteral("0.500"));
        QCOMPARE(value(m, LatestValuesModel::MagRelY), QStringLiteral("0.800"));
        QCOMPARE(value(m, LatestValuesModel::MagRelZ), QStringLiteral("-1.250"));
        QCOMPARE(value(m, LatestValuesModel::MagRoll), QStringLiteral("45.5"));
        QCOMPARE(m.index(LatestValuesModel::MagRelY, LatestValuesModel::UnitColumn).data().toString(),
                 QStringLiteral("relative"));
        QCOMPARE(m.index(LatestValuesModel::MagRoll, LatestValuesModel::UnitColumn).data().toString(), QStringLiteral("deg"));
        QVERIFY(m.index(LatestValuesModel::MagRelZ, 0).data(Qt::ToolTipRole).toString().contains(QStringLiteral("north is 1")));
        QVERIFY(m.index(LatestValuesModel::MagRelX, 0).data().toString().contains(QStringLiteral("Relative magnetic field X")));
        // Not rows of a module before any data.
        QVERIFY(!LatestValuesModel::isCoreRow(LatestValuesModel::MagRelX));
        QVERIFY(!LatestValuesModel::isCoreRow(LatestValuesModel::MagRoll));
        QVERIFY(LatestValuesModel::isCoreRow(LatestValuesModel::Temperature));
    }

    // A module set to NWU: the attitude rows say so, the others do not change.
    void nwuAttitudeRows()
    {
        LatestValuesModel m;
        const auto name = [&](LatestValuesModel::Row row) { return m.index(row, 0).data().toString(); };
        QCOMPARE(name(LatestValuesModel::Yaw), QStringLiteral("Yaw"));
        m.setWorldFrame(imudesk::model::WorldFrame::Nwu);
        QCOMPARE(name(LatestValuesModel::Yaw), QStringLiteral("Yaw (NWU)"));
        QCOMPARE(name(LatestValuesModel::QuatW), QStringLiteral("Quaternion W (NWU)"));
        QCOMPARE(name(LatestValuesModel::AccX), QStringLiteral("Acceleration X"));
        QVERIFY(m.index(LatestValuesModel::Yaw, 0).data(Qt::ToolTipRole).toString().contains(QStringLiteral("West")));
        m.setWorldFrame(imudesk::model::WorldFrame::Enu);
        QCOMPARE(name(LatestValuesModel::Roll), QStringLiteral("Roll"));
    }

    void deviceTimeAsUtcOncePpsAligned()
    {
        using namespace imudesk::model;
        Sample s;
        s.source = "HI91";
        s.fields = FieldDeviceTime | FieldMainStatus;
        s.mainStatus = 1u << 11; // UTC_UNSYNC: ms since power-on
        s.deviceTimeMs = 123456;
        LatestValuesModel m;
        m.refresh(s);
        QCOMPARE(value(m, LatestValuesModel::DeviceTime), QStringLiteral("123456"));
        QCOMPARE(m.index(LatestValuesModel::DeviceTime, LatestValuesModel::UnitColumn).data().toString(), QStringLiteral("ms"));
        QSignalSpy spy(&m, &QAbstractItemModel::dataChanged);
        s.mainStatus = 0; // aligned: the ms of the UTC day (v1.7.1 manual 2.2.2)
        s.deviceTimeMs = 3661000 + 42;
        m.refresh(s);
        QCOMPARE(value(m, LatestValuesModel::DeviceTime), QStringLiteral("01:01:01.042"));
        QCOMPARE(m.index(LatestValuesModel::DeviceTime, LatestValuesModel::UnitColumn).data().toString(), QStringLiteral("UTC"));
        bool unitChanged = false;
        for (const auto &args : spy)
            unitChanged |= args.at(0).toModelIndex().column() == LatestValuesModel::UnitColumn;
        QVERIFY(unitChanged);
        // Without a status word (older firmware) the time is never read as UTC.
        s.fields = FieldDeviceTime;
        m.refresh(s);
        QCOMPARE(value(m, LatestValuesModel::DeviceTime), QStringLiteral("3661042"));
    }

    void emptyShowsDash()
    {
        LatestValuesModel m;
        for (int r = 0; r < LatestValuesModel::RowCount; ++r)
            QCOMPARE(value(m, LatestValuesModel::Row(r)), QStringLiteral("—"));
    }

    void manualHi91Values()
    {
        const Sample s = manualSample();
        QCOMPARE(s.source, std::string("HI91"));
        LatestValuesModel m;
        QSignalSpy spy(&m, &QAbstractItemModel::dataChanged);
        m.refresh(s);
        // The example's status word 0x1508 has bit 11 (UTC_SYNCED in the manual's table: 0 =
        // synchronised) clear, so its system_time is the ms of the UTC day: the device time's
        // unit changes first. Then every row HI91 carries changed from "—": three ranges in the
        // value column, around the compass rows (relative field, magnetic roll) and the INS /
        // ship-motion / inclinometer rows that HI91 does not carry.
        QCOMPARE(spy.count(), 4);
        QCOMPARE(spy.at(0).at(0).toModelIndex().row(), int(LatestValuesModel::DeviceTime));
        QCOMPARE(spy.at(0).at(0).toModelIndex().column(), int(LatestValuesModel::UnitColumn));
        QCOMPARE(spy.at(1).at(0).toModelIndex().row(), 0);
        QCOMPARE(spy.at(1).at(1).toModelIndex().row(), int(LatestValuesModel::Temperature));
        QCOMPARE(spy.at(2).at(0).toModelIndex().row(), int(LatestValuesModel::DeviceTime));
        QCOMPARE(spy.at(2).at(1).toModelIndex().row(), int(LatestValuesModel::DeviceTime));
        QCOMPARE(spy.at(3).at(0).toModelIndex().row(), int(LatestValuesModel::StatusFlags));
        QCOMPARE(spy.at(3).at(1).toModelIndex().row(), int(LatestValuesModel::RowCount) - 1);
        QCOMPARE(spy.at(1).at(0).toModelIndex().column(), int(LatestValuesModel::ValueColumn));
        QVERIFY(m.everSeen(LatestValuesModel::Roll));
        QVERIFY(!m.everSeen(LatestValuesModel::Latitude));
        QCOMPARE(value(m, LatestValuesModel::Latitude), QStringLiteral("—"));

        QCOMPARE(value(m, LatestValuesModel::AccX), QStringLiteral("-0.2206"));
        QCOMPARE(value(m, LatestValuesModel::AccY), QStringLiteral("0.2092"));
        QCOMPARE(value(m, LatestValuesModel::AccZ), QStringLiteral("0.9489"));
        QCOMPARE(value(m, LatestValuesModel::GyrX), QStringLiteral("-0.062"));
        QCOMPARE(value(m, LatestValuesModel::GyrY), QStringLiteral("-0.006"));
        QCOMPARE(value(m, LatestValuesModel::GyrZ), QStringLiteral("-0.010"));
        QCOMPARE(value(m, LatestValuesModel::MagX), QStringLiteral("7.892"));
        QCOMPARE(value(m, LatestValuesModel::MagY), QStringLiteral("14.625"));
        QCOMPARE(value(m, LatestValuesModel::MagZ), QStringLiteral("-60.042"));
        QCOMPARE(value(m, LatestValuesModel::Roll), QStringLiteral("13.05"));
        QCOMPARE(value(m, LatestValuesModel::Pitch), QStringLiteral("12.19"));
        QCOMPARE(value(m, LatestValuesModel::Yaw), QStringLiteral("-122.48"));
        QCOMPARE(value(m, LatestValuesModel::QuatW), QStringLiteral("-0.4859"));
        QCOMPARE(value(m, LatestValuesModel::QuatX), QStringLiteral("-0.1498"));
        QCOMPARE(value(m, LatestValuesModel::QuatY), QStringLiteral("0.0381"));
        QCOMPARE(value(m, LatestValuesModel::QuatZ), QStringLiteral("0.8602"));
        QCOMPARE(value(m, LatestValuesModel::Pressure), QStringLiteral("100676.1"));
        QCOMPARE(value(m, LatestValuesModel::Temperature), QStringLiteral("35.0"));
        QCOMPARE(value(m, LatestValuesModel::DeviceTime), QStringLiteral("00:30:40.392")); // 1840392 ms
        // 0x1508: WB_CONV (3), bit 8 (undefined), MAG_AIDING (10), SOUT_PULSE (12).
        QCOMPARE(value(m, LatestValuesModel::StatusFlags), QStringLiteral("WB_CONV MAG_AIDING SOUT_PULSE (0x1508)"));
        QCOMPARE(value(m, LatestValuesModel::FrameType), QStringLiteral("HI91"));
    }

    void unchangedRefreshEmitsNothing()
    {
        LatestValuesModel m;
        QSignalSpy spy(&m, &QAbstractItemModel::dataChanged);
        QSignalSpy resetSpy(&m, &QAbstractItemModel::modelReset);
        m.refresh(std::nullopt);
        QCOMPARE(spy.count(), 0);
        const Sample s = manualSample();
        m.refresh(s);
        spy.clear();
        m.refresh(s);
        m.refresh(s);
        QCOMPARE(spy.count(), 0);
        // A change below the displayed precision is no change either.
        Sample t = s;
        t.roll += 0.0001;
        m.refresh(t);
        QCOMPARE(spy.count(), 0);
        QCOMPARE(resetSpy.count(), 0);
    }

    void onlyChangedCells()
    {
        LatestValuesModel m;
        Sample s = manualSample();
        m.refresh(s);
        QSignalSpy spy(&m, &QAbstractItemModel::dataChanged);
        s.pitch = 1.5;
        s.quat.x = 0.5;
        s.quat.y = 0.25;
        m.refresh(s);
        QCOMPARE(spy.count(), 2);
        const auto a0 = spy.at(0).at(0).toModelIndex(), a1 = spy.at(0).at(1).toModelIndex();
        QCOMPARE(a0.row(), int(LatestValuesModel::Pitch));
        QCOMPARE(a1.row(), int(LatestValuesModel::Pitch));
        QCOMPARE(a0.column(), int(LatestValuesModel::ValueColumn));
        QCOMPARE(a1.column(), int(LatestValuesModel::ValueColumn));
        QCOMPARE(spy.at(1).at(0).toModelIndex().row(), int(LatestValuesModel::QuatX));
        QCOMPARE(spy.at(1).at(1).toModelIndex().row(), int(LatestValuesModel::QuatY));
        QCOMPARE(value(m, LatestValuesModel::Pitch), QStringLiteral("1.50"));
    }

    void missingFieldsShowDash()
    {
        Sample s;
        s.source = "HI92";
        s.fields = imudesk::model::FieldAcc | imudesk::model::FieldGyr | imudesk::model::FieldEuler;
        s.acc = {0, 0, 1};
        s.roll = -0.0001; // rounds to zero without a minus sign
        LatestValuesModel m;
        m.refresh(s);
        QCOMPARE(value(m, LatestValuesModel::AccZ), QStringLiteral("1.0000"));
        QCOMPARE(value(m, LatestValuesModel::Roll), QStringLiteral("0.00"));
        for (auto row : {LatestValuesModel::MagX, LatestValuesModel::MagY, LatestValuesModel::MagZ,
                         LatestValuesModel::QuatW, LatestValuesModel::Pressure, LatestValuesModel::Temperature,
                         LatestValuesModel::DeviceTime, LatestValuesModel::StatusFlags})
            QCOMPARE(value(m, row), QStringLiteral("—"));
        QCOMPARE(value(m, LatestValuesModel::FrameType), QStringLiteral("HI92"));

        // Status present but no bit set.
        s.fields |= imudesk::model::FieldMainStatus;
        m.refresh(s);
        QCOMPARE(value(m, LatestValuesModel::StatusFlags), QStringLiteral("none (0x0000)"));
        // Back to nothing.
        m.refresh(std::nullopt);
        QCOMPARE(value(m, LatestValuesModel::AccZ), QStringLiteral("—"));
        QCOMPARE(value(m, LatestValuesModel::FrameType), QStringLiteral("—"));
    }

    void toolTipsGiveMeaningAndUnit()
    {
        LatestValuesModel m;
        for (int r = 0; r < LatestValuesModel::RowCount; ++r)
            for (int c = 0; c < LatestValuesModel::ColumnCount; ++c)
                QVERIFY(!m.index(r, c).data(Qt::ToolTipRole).toString().isEmpty());
        QVERIFY(m.index(LatestValuesModel::AccX, 1).data(Qt::ToolTipRole).toString().contains(QLatin1String("in G")));
        QVERIFY(m.index(LatestValuesModel::GyrY, 1).data(Qt::ToolTipRole).toString().contains(QLatin1String("deg/s")));
        QVERIFY(m.index(LatestValuesModel::MagZ, 0).data(Qt::ToolTipRole).toString().contains(QStringLiteral("µT")));
        QVERIFY(m.index(LatestValuesModel::Pressure, 2).data(Qt::ToolTipRole).toString().contains(QLatin1String("Pa")));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstLatestValuesModel)
#include "tst_latest_values_model.moc"
