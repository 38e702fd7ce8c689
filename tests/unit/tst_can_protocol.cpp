// CAN codecs: J1939 identifiers, data PGNs and the configuration protocol (v1.7.1 manual
// chapter 7, v1.6.6 chapter 6), CANopen TPDO/SDO/NMT/SYNC/heartbeat (v1.7.1 chapter 8, v1.6.6
// chapter 5), HEC495 PDOs and SDO writes (HEC495 manual "CAN 通讯协议"), with the manuals'
// examples byte for byte.
#include "protocol/can/can_decoder.h"
#include "protocol/can/can_record.h"
#include "protocol/can/canopen.h"
#include "protocol/can/hec495_can.h"
#include "protocol/can/hipnuc_canopen_objects.h"
#include "protocol/can/j1939.h"
#include "protocol/can/j1939_config.h"
#include "protocol/can/sdo.h"
#include "protocol/can/sdo_segmented_download.h"
#include "../common/test_main.h"
#include "format/sample_json.h"

#include <QTest>

#include <random>

using namespace imudesk::protocol::can;
using imudesk::model::Sample;

namespace {
QByteArray hex(const char *h) { return QByteArray::fromHex(h); }
bool near(double a, double b, double tol) { return std::abs(a - b) <= tol; }
} // namespace

class TstCanProtocol : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void j1939IdFields_data()
    {
        QTest::addColumn<uint>("id");
        QTest::addColumn<int>("priority");
        QTest::addColumn<uint>("pgn");
        QTest::addColumn<int>("sa");
        QTest::addColumn<int>("da");
        // 7.19.28 formula; 7.21 data IDs; 7.23 configuration example; notes 4.1 DBC id.
        QTest::newRow("time 0x0CFF2F08") << 0x0CFF2F08u << 3 << 0xFF2Fu << 8 << 0xFF;
        QTest::newRow("acc 0x0CFF3408") << 0x0CFF3408u << 3 << 0xFF34u << 8 << 0xFF;
        QTest::newRow("config 0x0CEF0855") << 0x0CEF0855u << 3 << 0xEF00u << 0x55 << 8;
        QTest::newRow("reply 0x0CEF5508") << 0x0CEF5508u << 3 << 0xEF00u << 8 << 0x55;
        QTest::newRow("dbc 0x0CFF1008") << 0x0CFF1008u << 3 << 0xFF10u << 8 << 0xFF;
    }
    void j1939IdFields()
    {
        QFETCH(uint, id);
        QFETCH(int, priority);
        QFETCH(uint, pgn);
        QFETCH(int, sa);
        QFETCH(int, da);
        const j1939::Id f = j1939::parseId(id);
        QCOMPARE(int(f.priority), priority);
        QCOMPARE(f.pgn(), pgn);
        QCOMPARE(int(f.sa), sa);
        QCOMPARE(int(f.destination()), da);
        QCOMPARE(j1939::makeId(uint8_t(priority), pgn, uint8_t(sa), uint8_t(da)), id);
    }

    // 7.21.31 / 7.24.41.18: 0x0CFF2F08 18 06 12 0E 1E 2D 58 02 -> 2024-06-18 14:30:45.600.
    void j1939TimeExample()
    {
        const CanFrame f = CanFrame::fromHex(0x0CFF2F08, true, "1806120E1E2D5802");
        const auto r = j1939::decodeData(f);
        QVERIFY(r.ok());
        QVERIFY(r.data.time.has_value());
        const j1939::UtcTime t = *r.data.time;
        QCOMPARE(t, (j1939::UtcTime{2024, 6, 18, 14, 30, 45, 600}));
        QCOMPARE(j1939::encodeTime(8, t), f);
        CanDecoder d;
        const DecodedFrame decoded = d.decode(f);
        QVERIFY(decoded.meaning.contains(QStringLiteral("2024-06-18 14:30:45.600")));
        // The time of day reaches the samples (values table, recording, JSON) like the serial
        // side's UTC: 14:30:45.600 = 52245.6 s after midnight.
        QVERIFY(decoded.sample.has_value());
        QCOMPARE(decoded.sample->utcTimeOfDayS, 52245.6);
        QVERIFY(decoded.sample->has(imudesk::model::FieldGnss));
        QCOMPARE(decoded.components, uint32_t(CompUtcTime));
        QVERIFY(QString::fromStdString(imudesk::format::sampleToJson(*decoded.sample)).contains(QStringLiteral("\"utc_time_s\":52245.6")));
    }

    // A time frame without a date (v1.6.6 6.1.1: year byte 20, month 0, day 0 when the module
    // has no UTC; the zero date of a v1.7.1 module without GNSS time) carries the module's own
    // clock: no UTC time of day reaches the samples, and the monitor says "date unknown".
    void j1939TimeDateUnknown_data()
    {
        QTest::addColumn<QByteArray>("data");
        QTest::newRow("v1.6.6 year 20, month 0, day 0") << QByteArray("1400000E1E2D5802");
        QTest::newRow("zero date") << QByteArray("0000000102035802");
        QTest::newRow("month 0") << QByteArray("1800120E1E2D5802");
        QTest::newRow("day 0") << QByteArray("1806000E1E2D5802");
    }
    void j1939TimeDateUnknown()
    {
        QFETCH(QByteArray, data);
        const CanFrame f = CanFrame::fromHex(0x0CFF2F08, true, data.constData());
        const auto r = j1939::decodeData(f);
        QVERIFY(r.ok() && r.data.time.has_value());
        QVERIFY(!r.data.time->dateKnown());
        CanDecoder d;
        const DecodedFrame decoded = d.decode(f);
        QCOMPARE(decoded.kind, FrameKind::J1939Data);
        QCOMPARE(decoded.node, 8);
        QVERIFY2(decoded.meaning.contains(QStringLiteral("date unknown, not UTC")), qPrintable(decoded.meaning));
        QVERIFY(!decoded.sample.has_value());
        QCOMPARE(decoded.components, 0u);
        QVERIFY((j1939::UtcTime{2024, 6, 18, 14, 30, 45, 600}).dateKnown());
    }

    void j1939DataPgns_data()
    {
        QTest::addColumn<uint>("id");
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<QString>("field");
        QTest::addColumn<double>("a");
        QTest::addColumn<double>("b");
        QTest::addColumn<double>("c");
        // Scales of 7.21.32-7.21.38.
        QTest::newRow("acc 1 G on z") << 0x0CFF3408u << hex("0000000000080000") << "acc" << 0.0 << 0.0 << 1.0;
        QTest::newRow("acc -0.5 G x") << 0x0CFF3408u << hex("00FC000000000000") << "acc" << -0.5 << 0.0 << 0.0;
        QTest::newRow("gyr 0x4000 = 1000 dps") << 0x0CFF3708u << hex("004000C000000000") << "gyr" << 1000.0 << -1000.0 << 0.0;
        QTest::newRow("mag 1000 = 30.5 uT") << 0x0CFF3A08u << hex("E803000018FC0000") << "mag" << 30.517578125 << 0.0 << -30.517578125;
        QTest::newRow("roll/pitch") << 0x0CFF3D08u << hex("39300000C7CFFFFF") << "euler" << 12.345 << -12.345 << 0.0;
        QTest::newRow("heading 90 CW both words") << 0x0CFF4108u << hex("905F010070A0FEFF") << "yaw" << -90.0 << 0.0 << 0.0;
        QTest::newRow("heading 270 v1.6.6 4 bytes") << 0x0CFF4108u << hex("B01E0400") << "yaw" << 90.0 << 0.0 << 0.0;
        QTest::newRow("quat identity") << 0x0CFF4608u << hex("1027000000000000") << "quat" << 1.0 << 0.0 << 0.0;
        QTest::newRow("inclinometer") << 0x0CFF4A08u << hex("E8030000F0D8FFFF") << "incl" << 1.0 << -10.0 << 0.0;
    }
    void j1939DataPgns()
    {
        QFETCH(uint, id);
        QFETCH(QByteArray, data);
        QFETCH(QString, field);
        QFETCH(double, a);
        QFETCH(double, b);
        QFETCH(double, c);
        const CanFrame f = CanFrame::fromBytes(id, true, reinterpret_cast<const uint8_t *>(data.constData()), size_t(data.size()));
        const auto r = j1939::decodeData(f);
        QVERIFY2(r.ok(), j1939::errorName(r.error));
        const Sample &s = r.data.sample;
        const double tol = 1e-9;
        if (field == QLatin1String("acc")) {
            QVERIFY(s.has(imudesk::model::FieldAcc));
            QVERIFY(near(s.acc.x, a, tol) && near(s.acc.y, b, tol) && near(s.acc.z, c, tol));
        } else if (field == QLatin1String("gyr")) {
            QVERIFY(near(s.gyr.x, a, tol) && near(s.gyr.y, b, tol) && near(s.gyr.z, c, tol));
        } else if (field == QLatin1String("mag")) {
            QVERIFY(near(s.mag.x, a, tol) && near(s.mag.y, b, tol) && near(s.mag.z, c, tol));
        } else if (field == QLatin1String("euler")) {
            QVERIFY(near(s.roll, a, tol) && near(s.pitch, b, tol));
        } else if (field == QLatin1String("yaw")) {
            QVERIFY(near(s.yaw, a, tol));
            QCOMPARE(r.data.hasYawPm180, f.len == 8);
        } else if (field == QLatin1String("quat")) {
            QVERIFY(near(s.quat.w, a, tol) && near(s.quat.x, b, tol));
        } else if (field == QLatin1String("incl")) {
            QVERIFY(near(s.inclinationX, a, tol) && near(s.inclinationY, b, tol));
        }
        // Round trip through the encoder (the simulator's path); FF41 in its 8-byte form.
        if (f.len == 8) {
            const CanFrame back = j1939::encodeData(r.data.pgn, 8, s);
            QCOMPARE(back.payload(), f.payload());
        }
    }

    void j1939Rejects()
    {
        QCOMPARE(j1939::decodeData(CanFrame::fromHex(0x188, false, "4A001F00C803")).error, j1939::DecodeError::NotExtended);
        QCOMPARE(j1939::decodeData(CanFrame::fromHex(0x0CFF3408, true, "0000")).error, j1939::DecodeError::TooShort);
        QCOMPARE(j1939::decodeData(CanFrame::fromHex(0x0CFF9908, true, "0000000000000000")).error, j1939::DecodeError::NotDataPgn);
        QCOMPARE(j1939::decodeData(CanFrame::fromHex(0x0CFF5A08, true, "0000000000000000")).error, j1939::DecodeError::TooShort);
    }

    // 7.21.39: the 64-byte CAN FD frame, encoded from a sample and decoded back.
    void j1939CanFdFrame()
    {
        Sample s;
        s.mainStatus = 0x1508;
        s.deviceTimeMs = 1840392;
        s.acc = {0.25, -0.5, 1.0};
        s.gyr = {10.0, -20.0, 30.0};
        s.mag = {15.0, -30.0, 45.0};
        s.roll = 13.052;
        s.pitch = -12.188;
        s.yaw = -122.477;
        s.quat = {0.5, -0.5, 0.5, -0.5};
        s.temperatureC = 35.25;
        const CanFrame f = j1939::encodeData(j1939::PgnCanFd0, 8, s);
        QCOMPARE(int(f.len), 64);
        QVERIFY(f.fd);
        QCOMPARE(f.id, 0x0CFF5A08u);
        QCOMPARE(u16At(f, 0), uint16_t(0x1508));
        QCOMPARE(u32At(f, 4), uint32_t(1840392));
        const auto r = j1939::decodeData(f);
        QVERIFY(r.ok());
        const Sample &d = r.data.sample;
        QCOMPARE(d.mainStatus, uint16_t(0x1508));
        QCOMPARE(d.deviceTimeMs, 1840392.0);
        QVERIFY(near(d.acc.z, 1.0, 1e-9) && near(d.gyr.y, -20.0, 0.031) && near(d.mag.z, 45.0, 0.016));
        QVERIFY(near(d.roll, 13.052, 1e-9) && near(d.yaw, -122.477, 1e-9));
        QVERIFY(near(d.quat.w, 0.5, 1e-9) && near(d.temperatureC, 35.25, 1e-9));
    }

    // 7.23 and v1.6.6 6.2.2: configuration frames, byte for byte.
    void j1939ConfigExamples_data()
    {
        QTest::addColumn<QByteArray>("expected");
        QTest::addColumn<uint>("id");
        QTest::addColumn<int>("addr");
        QTest::addColumn<uint>("value");
        QTest::newRow("gyr 100 ms (7.23 example)") << hex("3701060064000000") << 0x0CEF0855u << 0x0137 << 100u;
        QTest::newRow("time interval") << hex("2F010600E8030000") << 0x0CEF0855u << 0x012F << 1000u;
        QTest::newRow("acc interval") << hex("3401060005000000") << 0x0CEF0855u << 0x0134 << 5u;
        QTest::newRow("trigger acc") << hex("9600060034FF0000") << 0x0CEF0855u << 0x0096 << 0xFF34u;
        QTest::newRow("enable output") << hex("9D00060001000000") << 0x0CEF0855u << 0x009D << 1u;
        QTest::newRow("disable output") << hex("9D00060000000000") << 0x0CEF0855u << 0x009D << 0u;
        QTest::newRow("save") << hex("0000060000000000") << 0x0CEF0855u << 0x0000 << 0u;
        QTest::newRow("factory") << hex("0000060001000000") << 0x0CEF0855u << 0x0000 << 1u;
        QTest::newRow("reset") << hex("00000600FF000000") << 0x0CEF0855u << 0x0000 << 0xFFu;
        QTest::newRow("baud 250K") << hex("9A00060003000000") << 0x0CEF0855u << 0x009A << 3u;
        QTest::newRow("node id 9") << hex("9C00060009000000") << 0x0CEF0855u << 0x009C << 9u;
        QTest::newRow("heading reset") << hex("A500060001000000") << 0x0CEF0855u << 0x00A5 << 1u;
        QTest::newRow("incl X reversed") << hex("9E00060001000000") << 0x0CEF0855u << 0x009E << 1u;
        QTest::newRow("incl Y default") << hex("9F00060000000000") << 0x0CEF0855u << 0x009F << 0u;
        QTest::newRow("notes write 0x42") << hex("4200060078563412") << 0x0CEF0855u << 0x0042 << 0x12345678u;
    }
    void j1939ConfigExamples()
    {
        QFETCH(QByteArray, expected);
        QFETCH(uint, id);
        QFETCH(int, addr);
        QFETCH(uint, value);
        const CanFrame f = j1939::encodeReg(j1939::writeRequest(8, 0x55, uint16_t(addr), value));
        QCOMPARE(f.id, id);
        QVERIFY(f.extended);
        QCOMPARE(f.payload(), expected);
        const auto m = j1939::parseReg(f);
        QVERIFY(m);
        QCOMPARE(int(m->addr), addr);
        QCOMPARE(m->value, value);
        QCOMPARE(int(m->cmd), int(j1939::CmdWrite));
    }

    void j1939ConfigSemantics()
    {
        // 7.23 example means "gyro PGN at 100 ms".
        const auto m = j1939::parseReg(CanFrame::fromHex(0x0CEF0855, true, "3701060064000000"));
        QVERIFY(m);
        QCOMPARE(m->da, uint8_t(8));
        QCOMPARE(m->sa, uint8_t(0x55));
        QCOMPARE(j1939::pgnOfIntervalRegister(m->addr).value_or(0), uint32_t(j1939::PgnGyr));
        QCOMPARE(m->value, 100u);
        QCOMPARE(j1939::describe(*m), QStringLiteral("write PGN FF37 interval = 100 ms"));
        QCOMPARE(j1939::encodeReg(j1939::intervalRequest(8, 0x55, j1939::PgnGyr, 100)).payload(), hex("3701060064000000"));
        // Read request (notes 4.3) and the reply matching.
        const auto rd = j1939::readRequest(8, 0x55, 0x0001);
        QCOMPARE(j1939::encodeReg(rd).payload(), hex("0100030001000000"));
        j1939::RegMessage reply{0x55, 8, 0x0001, j1939::CmdRead, 0, 42};
        QCOMPARE(j1939::encodeReg(reply).id, 0x0CEF5508u);
        QVERIFY(j1939::answers(reply, rd));
        reply.sa = 9;
        QVERIFY(!j1939::answers(reply, rd));
        QVERIFY(j1939::validInterval(5) && j1939::validInterval(1000));
        QVERIFY(!j1939::validInterval(4) && !j1939::validInterval(1001));
        QCOMPARE(j1939::baudFromCode(2), 500000);
        QCOMPARE(j1939::codeFromBaud(800000), 1);
        QVERIFY(!j1939::pgnOfIntervalRegister(0x0096));
    }

    // 8.26.42: TPDO examples.
    void canopenTpdoExamples()
    {
        const auto acc = canopen::decodeTpdo(CanFrame::fromHex(0x188, false, "4A001F00C803"));
        QVERIFY(acc.ok());
        QCOMPARE(int(acc.node), 8);
        QCOMPARE(acc.channel, 0);
        QVERIFY(near(acc.sample.acc.x, 0.074, 1e-12) && near(acc.sample.acc.y, 0.031, 1e-12) && near(acc.sample.acc.z, 0.968, 1e-12));
        const auto gyr = canopen::decodeTpdo(CanFrame::fromHex(0x288, false, "150014013400"));
        QVERIFY(gyr.ok());
        QVERIFY(near(gyr.sample.gyr.x, 2.1, 1e-12) && near(gyr.sample.gyr.y, 27.6, 1e-12) && near(gyr.sample.gyr.z, 5.2, 1e-12));
        QCOMPARE(canopen::encodeTpdo(0, 8, acc.sample).payload(), hex("4A001F00C803"));
        QCOMPARE(canopen::encodeTpdo(1, 8, gyr.sample).payload(), hex("150014013400"));
        // 8.27 PCAN-View capture rows.
        const auto q = canopen::decodeTpdo(CanFrame::fromHex(0x488, false, "E026FB020E021A01"));
        QVERIFY(q.ok());
        QVERIFY(near(q.sample.quat.w, 0.9952, 1e-12) && near(q.sample.quat.z, 0.0282, 1e-12));
        const auto e = canopen::decodeTpdo(CanFrame::fromHex(0x388, false, "48027B031701"));
        QVERIFY(near(e.sample.roll, 5.84, 1e-12) && near(e.sample.pitch, 8.91, 1e-12) && near(e.sample.yaw, 2.79, 1e-12));
        const auto p = canopen::decodeTpdo(CanFrame::fromHex(0x688, false, "A0860100"));
        QVERIFY(p.ok() && p.sample.pressurePa == 100000.0);
        const auto i = canopen::decodeTpdo(CanFrame::fromHex(0x788, false, "E8030000F0D8FFFF"));
        QVERIFY(i.ok() && near(i.sample.inclinationX, 10.0, 1e-12) && near(i.sample.inclinationY, -100.0, 1e-12));
        QCOMPARE(canopen::decodeTpdo(CanFrame::fromHex(0x188, false, "4A001F00C80300")).error, canopen::TpdoError::WrongLength);
        QCOMPARE(canopen::decodeTpdo(CanFrame::fromHex(0x588, false, "4A001F00C803")).error, canopen::TpdoError::NotTpdo);
    }

    // Chapter 8.28 (v1.7.1) and 5.4 (v1.6.6): every SDO request, byte for byte.
    void sdoManualExamples_data()
    {
        QTest::addColumn<QByteArray>("built");
        QTest::addColumn<QByteArray>("manual");
        using namespace canopen::hipnuc;
        auto row = [](const char *name, const CanFrame &f, const char *manual) {
            QCOMPARE(f.id, 0x608u);
            QTest::newRow(name) << f.payload() << hex(manual);
        };
        row("node id 0x209C = 9", setNodeId(8, 9), "239C200009000000");
        row("v1.6.6 node id 0x20A0 = 9", setNodeId(8, 9, ObjNodeIdV166), "23A0200009000000");
        // A node-ID write moved to the v1.6.6 object.
        row("node id 0x209C moved to 0x20A0", retarget(setNodeId(8, 9), ObjNodeIdV166), "23A0200009000000");
        row("save", command(8, CommandSave), "2300200000000000");
        row("reset", command(8, CommandReset), "23002000FF000000");
        row("factory", command(8, CommandFactory), "2300200001000000");
        row("baud 1000K", setBaud(8, 0), "239A200000000000");
        row("baud 500K", setBaud(8, 2), "239A200002000000");
        row("baud 250K", setBaud(8, 3), "239A200003000000");
        row("baud 125K", setBaud(8, 4), "239A200004000000");
        // 8.28.45.24: 1800..1804 sub 5 = 0, 5, 10, 20, 50, 100 ms.
        static const char *rates[5][6] = {
            {"2B00180500000000", "2B00180505000000", "2B0018050A000000", "2B00180514000000", "2B00180532000000", "2B00180564000000"},
            {"2B01180500000000", "2B01180505000000", "2B0118050A000000", "2B01180514000000", "2B01180532000000", "2B01180564000000"},
            {"2B02180500000000", "2B02180505000000", "2B0218050A000000", "2B02180514000000", "2B02180532000000", "2B02180564000000"},
            {"2B03180500000000", "2B03180505000000", "2B0318050A000000", "2B03180514000000", "2B03180532000000", "2B03180564000000"},
            {"2B04180500000000", "2B04180505000000", "2B0418050A000000", "2B04180514000000", "2B04180532000000", "2B04180564000000"},
        };
        static const uint16_t periods[6] = {0, 5, 10, 20, 50, 100};
        for (int c = 0; c < 5; ++c)
            for (int k = 0; k < 6; ++k) {
                const QByteArray name = QByteArrayLiteral("TPDO rate 0x180") + QByteArray::number(c) + QByteArrayLiteral(".5=")
                    + QByteArray::number(periods[k]);
                QTest::newRow(name.constData()) << setTpdoPeriod(8, c, periods[k]).payload() << hex(rates[c][k]);
            }
        row("incl zero set", setInclZero(8, 2), "23A5200002000000");
        row("incl zero clear", setInclZero(8, 5), "23A5200005000000");
        row("sync mode", setTransmissionType(8, 0, kTransmissionSync), "2F00180201000000");
        row("async mode", setTransmissionType(8, 0, kTransmissionAsync), "2F001802FF000000");
        row("heartbeat 100 ms", setHeartbeat(8, 100), "2B17100064000000");
        row("v1.6.6 incl X default", setInclSign(8, false, false), "239E200000000000");
        row("v1.6.6 incl X reversed", setInclSign(8, false, true), "239E200001000000");
        row("v1.6.6 incl Y default", setInclSign(8, true, false), "239F200000000000");
        row("v1.6.6 incl Y reversed", setInclSign(8, true, true), "239F200001000000");
    }
    void sdoManualExamples()
    {
        QFETCH(QByteArray, built);
        QFETCH(QByteArray, manual);
        QCOMPARE(built.toHex(' '), manual.toHex(' '));
        const auto m = canopen::parseSdo(CanFrame::fromBytes(0x608, false, reinterpret_cast<const uint8_t *>(manual.constData()), 8));
        QVERIFY(m);
        QCOMPARE(m->kind, canopen::SdoKind::DownloadExpedited);
        QCOMPARE(int(m->node), 8);
    }

    // The node-ID object by the firmware version the module reports (0x1018:3, major << 16 |
    // minor << 8 | patch): 0x20A0 up to 1.6.x (v1.6.6 5.4.1), 0x209C from 1.7 (v1.7.1 8.28).
    void nodeIdObjectByRevision()
    {
        using namespace canopen::hipnuc;
        QCOMPARE(nodeIdObjectOfRevision(0x010606), std::optional<uint16_t>(ObjNodeIdV166));
        QCOMPARE(nodeIdObjectOfRevision(0x010505), std::optional<uint16_t>(ObjNodeIdV166));
        QCOMPARE(nodeIdObjectOfRevision(0x010701), std::optional<uint16_t>(ObjNodeId));
        QCOMPARE(nodeIdObjectOfRevision(0x010700), std::optional<uint16_t>(ObjNodeId));
        QCOMPARE(nodeIdObjectOfRevision(0), std::nullopt);
        QVERIFY(isNodeIdObject(0x209C) && isNodeIdObject(0x20A0) && !isNodeIdObject(0x209A));
        QVERIFY(isV166Revision(0x010606) && !isV166Revision(0x010701) && !isV166Revision(0));
        const CanFrame read = readRevision(8); // CiA 301 upload request: 40, index, sub
        QCOMPARE(read.id, 0x608u);
        QCOMPARE(read.payload().toHex().toUpper(), QByteArray("4018100300000000"));
    }

    void sdoReplyAndAbort()
    {
        using namespace canopen;
        // 8.28.43: reply 0x580 + ID, 0x60.
        const CanFrame ok = sdoWriteReply(8, 0x1800, 5);
        QCOMPARE(ok.id, 0x588u);
        QCOMPARE(ok.payload(), hex("6000180500000000"));
        const auto req = parseSdo(hipnuc::setTpdoPeriod(8, 0, 10));
        const auto rep = parseSdo(ok);
        QVERIFY(req && rep && sdoAnswers(*rep, *req));
        QCOMPARE(rep->kind, SdoKind::DownloadReply);
        // Upload.
        QCOMPARE(sdoRead(8, 0x1017, 0).payload(), hex("4017100000000000"));
        const auto up = parseSdo(sdoReadReply(8, 0x1017, 0, 100, 2));
        QVERIFY(up && up->kind == SdoKind::UploadExpedited && up->size == 2 && up->value == 100);
        QCOMPARE(sdoReadReply(8, 0x1017, 0, 100, 2).payload(), hex("4B17100064000000"));
        // Abort.
        const auto ab = parseSdo(sdoAbortFrame(8, 0x2000, 0, AbortNoObject));
        QVERIFY(ab && ab->kind == SdoKind::Abort && ab->value == AbortNoObject);
        QCOMPARE(sdoAbortFrame(8, 0x2000, 0, AbortNoObject).payload(), hex("8000200000000206"));
        QVERIFY(abortText(AbortNoObject).contains(QStringLiteral("does not exist")));
        QVERIFY(abortText(0x12345678).contains(QStringLiteral("12345678")));
        // HEC495 unsized write 0x22.
        const auto hw = parseSdo(sdoWriteUnsized(5, 0x1010, 0, 0x10));
        QVERIFY(hw && hw->kind == SdoKind::DownloadExpedited && hw->size == 0);
    }

    // Notes 4.5: the vendor test's happy path, 20 bytes A0..B3, HiPNUC last-segment convention.
    void sdoSegmentedDownload()
    {
        using namespace canopen;
        std::vector<uint8_t> image;
        for (int i = 0; i < 20; ++i)
            image.push_back(uint8_t(0xA0 + i));
        SdoSegmentedDownload dl(8, 0x1F51, 1, image);
        QCOMPARE(dl.start().payload(), hex("21511F0114000000"));
        QVERIFY(dl.onFrame(CanFrame::fromHex(0x588, false, "60511F0100000000")));
        QCOMPARE(dl.next().payload(), hex("00A0A1A2A3A4A5A6"));
        QVERIFY(!dl.onFrame(CanFrame::fromHex(0x589, false, "2000000000000000"))); // other node
        QVERIFY(dl.onFrame(CanFrame::fromHex(0x588, false, "2000000000000000")));
        QCOMPARE(dl.next().payload(), hex("10A7A8A9AAABACAD"));
        QVERIFY(dl.onFrame(CanFrame::fromHex(0x588, false, "3000000000000000")));
        QCOMPARE(dl.next().payload(), hex("05AEAFB0B1B2B300"));
        QCOMPARE(dl.status(), SdoSegmentedDownload::Status::Running);
        QVERIFY(dl.onFrame(CanFrame::fromHex(0x588, false, "2000000000000000")));
        QCOMPARE(dl.status(), SdoSegmentedDownload::Status::Done);
        QCOMPARE(dl.percent(), 100);
        // CiA 301 last segment: n = 6 -> 0x03; HiPNUC n = 7 -> 0x03, n = 1 -> 0x0F.
        QCOMPARE(SdoSegmentedDownload::segmentCs(6, false, true, SdoSegmentedDownload::LastSegment::Cia301), uint8_t(0x03));
        QCOMPARE(SdoSegmentedDownload::segmentCs(7, false, true, SdoSegmentedDownload::LastSegment::Hipnuc), uint8_t(0x03));
        QCOMPARE(SdoSegmentedDownload::segmentCs(1, true, true, SdoSegmentedDownload::LastSegment::Hipnuc), uint8_t(0x1F));
        // Wrong toggle and abort fail the transfer.
        SdoSegmentedDownload bad(8, 0x1F51, 1, image);
        bad.start();
        bad.onFrame(CanFrame::fromHex(0x588, false, "60511F0100000000"));
        QVERIFY(bad.onFrame(CanFrame::fromHex(0x588, false, "3000000000000000")));
        QCOMPARE(bad.status(), SdoSegmentedDownload::Status::Failed);
        SdoSegmentedDownload ab(8, 0x1F51, 1, image);
        ab.start();
        QVERIFY(ab.onFrame(sdoAbortFrame(8, 0x1F51, 1, AbortGeneral)));
        QCOMPARE(ab.status(), SdoSegmentedDownload::Status::Failed);
        QCOMPARE(ab.abortCode(), uint32_t(AbortGeneral));
    }

    void nmtSyncHeartbeat()
    {
        using namespace canopen;
        QCOMPARE(encodeSync().id, 0x80u); // 8.28.46.27: ID 0x80, no data
        QCOMPARE(int(encodeSync().len), 0);
        QVERIFY(isSync(encodeSync()));
        const auto n = parseNmt(encodeNmt(NmtResetNode, 8));
        QVERIFY(n && n->command == NmtResetNode && n->node == 8);
        const auto hb = parseHeartbeat(encodeHeartbeat(8, StateOperational));
        QVERIFY(hb && hb->node == 8 && hb->state == StateOperational);
        QCOMPARE(encodeHeartbeat(8, StateBootUp).id, 0x708u);
        QVERIFY(!parseHeartbeat(CanFrame::fromHex(0x708, false, "0500")));
    }

    // HEC495 manual: fixed-point examples and the SDO tables.
    void hec495FixedPoint_data()
    {
        QTest::addColumn<QByteArray>("three");
        QTest::addColumn<double>("divisor");
        QTest::addColumn<double>("value");
        QTest::newRow("angle 26 15 01 = -54.14") << hex("261501") << 100.0 << -54.14;
        QTest::newRow("acc 18 00 01 = -0.0024") << hex("180001") << 10000.0 << -0.0024;
        QTest::newRow("positive") << hex("261500") << 100.0 << 54.14;
    }
    void hec495FixedPoint()
    {
        QFETCH(QByteArray, three);
        QFETCH(double, divisor);
        QFETCH(double, value);
        const auto *b = reinterpret_cast<const uint8_t *>(three.constData());
        QVERIFY(near(hec495::fixedValue(b, divisor), value, 1e-12));
        uint8_t back[3];
        hec495::putFixed(back, value, divisor);
        QCOMPARE(QByteArray(reinterpret_cast<const char *>(back), 3), three);
    }

    void hec495Pdos()
    {
        // 0x185: X angle -54.14, X acc -0.0024 in fixed mode.
        const auto fx = hec495::decodePdo(CanFrame::fromHex(0x185, false, "2615011800010000"));
        QVERIFY(fx && fx->fixed);
        QCOMPARE(int(fx->node), 5);
        QVERIFY(near(fx->sample.pitch, -54.14, 1e-12) && near(fx->sample.acc.x, -0.0024, 1e-12));
        // Float mode: 0x185 = X angle 3.5, Y angle -20.4 (the Modbus example's floats).
        const auto fl = hec495::decodePdo(CanFrame::fromHex(0x185, false, "000060403333A3C1"));
        QVERIFY(fl && !fl->fixed);
        QVERIFY(near(fl->sample.pitch, 3.5, 1e-6) && near(fl->sample.roll, -20.4, 1e-5));
        QCOMPARE(hec495::pdoSlotOfId(0x1C5), 4);
        QCOMPARE(hec495::pdoSlotOfId(0x2C5), 5);
        QCOMPARE(hec495::pdoSlotOfId(0x485), 3);
        // Round trip of all slots in both modes.
        Sample s;
        s.pitch = 12.34; s.roll = -5.67; s.yaw = 123.45;
        s.acc = {0.1234, -0.5678, 0.9}; s.gyr = {1.5, -2.25, 3.0}; s.magRelative = {0.25, -0.3, 0.45};
        // The field is relative on CAN as in the serial read-all record (2.5): never Sample::mag (uT).
        const auto magYz = hec495::decodePdo(hec495::encodePdo(5, 5, s, false), 0);
        QVERIFY(magYz && magYz->sample.has(imudesk::model::FieldMagRelative) && !magYz->sample.has(imudesk::model::FieldMag));
        QVERIFY(near(magYz->sample.magRelative.y, -0.3, 1e-6) && near(magYz->sample.magRelative.z, 0.45, 1e-6));
        for (bool fixed : {false, true})
            for (int slot = 0; slot < hec495::kPdoCount; ++slot) {
                const auto r = hec495::decodePdo(hec495::encodePdo(slot, 5, s, fixed), fixed ? 1 : 0);
                QVERIFY(r && r->slot == slot);
                QCOMPARE(hec495::encodePdo(slot, 5, r->sample, fixed), hec495::encodePdo(slot, 5, s, fixed));
            }
        const auto ext = hec495::decodeExtended(hec495::encodeExtended(true, s));
        QVERIFY(ext && near(ext->sample.roll, -5.67, 1e-12) && near(ext->sample.acc.y, -0.5678, 1e-12));
    }

    void hec495Sdo_data()
    {
        QTest::addColumn<QByteArray>("built");
        QTest::addColumn<uint>("id");
        QTest::addColumn<QByteArray>("manual");
        using namespace hec495;
        QTest::newRow("node 0x10") << writeRequest(5, ObjNodeId, 0x10).payload() << 0x605u << hex("2210100010000000");
        QTest::newRow("node reply") << writeReply(5, ObjNodeId).payload() << 0x585u << hex("6010100000000000");
        QTest::newRow("baud 250K") << writeRequest(5, ObjBaud, 2).payload() << 0x605u << hex("2220100002000000");
        QTest::newRow("fixed mode") << writeRequest(5, ObjPdoMode, 1).payload() << 0x605u << hex("2280100001000000");
        QTest::newRow("heartbeat N=9") << writeRequest(5, ObjHeartbeat, 9).payload() << 0x605u << hex("2217100009000000");
        QTest::newRow("rate 100 Hz") << writeRequest(5, ObjPdoRate, 6).payload() << 0x605u << hex("2200620006000000");
        QTest::newRow("work mode 2") << writeRequest(5, ObjWorkMode, 2).payload() << 0x605u << hex("2245620002000000");
        QTest::newRow("start PDO") << writeRequest(5, ObjPdoStart, 1).payload() << 0x605u << hex("2283100001000000");
        QTest::newRow("ext baud") << writeRequest(0, ObjBaud, 2, true).payload() << kExtRequestId << hex("2220100002000000");
        QTest::newRow("ext reply") << writeReply(0, ObjBaud, true).payload() << kExtReplyId << hex("6020100000000000");
        QTest::newRow("start all") << startAll().payload() << 0x000u << hex("0100");
        QTest::newRow("stop all") << stopAll().payload() << 0x000u << hex("0200");
    }
    void hec495Sdo()
    {
        QFETCH(QByteArray, built);
        QFETCH(QByteArray, manual);
        QCOMPARE(built.toHex(' '), manual.toHex(' '));
        QCOMPARE(hec495::baudFromCode(2), 250000);
        QCOMPARE(hec495::heartbeatPeriodMs(9), 1000);
        QCOMPARE(hec495::rateHzFromCode(1), 5.0);
        // 100 ms * (N + 1): the nearest N, half-way up; no "off" below 100 ms, none above N = 255.
        QCOMPARE(hec495::heartbeatCode(1000), std::optional<uint8_t>(9)); // the default, 1 s
        QCOMPARE(hec495::heartbeatCode(100), std::optional<uint8_t>(0));
        QCOMPARE(hec495::heartbeatCode(149), std::optional<uint8_t>(0));
        QCOMPARE(hec495::heartbeatCode(150), std::optional<uint8_t>(1));
        QCOMPARE(hec495::heartbeatCode(350), std::optional<uint8_t>(3));
        QCOMPARE(hec495::heartbeatCode(25600), std::optional<uint8_t>(255));
        QCOMPARE(hec495::heartbeatCode(0), std::nullopt);
        QCOMPARE(hec495::heartbeatCode(99), std::nullopt);
        QCOMPARE(hec495::heartbeatCode(25601), std::nullopt);
        for (int n = 0; n <= 255; ++n)
            QCOMPARE(hec495::heartbeatCode(hec495::heartbeatPeriodMs(uint32_t(n))), std::optional<uint8_t>(uint8_t(n)));
    }

    void decoderAutoDetect()
    {
        CanDecoder j;
        QVERIFY(j.decode(CanFrame::fromHex(0x0CFF3408, true, "0000000000080000")).sample);
        QCOMPARE(j.detected(), CanProtocol::J1939);
        CanDecoder c;
        const auto d = c.decode(CanFrame::fromHex(0x188, false, "4A001F00C803"));
        QCOMPARE(d.kind, FrameKind::TpdoData);
        QCOMPARE(c.detected(), CanProtocol::CanOpen);
        QVERIFY(d.meaning.contains(QStringLiteral("TPDO1")));
        CanDecoder h;
        QCOMPARE(h.decode(CanFrame::fromHex(0x185, false, "2615011800010000")).kind, FrameKind::Hec495Data);
        QCOMPARE(h.detected(), CanProtocol::Hec495);
        QCOMPARE(h.decode(hec495::writeReply(5, hec495::ObjPdoRate)).kind, FrameKind::Hec495Sdo);
        CanDecoder x;
        QCOMPARE(x.decode(hec495::encodeExtended(false, Sample{})).kind, FrameKind::Hec495Data);
        QCOMPARE(x.decode(CanFrame::fromHex(0x123, false, "01")).kind, FrameKind::Unknown);
        QCOMPARE(x.counters().unknownFrames, uint64_t(1));
    }

    // Random frames never crash the decoder, and each is classified exactly once.
    void decoderRandomFrames()
    {
        std::mt19937 rng(7);
        CanDecoder d;
        for (int i = 0; i < 20000; ++i) {
            CanFrame f;
            f.extended = rng() & 1;
            f.id = f.extended ? (rng() & 0x1FFFFFFF) : (rng() & 0x7FF);
            f.fd = (rng() & 7) == 0;
            f.len = uint8_t(rng() % (f.fd ? 65 : 9));
            for (int k = 0; k < f.len; ++k)
                f.data[size_t(k)] = uint8_t(rng());
            d.decode(f);
        }
        const auto &c = d.counters();
        QCOMPARE(c.frames, uint64_t(20000));
        QCOMPARE(c.dataFrames + c.configFrames + c.unknownFrames, c.frames);
    }

    // Frames as records on the session's transport: the bytes are as documented in
    // can_record.h, every kind of frame comes back equal, split anywhere, and noise in front
    // of a record is skipped byte by byte.
    void recordsCarryFramesWhole()
    {
        const CanFrame j1939 = CanFrame::fromHex(0x0CFF3408, true, "4A001F00C803FFFF");
        QCOMPARE(toRecord(j1939).toHex(), QByteArray("01080834ff0c4a001f00c803ffff"));
        CanFrame fd = CanFrame::fromBytes(0x123, false, reinterpret_cast<const uint8_t *>("0123456789abcdef0123"), 20,
                                          true);
        CanFrame remote(0x701, false, {});
        remote.remote = true;
        QByteArray stream = QByteArray::fromHex("ff40") + toRecord(j1939) + toRecord(fd) + toRecord(remote)
            + toRecord(CanFrame(0x20000080, true, {0x01}), true);
        CanRecordReader reader;
        std::vector<CanRecord> out;
        for (qsizetype at = 0; at < stream.size(); at += 5) // split in the middle of headers and data
            reader.feed(stream.mid(at, 5), out);
        QCOMPARE(out.size(), size_t(4));
        QCOMPARE(reader.bytesSkipped(), uint64_t(2));
        QVERIFY(!reader.holding());
        QVERIFY(out[0].frame == j1939 && !out[0].error);
        QVERIFY(out[1].frame == fd);
        QCOMPARE(int(out[1].frame.len), 20);
        QVERIFY(out[2].frame.remote && out[2].frame.len == 0 && out[2].frame.id == 0x701);
        QVERIFY(out[3].error);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCanProtocol)
#include "tst_can_protocol.moc"
