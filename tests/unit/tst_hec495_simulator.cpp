// The simulated HEC495: every command, settings kept until power-off unless saved, the
// auto-output window after power-on, baud and address changes, RS-485 half duplex, and the
// calibration methods collecting points in the poses of the manual's tables.
#include "protocol/witlink/commands.h"
#include "protocol/witlink/frame_decoder.h"
#include "protocol/witlink/reply.h"
#include "sim/hec495_simulator.h"
#include "../common/test_main.h"

#include <QTest>

#include <cmath>

using namespace imudesk::sim;
using namespace imudesk::protocol::witlink;
namespace cmd = imudesk::protocol::witlink::commands;

namespace {

struct Bench {
    explicit Bench(Hec495Options o = {}) : sim(o) {}
    Hec495Simulator sim;
    FrameDecoder dec;
    int64_t t = 0;
    std::vector<int> bauds; // baud of each reply byte chunk

    std::vector<Reply> run(int64_t us)
    {
        t += us;
        sim.advanceTo(t);
        std::vector<Reply> out;
        for (auto &s : sim.takeOutputSegments()) {
            bauds.push_back(s.baud);
            for (const auto &f : dec.feed(s.bytes))
                out.push_back(decodeReply(f));
        }
        return out;
    }
    std::vector<Reply> ask(const std::vector<uint8_t> &bytes, int64_t waitUs = 120000) // 89 bytes at 9600: 93 ms
    {
        sim.receive(bytes.data(), bytes.size());
        return run(waitUs);
    }
    Reply one(const std::vector<uint8_t> &bytes)
    {
        const auto r = ask(bytes);
        if (r.size() != 1)
            qFatal("expected one reply, got %d", int(r.size()));
        return r.front();
    }
};

double angleDiff(double a, double b)
{
    double d = std::fmod(a - b + 540.0, 360.0) - 180.0;
    return std::fabs(d);
}

} // namespace

class TstHec495Simulator : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void readCommands_data()
    {
        QTest::addColumn<QByteArray>("request");
        QTest::addColumn<int>("replyCommand");
        QTest::addColumn<int>("kind");
        auto b = [](const std::vector<uint8_t> &v) { return QByteArray(reinterpret_cast<const char *>(v.data()), qsizetype(v.size())); };
        QTest::newRow("pitch") << b(cmd::readPitch()) << 0x81 << int(Reply::Kind::Angle);
        QTest::newRow("roll") << b(cmd::readRoll()) << 0x82 << int(Reply::Kind::Angle);
        QTest::newRow("heading") << b(cmd::readHeading()) << 0x83 << int(Reply::Kind::Angle);
        QTest::newRow("angles") << b(cmd::readAngles()) << 0x84 << int(Reply::Kind::Angles);
        QTest::newRow("all") << b(cmd::readAll()) << 0x14 << int(Reply::Kind::AllData);
        QTest::newRow("declination") << b(cmd::readDeclination()) << 0x87 << int(Reply::Kind::Declination);
        QTest::newRow("address") << b(cmd::queryAddress()) << 0x1F << int(Reply::Kind::Address);
    }
    void readCommands()
    {
        QFETCH(QByteArray, request);
        QFETCH(int, replyCommand);
        QFETCH(int, kind);
        Bench b;
        b.run(100000);
        const Reply r = b.one(std::vector<uint8_t>(request.begin(), request.end()));
        QVERIFY(r.ok());
        QCOMPARE(int(r.command), replyCommand);
        QCOMPARE(int(r.kind), kind);
    }

    void valuesFollowTheMotion()
    {
        Bench b;
        b.sim.setPose(Hec495Calibration::Pose{120.0, 10.0, -20.0});
        b.run(50000);
        const Reply r = b.one(cmd::readAngles());
        QVERIFY(qAbs(r.pitch - 10.0) < 0.02);
        QVERIFY(qAbs(r.roll + 20.0) < 0.02);
        // Uncalibrated: the heading carries the iron error, but stays near the truth.
        QVERIFY(angleDiff(r.heading, 120.0) < 45.0);
        const Reply all = b.one(cmd::readAll());
        QVERIFY(qAbs(double(all.record.pitch) - 10.0) < 0.02);
        QVERIFY(qAbs(double(all.record.acc[2]) - std::cos(10 * M_PI / 180) * std::cos(20 * M_PI / 180)) < 0.01);
    }

    void settingsLostUnlessSaved()
    {
        Bench b;
        QVERIFY(b.one(cmd::setDeclination(-3.2)).success);
        QCOMPARE(b.one(cmd::readDeclination()).declination, -3.2);
        b.sim.powerCycle();
        QCOMPARE(b.one(cmd::readDeclination()).declination, 0.0);
        QVERIFY(b.one(cmd::setDeclination(20.8)).success);
        QVERIFY(b.one(cmd::saveSettings()).success);
        b.sim.powerCycle();
        QCOMPARE(b.one(cmd::readDeclination()).declination, 20.8);
    }

    void declinationShiftsHeading()
    {
        Bench b;
        b.sim.setPose(Hec495Calibration::Pose{200.0, 0, 0});
        const double h0 = b.one(cmd::readHeading()).angle;
        b.one(cmd::setDeclination(20.8));
        const double h1 = b.one(cmd::readHeading()).angle;
        QVERIFY(angleDiff(h1, h0 + 20.8) < 0.5);
    }

    void badArgumentsFail()
    {
        Bench b;
        Reply r = b.one(cmd::request(Command::SetBaud, 0, {0x09}));
        QVERIFY(r.ok());
        QVERIFY(!r.success);
        r = b.one(cmd::request(Command::SetOutputRate, 0, {0x07}));
        QVERIFY(!r.success);
        r = b.one(cmd::request(Command::SetDeclination, 0, {0x0A, 0x00}));
        QVERIFY(!r.success);
        QVERIFY(b.ask(encodeFrame(0, 0x55)).empty()); // unknown: silence
    }

    void noiseDoesNotSwallowTheNextCommand()
    {
        Bench b;
        // A false sync with a long LEN, then a pause, then a real command.
        QVERIFY(b.ask({0x77, 0x50, 0x01}).empty());
        QCOMPARE(b.one(cmd::readDeclination()).kind, Reply::Kind::Declination);
    }

    void baudChange()
    {
        Bench b;
        b.bauds.clear();
        const Reply r = b.one(cmd::setBaud(115200));
        QVERIFY(r.success);
        QCOMPARE(b.bauds, std::vector<int>{9600}); // the reply at the old rate
        QCOMPARE(b.sim.baud(), 115200);
        b.sim.powerCycle();
        QCOMPARE(b.sim.baud(), 9600); // not saved
    }

    void addressing()
    {
        Bench b;
        QVERIFY(b.ask(cmd::readAngles(5)).empty()); // someone else's
        const Reply set = b.one(cmd::setAddress(5));
        QVERIFY(set.success);
        QCOMPARE(set.address, uint8_t(0xFF)); // 2.16
        QVERIFY(b.ask(cmd::readAngles(0)).empty());
        QCOMPARE(b.one(cmd::readAngles(5)).address, uint8_t(5));
        const Reply q = b.one(cmd::queryAddress());
        QCOMPARE(q.deviceAddress, uint8_t(5));
    }

    void autoOutput_data()
    {
        QTest::addColumn<int>("hz");
        QTest::addColumn<int>("content");
        QTest::addColumn<int>("baud");
        QTest::newRow("5 Hz angles") << 5 << 0 << 9600;
        QTest::newRow("50 Hz angles") << 50 << 0 << 9600;
        QTest::newRow("100 Hz record 115200") << 100 << 2 << 115200;
        QTest::newRow("25 Hz internal 115200") << 25 << 1 << 115200;
        QTest::newRow("15 Hz record 19200") << 15 << 2 << 19200;
    }
    void autoOutput()
    {
        QFETCH(int, hz);
        QFETCH(int, content);
        QFETCH(int, baud);
        Hec495Options o;
        o.rateHz = hz;
        o.content = OutputContent(content);
        o.baud = baud;
        Bench b(o);
        QVERIFY(b.run(2800000).empty()); // quiet after power-on (2.14)
        // Commands are heard in the window.
        QVERIFY(b.one(cmd::readDeclination()).ok());
        b.run(100000 + 1000000 / hz);
        const auto frames = b.run(2000000);
        QVERIFY2(std::abs(int(frames.size()) - 2 * hz) <= 1, qPrintable(QString::number(frames.size())));
        for (const auto &r : frames) {
            QVERIFY(r.ok());
            QCOMPARE(r.kind, content == 0 ? Reply::Kind::Angles : Reply::Kind::AllData);
        }
        QCOMPARE(b.sim.framesDropped(), uint64_t(0));
    }

    void rateSetAtRuntimeAndNmea()
    {
        Bench b;
        b.run(5000000);
        QVERIFY(b.one(cmd::setOutputContent(OutputContent::Nmea0183)).success);
        QVERIFY(b.ask(cmd::setOutputRate(10)).size() == 1);
        QVERIFY(b.run(1000000).empty()); // no frames: text
        QCOMPARE(b.dec.counters().frames, uint64_t(b.dec.counters().frames));
        const std::string text = b.dec.takeSkipped();
        QVERIFY(text.find("$HCHDT,") != std::string::npos);
        QVERIFY(b.one(cmd::setOutputRate(0)).success); // back to question/answer
        b.dec.takeSkipped();
        b.run(1000000);
        QVERIFY(b.dec.takeSkipped().empty());
    }

    void rateSetInsideTheQuietWindow()
    {
        Bench b;
        b.run(1000000);
        for (int i = 0; i < 5; ++i)
            QCOMPARE(b.ask(cmd::readAll(), 120000).size(), size_t(1)); // polled like the session
        QVERIFY(b.one(cmd::setOutputRate(50)).success);
        QVERIFY(b.run(1200000).empty()); // the power-on window is not over yet
        b.run(100000);
        const auto frames = b.run(2000000);
        QVERIFY2(std::abs(int(frames.size()) - 100) <= 1, qPrintable(QString::number(frames.size())));
    }

    void tooFastForTheBaudIsDropped()
    {
        Hec495Options o;
        o.rateHz = 100;
        o.content = OutputContent::AllData; // 89 bytes x 100 Hz > 960 bytes/s at 9600
        Bench b(o);
        b.run(3000000);
        const auto frames = b.run(2000000);
        QVERIFY(frames.size() < 30);
        QVERIFY(b.sim.framesDropped() > 150);
    }

    void rs485LosesCommandsWhileTalking()
    {
        Hec495Options o;
        o.rateHz = 100;
        o.content = OutputContent::AllData;
        o.rs485 = true;
        Bench b(o);
        b.run(3005000); // the first frame is on the line
        const auto r = b.ask(cmd::readDeclination(), 1000);
        for (const auto &x : r)
            QVERIFY(x.kind != Reply::Kind::Declination);
        QCOMPARE(b.sim.commandsLost(), uint64_t(1));
    }

    void factoryReset()
    {
        Bench b;
        b.one(cmd::setDeclination(5.5));
        b.one(cmd::saveSettings());
        b.one(cmd::setBaud(19200));
        b.bauds.clear();
        QVERIFY(b.one(cmd::factoryReset()).success);
        QCOMPARE(b.bauds, std::vector<int>{19200});
        QCOMPARE(b.sim.runningSettings(), Hec495Simulator::factorySettings());
        QCOMPARE(b.sim.savedSettings(), Hec495Simulator::factorySettings());
    }

    // Table 1 of the manual: the 12 poses of the automatic 12-point calibration.
    void auto12InTheTablePoses()
    {
        Bench b;
        QVERIFY(b.one(cmd::startCalibration(CalibrationMethod::Auto12)).success);
        // Away from every table pose: nothing collected.
        b.sim.setPose(Hec495Calibration::Pose{45, 0, 0});
        QVERIFY(b.run(200000).empty());
        const double headings[12] = {0, 90, 180, 270, 30, 120, 210, 300, 60, 150, 240, 330};
        int last = 0;
        for (int i = 0; i < 12; ++i) {
            const double pitch = i < 4 ? 2.0 : (i < 8 ? 55.0 : -55.0);
            const double roll = i % 2 == 0 ? 35.0 : -35.0;
            b.sim.setPose(Hec495Calibration::Pose{headings[i] + 5.0, pitch, roll});
            const auto r = b.run(100000);
            QCOMPARE(r.size(), size_t(1));
            QCOMPARE(r[0].kind, Reply::Kind::CalibrationPoint);
            QCOMPARE(r[0].points, last + 1);
            last = r[0].points;
            QVERIFY(b.run(100000).empty()); // the same pose once only
        }
        const Reply saved = b.one(cmd::saveCalibration());
        QCOMPARE(saved.kind, Reply::Kind::CalibrationSaved);
        QCOMPARE(saved.points, 12);
        QVERIFY2(saved.fitError > 0.05f && saved.fitError < 10.0f, qPrintable(QString::number(saved.fitError)));
        QVERIFY(b.sim.calibrated());
        // The hard iron found is the simulated one, and the heading error shrinks.
        QVERIFY((b.sim.hardIronCorrection() - b.sim.sensorModel().hardIron()).norm() < 3.0);
    }

    void calibrationImprovesHeading()
    {
        Hec495Options o;
        o.seed = 5;
        Bench b(o);
        auto worstError = [&] {
            double worst = 0;
            for (int h = 0; h < 360; h += 15) {
                b.sim.setPose(Hec495Calibration::Pose{double(h), 0, 0});
                worst = std::max(worst, angleDiff(b.one(cmd::readHeading()).angle, h));
            }
            return worst;
        };
        const double before = worstError();
        b.sim.setPose(Hec495Calibration::Pose{0, 30, 0}); // tilted: the planar method takes nothing
        QVERIFY(b.one(cmd::startCalibration(CalibrationMethod::Planar)).success);
        for (int h = 0; h < 360; h += 30) {
            b.sim.setPose(Hec495Calibration::Pose{h + 10.0, 0.5, -0.5});
            QCOMPARE(b.run(40000).size(), size_t(1));
        }
        const Reply saved = b.one(cmd::saveCalibration());
        QCOMPARE(saved.points, 12);
        const double after = worstError();
        QVERIFY2(after < before / 2, qPrintable(QStringLiteral("%1 -> %2").arg(before).arg(after)));
    }

    void planarWithSpinningMotion()
    {
        Hec495Options o;
        o.motion = Motion::Spin;
        Bench b(o);
        auto replies = b.ask(cmd::startCalibration(CalibrationMethod::Planar));
        QVERIFY(!replies.empty());
        QCOMPARE(replies.front().kind, Reply::Kind::Status);
        QVERIFY(replies.front().success);
        for (const auto &r : b.run(13000000))
            replies.push_back(r);
        int points = 0;
        for (const auto &r : replies)
            if (r.kind == Reply::Kind::CalibrationPoint)
                points = r.points;
        QCOMPARE(points, 12);
        const Reply saved = b.one(cmd::saveCalibration());
        QCOMPARE(saved.kind, Reply::Kind::CalibrationSaved);
        QCOMPARE(saved.points, 12);
        QVERIFY(saved.fitError < 10.0f);
    }

    void manualNeedsTwelvePoints()
    {
        Bench b;
        QVERIFY(b.ask(cmd::collectPoint()).empty()); // no run
        QVERIFY(b.one(cmd::startCalibration(CalibrationMethod::Manual)).success);
        for (int i = 0; i < 11; ++i) {
            b.sim.setPose(Hec495Calibration::Pose{i * 33.0, (i % 3 - 1) * 40.0, (i % 2) * 30.0});
            QCOMPARE(b.one(cmd::collectPoint()).points, i + 1);
        }
        const Reply fail = b.one(cmd::saveCalibration());
        QCOMPARE(fail.kind, Reply::Kind::Status);
        QVERIFY(!fail.success);
        QVERIFY(!b.sim.calibrated());
        // Stop with no run fails; clear succeeds.
        QVERIFY(!b.one(cmd::stopCalibration()).success);
        QVERIFY(b.one(cmd::clearCalibration()).success);
    }

    void allOrientationWithTumble()
    {
        Hec495Options o;
        o.motion = Motion::Tumble;
        Bench b(o);
        auto replies = b.ask(cmd::startCalibration(CalibrationMethod::AllOrientation));
        QVERIFY(!replies.empty());
        QVERIFY(replies.front().success);
        for (const auto &r : b.run(60000000))
            replies.push_back(r);
        int points = 0;
        for (const auto &r : replies)
            if (r.kind == Reply::Kind::CalibrationPoint)
                points = r.points;
        QVERIFY2(points >= 30, qPrintable(QString::number(points)));
        const Reply saved = b.one(cmd::saveCalibration());
        QCOMPARE(saved.kind, Reply::Kind::CalibrationSaved);
        QVERIFY(saved.fitError < 10.0f);
        QVERIFY((b.sim.hardIronCorrection() - b.sim.sensorModel().hardIron()).norm() < 3.0);
    }

    void smallTiltTable()
    {
        using P = Hec495Calibration::Pose;
        QCOMPARE(Hec495Calibration::tableSlot(CalibrationMethod::SmallTilt12, P{92, 0, 3}), 1);
        QCOMPARE(Hec495Calibration::tableSlot(CalibrationMethod::SmallTilt12, P{92, 0, 8}), -1);
        QCOMPARE(Hec495Calibration::tableSlot(CalibrationMethod::SmallTilt12, P{330, -50, 0}), 11);
        QCOMPARE(Hec495Calibration::tableSlot(CalibrationMethod::Auto12, P{355, 0, 33}), 0);
        QCOMPARE(Hec495Calibration::tableSlot(CalibrationMethod::Auto12, P{90, 0, 33}), -1); // roll sign
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstHec495Simulator)
#include "tst_hec495_simulator.moc"
