// HipnucSimulator in process: every command of the v1.7.1 and v1.6.6 manuals with its
// reply (OK / ERR / silence), persistence, resets, baud switching, output rates and
// triggers, frame contents decoded with the core codecs, calibrations, the bootloader
// and the UART model, the per-module faults (SimFaults) and a firmware update from 1.6.6.
#include "core/firmware/update_flow.h"
#include "model/device_identity.h"
#include "model/main_status.h"
#include "model/sample.h"
#include "protocol/hipnuc/ascii_reply.h"
#include "protocol/hipnuc/crc16.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/nmea/nmea_parser.h"
#include "protocol/stream/stream_demux.h"
#include "sim/hipnuc_simulator.h"
#include "sim/simulated_byte_link.h"
#include "../common/test_main.h"

#include <QTest>

#include <cmath>

using namespace imudesk;
using namespace imudesk::sim;
using namespace imudesk::protocol::hipnuc;
using model::MainStatus;

Q_DECLARE_METATYPE(imudesk::sim::Motion)

namespace {

// Everything the module sent during one step, split by the core stream demultiplexer.
struct Capture {
    std::vector<uint8_t> raw;
    std::vector<std::string> lines;
    std::vector<std::vector<uint8_t>> frames; // payloads
    std::vector<protocol::nmea::Sentence> sentences;
    int nmeaErrors = 0;

    template <typename T> std::vector<T> packets() const
    {
        std::vector<T> out;
        for (const auto &f : frames) {
            const PayloadResult r = decodePayload(f);
            if (!r.ok())
                continue;
            for (const auto &p : r.packets)
                if (const T *t = std::get_if<T>(&p))
                    out.push_back(*t);
        }
        return out;
    }
    int countTag(uint8_t tag) const
    {
        int n = 0;
        for (const auto &f : frames)
            n += !f.empty() && f[0] == tag;
        return n;
    }
    int countSentences(const std::string &type) const
    {
        int n = 0;
        for (const auto &s : sentences)
            n += s.type == type;
        return n;
    }
    std::string text() const { return std::string(raw.begin(), raw.end()); }
};

class Rig {
public:
    explicit Rig(SimOptions o = {}) : sim(std::move(o)) {}

    Capture run(int64_t us)
    {
        sim.advanceTo(sim.nowUs() + us);
        return collect();
    }
    Capture collect()
    {
        Capture c;
        c.raw = sim.takeOutput();
        for (auto &e : demux.feed(c.raw.data(), c.raw.size())) {
            switch (e.kind) {
            case protocol::StreamEvent::Kind::Frame: c.frames.push_back(std::move(e.payload)); break;
            case protocol::StreamEvent::Kind::Line: c.lines.push_back(e.text); break;
            case protocol::StreamEvent::Kind::Nmea:
                c.sentences.push_back(*protocol::nmea::parseSentence(e.text).sentence);
                break;
            case protocol::StreamEvent::Kind::NmeaError: ++c.nmeaErrors; break;
            }
        }
        return c;
    }
    Capture send(const std::string &line, int64_t waitUs = 100000)
    {
        sim.receive(line + "\r\n");
        demux.endQuarantine(); // as the session does: the reply follows the command
        return run(waitUs);
    }
    // Sends a command and collects its reply; Pending status means silence.
    AsciiReply command(const std::string &line, int64_t waitUs = 100000)
    {
        last = send(line, waitUs);
        ReplyCollector rc(line);
        for (const auto &l : last.lines)
            if (rc.addLine(l))
                break;
        return rc.take();
    }
    bool ok(const std::string &line, int64_t waitUs = 100000) { return command(line, waitUs).ok(); }
    // Output off, buffer drained: later raw bytes are replies only.
    void quiet()
    {
        QVERIFY(ok("LOG DISABLE"));
        run(100000);
    }

    HipnucSimulator sim;
    protocol::StreamDemux demux;
    Capture last;
};

SimOptions opts(const std::string &firmware = "1.7.1", const std::string &model = "HI14", Motion motion = Motion::Static,
                int baud = 115200)
{
    SimOptions o;
    o.firmware = firmware;
    o.model = model;
    o.motion = motion;
    o.baud = baud;
    return o;
}

std::string outcome(const AsciiReply &r)
{
    switch (r.status) {
    case AsciiReply::Status::Ok: return "OK";
    case AsciiReply::Status::Error: return "ERR";
    case AsciiReply::Status::Pending: return "-";
    default: return "?";
    }
}

double angleDiff(double a, double b)
{
    double d = std::fmod(a - b, 360.0);
    if (d > 180.0) d -= 360.0;
    if (d < -180.0) d += 360.0;
    return d;
}

Eigen::Vector3d vec(const std::array<float, 3> &a)
{
    return {a[0], a[1], a[2]};
}

uint16_t bit(MainStatus::Bit b)
{
    return uint16_t(1u << b);
}

SimOptions withFaults(const SimFaults &faults, SimOptions o = opts())
{
    o.faults = faults;
    return o;
}

// Standard deviation of each axis of the HI91 gyro readings, averaged over the axes.
double gyroStd(const std::vector<Hi91> &frames)
{
    Eigen::Vector3d sum = Eigen::Vector3d::Zero(), squares = Eigen::Vector3d::Zero();
    for (const Hi91 &h : frames) {
        sum += vec(h.gyr);
        squares += vec(h.gyr).cwiseProduct(vec(h.gyr));
    }
    const double n = double(frames.size());
    const Eigen::Vector3d variance = squares / n - (sum / n).cwiseProduct(sum / n);
    return variance.cwiseSqrt().mean();
}

// Starts (or restarts) an MCAL with the output off, polls LOG MCAL STAT every 100 ms of
// simulated time until it ends (STAT 3 or 4) or limitS pass, and turns the output on again.
// Returns STAT, PROGRESS and the simulated seconds from START to the first poll that saw the end.
struct McalEnd {
    int stat = 0, progress = 0;
    double seconds = -1;
};
McalEnd runMagCal(Rig &rig, double limitS = 130)
{
    McalEnd end;
    if (!rig.ok("LOG DISABLE") || !rig.ok("CONFIG MCAL START", 10000))
        return end;
    const int64_t startUs = rig.sim.nowUs() - 10000;
    while (rig.sim.nowUs() - startUs < int64_t(limitS * 1e6)) {
        rig.run(90000);
        const AsciiReply r = rig.command("LOG MCAL STAT", 10000);
        end.stat = std::stoi(r.values.at("STAT"));
        end.progress = std::stoi(r.values.at("PROGRESS"));
        if (end.stat >= 3) {
            end.seconds = double(rig.sim.nowUs() - startUs) * 1e-6;
            break;
        }
    }
    rig.ok("LOG ENABLE");
    return end;
}

} // namespace

class TestHipnucSimulator : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void commandReplies_data();
    void commandReplies();
    void replyBytesAreExact();
    void unknownCommandIsSilent();
    void lineEndings();
    void versionReply_data();
    void versionReply();
    void comConfigDefaults_data();
    void comConfigDefaults();
    void comConfigReflectsChanges();
    void saveRebootPersistence();
    void rebootIgnoresInputAndIsSilent();
    void factoryReset();
    void serialConfigSwitchesAfterOk();
    void serialConfigOtherPortAndLegacyList();
    void logDisableStopsFrames();
    void onTimeRates_data();
    void onTimeRates();
    void onMarkOnce();
    void onMarkSyncIn();
    void hi83MapChangesLength_data();
    void hi83MapChangesLength();
    void ppsAlignsTheClockToUtc();
    void hi91Contents();
    void hi81Contents();
    void hi92Contents();
    void nmeaSentences();
    void mainStatus_data();
    void mainStatus();
    void modelGates();
    void attitudeResets();
    void legacyYawCommand();
    void sixAxisHeadingStartsAtZero();
    void gyroCalibration_data();
    void gyroCalibration();
    void magCalTumbleCompletes();
    void magCalStaticFails();
    void legacyBackgroundMagCal_data();
    void legacyBackgroundMagCal();
    void bootloaderPing();
    void uartDropsFramesWhenBaudTooLow();
    void uartNoDropsAtHighBaud();
    void firmwareUpdateFrom166To171();
    void faultNoisyGyro();
    void faultMounting();
    void faultMagDisturbance_data();
    void faultMagDisturbance();
    void faultFixtureMagCal();
    void faultsText();
};

// ---------------------------------------------------------------------------------------

void TestHipnucSimulator::commandReplies_data()
{
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<QString>("model");
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("expected"); // OK, ERR or "-" (no reply)

    auto row = [](const char *fw, const char *model, const char *cmd, const char *expected) {
        QTest::addRow("%s %s: %s", fw, model, cmd) << fw << model << cmd << expected;
    };
    // v1.7.1, chapter 4
    const char *n = "1.7.1", *m = "HI14";
    row(n, m, "REBOOT", "OK");
    row(n, m, "REBOOT BL", "OK");
    row(n, m, "REBOOT NOW", "ERR");
    row(n, m, "SAVECONFIG", "OK");
    row(n, m, "SAVECONFIG ALL", "ERR");
    row(n, m, "FRESET", "OK");
    row(n, m, "FRESET 1", "ERR");
    row(n, m, "SERIALCONFIG 115200", "OK");
    row(n, m, "SERIALCONFIG 4800", "OK");
    row(n, m, "SERIALCONFIG 230400", "OK");
    row(n, m, "SERIALCONFIG 256000", "OK");
    row(n, m, "SERIALCONFIG 921600", "OK");
    row(n, m, "SERIALCONFIG 12345", "ERR");
    row(n, m, "SERIALCONFIG", "ERR");
    row(n, m, "SERIALCONFIG FAST", "ERR");
    row(n, m, "SERIALCONFIG COM1 460800", "OK");
    row(n, m, "SERIALCONFIG COM4 9600", "OK");
    row(n, m, "SERIALCONFIG COM5 9600", "ERR");
    row(n, m, "CONFIG ATT MODE 0", "OK");
    row(n, m, "CONFIG ATT MODE 1", "OK");
    row(n, m, "CONFIG ATT MODE 4", "OK");
    row(n, m, "CONFIG ATT MODE 2", "ERR");
    row(n, m, "CONFIG ATT MODE", "ERR");
    row(n, m, "CONFIG ATT RST 1", "OK");
    row(n, m, "CONFIG ATT RST 2", "OK");
    row(n, m, "CONFIG ATT RST 3", "OK");
    row(n, m, "CONFIG ATT RST 5", "OK");
    row(n, m, "CONFIG ATT RST 4", "ERR");
    row(n, m, "CONFIG ATT FOO 1", "ERR");
    row(n, m, "CONFIG IMU URFR 24", "OK");
    row(n, m, "CONFIG IMU URFR 024", "OK");
    row(n, m, "CONFIG IMU URFR 240", "OK");
    row(n, m, "CONFIG IMU URFR 531", "OK");
    row(n, m, "CONFIG IMU URFR 25", "ERR");
    row(n, m, "CONFIG IMU URFR 999", "ERR");
    row(n, m, "CONFIG IMU URFR=24", "ERR");
    row(n, m, "CONFIG IMU URFR 1,0,0,0,1,0,0,0,1", "ERR");
    row(n, m, "CONFIG IMU COORD 0", "OK");
    row(n, m, "CONFIG IMU COORD 4", "OK");
    row(n, m, "CONFIG IMU COORD 1", "ERR");
    row(n, m, "CONFIG IMU", "ERR");
    row(n, m, "CONFIG PMUX1 IO1", "OK");
    row(n, m, "CONFIG PMUX2 IO1", "OK");
    row(n, m, "CONFIG PMUX3 IO2", "OK");
    row(n, m, "CONFIG PMUX3 IO5", "OK");
    row(n, m, "CONFIG PMUX4 IO1", "ERR");
    row(n, m, "CONFIG PMUX1 IO6", "ERR");
    row(n, m, "CONFIG PMUX1 IO0", "ERR");
    row(n, m, "CONFIG PMUX2 DIV 1", "OK");
    row(n, m, "CONFIG PMUX2 DIV 5", "OK");
    row(n, m, "CONFIG PMUX2 DIV 1000", "OK");
    row(n, m, "CONFIG PMUX2 DIV 0", "ERR");
    row(n, m, "CONFIG PMUX2 DIV 1001", "ERR");
    row(n, m, "CONFIG PMUX1 DIV 5", "ERR");
    row(n, m, "CONFIG MCAL START", "OK");
    row(n, m, "CONFIG MCAL STOP", "ERR");
    row(n, m, "CONFIG USRCAL START 720", "OK");
    row(n, m, "CONFIG USRCAL START 1800", "OK");
    row(n, m, "CONFIG USRCAL START 700", "ERR");
    row(n, m, "CONFIG USRCAL START 1900", "ERR");
    row(n, m, "CONFIG USRCAL STOP", "ERR"); // nothing started
    row(n, m, "LOG ENABLE", "OK");
    row(n, m, "LOG DISABLE", "OK");
    row(n, m, "LOG VERSION", "OK");
    row(n, m, "LOG COMCONFIG", "OK");
    row(n, m, "LOG MCAL STAT", "OK");
    row(n, m, "LOG MCAL", "ERR");
    row(n, m, "LOG", "ERR");
    row(n, m, "LOG HI91 ONTIME 0.01", "OK");
    row(n, m, "LOG HI91 ONTIME 0.05", "OK");
    row(n, m, "LOG HI91 ONTIME 0.001", "OK");
    row(n, m, "LOG HI91 ONTIME 1", "OK");
    row(n, m, "LOG HI91 ONTIME 0", "OK");
    row(n, m, "LOG HI91 ONTIME 0.0005", "ERR");
    row(n, m, "LOG HI91 ONTIME 0.0015", "ERR");
    row(n, m, "LOG HI91 ONTIME 2", "ERR");
    row(n, m, "LOG HI91 ONTIME -1", "ERR");
    row(n, m, "LOG HI91 ONTIME", "ERR");
    row(n, m, "LOG HI91 ONMARK 1", "OK");
    row(n, m, "LOG HI91 ONMARK ONCE", "OK");
    row(n, m, "LOG HI91 ONMARK 2", "ERR");
    row(n, m, "LOG HI81 ONTIME 0.1", "OK");
    row(n, m, "LOG HI83 ONTIME 0.01", "OK");
    row(n, m, "LOG HI83 ONMARK ONCE", "OK");
    row(n, m, "LOG GGA ONTIME 1", "OK");
    row(n, m, "LOG RMC ONTIME 1", "OK");
    row(n, m, "LOG SXT ONTIME 1", "OK");
    row(n, m, "LOG HI83 MAP 0x000000FF", "OK");
    row(n, m, "LOG HI83 MAP 0x0000001F", "OK");
    row(n, m, "LOG HI83 MAP 31", "OK");
    row(n, m, "LOG HI83 MAP 0x00100000", "ERR");
    row(n, m, "LOG HI83 MAP 0", "ERR");
    row(n, m, "LOG HI83 MAP 0xZZ", "ERR");
    row(n, m, "LOG HI91 MAP 0x1F", "ERR");
    row(n, m, "LOG HI92 ONTIME 0.01", "ERR");  // not a v1.7.1 message
    row(n, m, "LOG VTG ONTIME 1", "ERR");      // unknown message
    row(n, m, "LOG COM1 HI91 ONTIME 0.02", "OK");
    row(n, m, "LOG COM2 HI91 ONTIME 0.02", "OK");
    row(n, m, "LOG COM7 HI91 ONTIME 0.02", "ERR");
    row(n, m, "log version", "OK");
    // v1.6.6-only keywords are unknown to 1.7.1: silence.
    row(n, m, "CONFIG YAW 1 16", "-");
    row(n, m, "CONFIG IMU_EN_MCAL 1", "-");
    row(n, m, "LOG MAGCONFIG", "-");
    // Unknown keywords.
    row(n, m, "HELLO", "-");
    row(n, m, "AT+INFO", "-");
    row(n, m, "CONFIG FOO 1", "-");
    row(n, m, "LOG FOO", "-");
    row(n, m, "LOG FOO BAR", "-");

    // v1.6.6, chapter 2 and 8
    n = "1.6.6";
    row(n, m, "REBOOT", "OK");
    row(n, m, "SAVECONFIG", "OK");
    row(n, m, "FRESET", "OK");
    row(n, m, "SERIALCONFIG 9600", "OK");
    row(n, m, "SERIALCONFIG 115200", "OK");
    row(n, m, "SERIALCONFIG 256000", "OK");
    row(n, m, "SERIALCONFIG 460800", "OK");
    row(n, m, "SERIALCONFIG 921600", "OK");
    row(n, m, "SERIALCONFIG 230400", "ERR"); // not in the v1.6.6 list
    row(n, m, "SERIALCONFIG 4800", "ERR");
    row(n, m, "CONFIG ATT MODE 0", "OK");
    row(n, m, "CONFIG ATT MODE 1", "OK");
    row(n, m, "CONFIG ATT MODE 4", "ERR");
    row(n, m, "CONFIG ATT RST 1", "ERR"); // v1.6.6 has 2, 3, 5 (and CONFIG YAW)
    row(n, m, "CONFIG ATT RST 2", "OK");
    row(n, m, "CONFIG ATT RST 3", "OK");
    row(n, m, "CONFIG ATT RST 5", "OK");
    row(n, m, "CONFIG YAW 1 16", "OK");
    row(n, m, "CONFIG YAW 0 1.5", "OK");
    row(n, m, "CONFIG YAW 1 -180", "OK");
    row(n, m, "CONFIG YAW 2 1", "ERR");
    row(n, m, "CONFIG YAW 1 190", "ERR");
    row(n, m, "CONFIG YAW 1", "ERR");
    row(n, m, "CONFIG IMU URFR 1,0,0,0,1,0,0,0,1", "OK");
    row(n, m, "CONFIG IMU URFR 1,0,0,0,0,1,0,-1,0", "OK");
    row(n, m, "CONFIG IMU URFR 0,0,-1,0,1,0,1,0,0", "OK");
    row(n, m, "CONFIG IMU URFR 0.7071068,-0.7071068,0,0.7071068,0.7071068,0,0,0,1", "OK");
    row(n, m, "CONFIG IMU URFR 1,0,0,0,1,0,-1,0", "ERR");    // 8 numbers (as printed in the manual)
    row(n, m, "CONFIG IMU URFR 1,0,0,0,1,0,0,0,-1", "ERR");  // reflection
    row(n, m, "CONFIG IMU URFR 2,0,0,0,1,0,0,0,1", "ERR");
    row(n, m, "CONFIG IMU URFR 24", "ERR");
    row(n, m, "CONFIG PMUX3 IO2", "OK");
    row(n, m, "CONFIG PMUX5 IO9", "OK");
    row(n, m, "CONFIG PMUX6 IO1", "ERR");
    row(n, m, "CONFIG PMUX1 IO10", "ERR");
    row(n, m, "CONFIG PMUX2 DIV 5", "ERR");
    row(n, m, "CONFIG IMU_EN_MCAL 0", "OK");
    row(n, m, "CONFIG IMU_EN_MCAL 1", "OK");
    row(n, m, "CONFIG IMU_EN_MCAL 2", "ERR");
    row(n, m, "CONFIG USRCAL START 720", "OK");
    row(n, m, "CONFIG USRCAL STOP", "ERR");
    row(n, m, "LOG ENABLE", "OK");
    row(n, m, "LOG DISABLE", "OK");
    row(n, m, "LOG VERSION", "OK");
    row(n, m, "LOG COMCONFIG", "OK");
    row(n, m, "LOG MAGCONFIG", "OK");
    row(n, m, "LOG HI91 ONTIME 0.01", "OK");
    row(n, m, "LOG HI92 ONTIME 0.05", "OK");
    row(n, m, "LOG HI92 ONTIME 0.002", "OK");
    row(n, m, "LOG HI91 ONMARK 1", "OK");
    row(n, m, "LOG HI92 ONMARK ONCE", "OK");
    row(n, m, "LOG HI81 ONTIME 0.1", "ERR");
    row(n, m, "LOG HI83 ONTIME 0.1", "ERR");
    row(n, m, "LOG HI83 MAP 0xFF", "ERR");
    row(n, m, "LOG GGA ONTIME 1", "ERR");
    // v1.7.x-only keywords are unknown to 1.6.6: silence.
    row(n, m, "CONFIG IMU COORD 4", "-");
    row(n, m, "CONFIG MCAL START", "-");
    row(n, m, "LOG MCAL STAT", "-");
    row(n, m, "AT+EOUT=0", "-");

    // Model gates (v1.7.1 chapter 3)
    n = "1.7.1";
    row(n, "HI02", "CONFIG ATT MODE 1", "ERR");
    row(n, "HI02", "CONFIG ATT MODE 0", "OK");
    row(n, "HI02", "CONFIG ATT RST 2", "ERR");
    row(n, "HI02", "CONFIG PMUX3 IO2", "ERR");
    row(n, "HI02", "CONFIG MCAL START", "ERR");
    row(n, "HI02", "CONFIG USRCAL START 720", "OK");
    row(n, "HI50", "CONFIG ATT MODE 1", "ERR");
    row(n, "HI50", "CONFIG ATT RST 2", "OK");
    row(n, "HI50", "CONFIG PMUX3 IO2", "ERR");
    row(n, "HI50", "CONFIG MCAL START", "ERR");
    row(n, "HI92", "CONFIG ATT MODE 1", "OK");
    row(n, "HI92", "CONFIG PMUX3 IO2", "ERR");
    row(n, "HI05", "CONFIG PMUX3 IO2", "OK");
    row(n, "CH040", "CONFIG PMUX3 IO2", "OK");
    // MCAL needs >= 1.7.0, which still uses the v1.6.6 command set otherwise.
    row("1.7.0", m, "CONFIG MCAL START", "OK");
    row("1.7.0", m, "LOG MCAL STAT", "OK");
    row("1.7.0", m, "CONFIG YAW 1 10", "OK");
}

void TestHipnucSimulator::commandReplies()
{
    QFETCH(QString, firmware);
    QFETCH(QString, model);
    QFETCH(QString, command);
    QFETCH(QString, expected);
    Rig rig(opts(firmware.toStdString(), model.toStdString()));
    rig.run(200000);
    const AsciiReply r = rig.command(command.toStdString(), 200000);
    QCOMPARE(QString::fromStdString(outcome(r)), expected);
    if (expected == "-")
        QVERIFY2(rig.last.lines.empty(), rig.last.lines.empty() ? "" : rig.last.lines.front().c_str()); // not even a stray line
    if (QString::fromStdString(outcome(r)) != expected)
        for (const auto &l : rig.last.lines)
            qWarning("line: %s", l.c_str());
    if (expected == "ERR")
        QCOMPARE(QString::fromStdString(r.errorLine), QStringLiteral("ERR"));
}

void TestHipnucSimulator::replyBytesAreExact()
{
    Rig rig;
    rig.quiet();
    QCOMPARE(QString::fromStdString(rig.send("SAVECONFIG").text()), QStringLiteral("OK\r\n"));
    QCOMPARE(QString::fromStdString(rig.send("CONFIG ATT MODE 7").text()), QStringLiteral("ERR\r\n"));
    QCOMPARE(QString::fromStdString(rig.send("LOG MCAL STAT").text()), QStringLiteral("STAT=0\r\nPROGRESS=0\r\nOK\r\n"));
    const std::string version = rig.send("LOG VERSION").text();
    QCOMPARE(QString::fromStdString(version),
             QString::fromStdString("PNAME=HI14R3\r\nBUILD=Oct 15 2024\r\nUUID=" + rig.sim.uuid()
                                    + "\r\nAPP_VER=171\r\nBL_VER=109\r\nOK\r\n"));
    // ONMARK ONCE while output is disabled: OK first, then exactly one HI91 frame.
    const Capture once = rig.send("LOG HI91 ONMARK ONCE");
    QCOMPARE(once.raw.size(), size_t(4 + 82));
    QCOMPARE(std::string(once.raw.begin(), once.raw.begin() + 4), std::string("OK\r\n"));
    QCOMPARE(once.countTag(TagHi91), 1);
}

void TestHipnucSimulator::unknownCommandIsSilent()
{
    Rig rig;
    rig.quiet();
    for (const char *c : {"HELLO", "CONFIG YAW 1 16", "LOG MAGCONFIG", "AT+INFO", "XYZ 1 2 3"}) {
        const Capture cap = rig.send(c, 1000000);
        QVERIFY2(cap.raw.empty(), c);
    }
    // The device still answers afterwards.
    QVERIFY(rig.ok("LOG VERSION"));
}

void TestHipnucSimulator::lineEndings()
{
    Rig rig;
    rig.quiet();
    rig.sim.receive("LOG VERSION\n");
    QVERIFY(rig.run(50000).text().find("APP_VER=171\r\nBL_VER=109\r\nOK\r\n") != std::string::npos);
    // Split over several receive calls.
    rig.sim.receive("SAVE");
    rig.run(10000);
    rig.sim.receive("CONFIG\r");
    QVERIFY(rig.run(10000).raw.empty());
    rig.sim.receive("\n");
    QCOMPARE(QString::fromStdString(rig.run(10000).text()), QStringLiteral("OK\r\n"));
    // Blank lines and extra spaces.
    rig.sim.receive("\r\n\r\n");
    QVERIFY(rig.run(50000).raw.empty());
    QCOMPARE(QString::fromStdString(rig.send("  LOG   HI91  ONTIME   0.02 ").text()), QStringLiteral("OK\r\n"));
    QCOMPARE(rig.sim.runningConfig().message(Message::HI91).periodMs, 20);
    // An over-long line is discarded entirely; the next line works.
    rig.sim.receive(std::string(400, 'A') + "\r\n");
    QVERIFY(rig.run(50000).raw.empty());
    QVERIFY(rig.ok("SAVECONFIG"));
}

void TestHipnucSimulator::versionReply_data()
{
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<QString>("model");
    QTest::addColumn<QString>("appVer");
    QTest::newRow("HI14 1.7.1") << "1.7.1" << "HI14" << "171";
    QTest::newRow("HI14 1.6.6") << "1.6.6" << "HI14" << "166";
    QTest::newRow("CH0x0 1.5.6") << "156" << "CH040" << "156";
    QTest::newRow("HI02 1.7.2") << "v1.7.2" << "HI02" << "172";
    QTest::newRow("HI12R2 1.7.1") << "1.7.1" << "HI12R2" << "171";
}

void TestHipnucSimulator::versionReply()
{
    QFETCH(QString, firmware);
    QFETCH(QString, model);
    QFETCH(QString, appVer);
    Rig rig(opts(firmware.toStdString(), model.toStdString()));
    const AsciiReply r = rig.command("LOG VERSION");
    QVERIFY(r.ok());
    QCOMPARE(r.lines.size(), size_t(5));
    QCOMPARE(QString::fromStdString(r.values.at("PNAME")), model.contains('R') ? model : model + "R3");
    QCOMPARE(QString::fromStdString(r.values.at("BUILD")), QStringLiteral("Oct 15 2024"));
    QCOMPARE(QString::fromStdString(r.values.at("APP_VER")), appVer);
    QCOMPARE(QString::fromStdString(r.values.at("BL_VER")), QStringLiteral("109"));
    const std::string uuid = r.values.at("UUID");
    QCOMPARE(uuid.size(), size_t(16));
    for (char c : uuid)
        QVERIFY((c >= '0' && c <= '9') || (c >= 'A' && c <= 'F'));
    const auto id = model::DeviceIdentity::fromKeyValues(r.values);
    QVERIFY(id.usable());
    QCOMPARE(QStringLiteral("%1%2%3").arg(id.firmware->major).arg(id.firmware->minor).arg(id.firmware->patch), appVer);
    QCOMPARE(id.family(), model::familyOfProduct(model.toStdString()));
    // The UUID follows the seed.
    SimOptions o = opts(firmware.toStdString(), model.toStdString());
    QCOMPARE(HipnucSimulator(o).uuid(), uuid);
    o.seed = 2;
    QVERIFY(HipnucSimulator(o).uuid() != uuid);
}

void TestHipnucSimulator::comConfigDefaults_data()
{
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<QString>("model");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("HI14 1.7.1") << "1.7.1" << "HI14"
                                << QStringList{"BAUD=115200",    "LOG=ENABLE",   "HI91=ONTIME 0.01", "HI81=OFF",
                                               "HI83=OFF",       "GGA=OFF",      "RMC=OFF",          "SXT=OFF",
                                               "HI83_MAP=0x000000FF", "ATT_MODE=1", "URFR=24",       "COORD=0",
                                               "PMUX1=IO1",      "PMUX2=IO2",    "PMUX3=IO5",        "PMUX2_DIV=1"};
    QTest::newRow("HI14 1.6.6") << "1.6.6" << "HI14"
                                << QStringList{"BAUD=115200", "LOG=ENABLE", "HI91=ONTIME 0.01", "HI92=OFF", "ATT_MODE=1",
                                               "URFR=1,0,0,0,1,0,0,0,1", "PMUX1=IO1", "PMUX2=IO2", "PMUX3=IO5",
                                               "IMU_EN_MCAL=1"};
    QTest::newRow("HI02 1.7.1") << "1.7.1" << "HI02"
                                << QStringList{"BAUD=115200", "LOG=ENABLE", "HI91=ONTIME 0.01", "HI81=OFF", "HI83=OFF",
                                               "GGA=OFF", "RMC=OFF", "SXT=OFF", "HI83_MAP=0x000000FF", "ATT_MODE=0",
                                               "URFR=24", "COORD=0"};
}

void TestHipnucSimulator::comConfigDefaults()
{
    QFETCH(QString, firmware);
    QFETCH(QString, model);
    QFETCH(QStringList, expected);
    Rig rig(opts(firmware.toStdString(), model.toStdString()));
    const AsciiReply r = rig.command("LOG COMCONFIG");
    QVERIFY(r.ok());
    QStringList got;
    for (const auto &l : r.lines)
        got << QString::fromStdString(l);
    QCOMPARE(got, expected);
}

void TestHipnucSimulator::comConfigReflectsChanges()
{
    Rig rig(opts("1.7.1", "HI14", Motion::Static, 921600)); // 200 Hz HI91 needs more than 115200
    for (const char *c : {"LOG HI91 ONTIME 0.005", "LOG HI83 ONMARK 1", "LOG GGA ONTIME 1", "LOG HI83 MAP 0x1F",
                          "CONFIG ATT MODE 0", "CONFIG IMU URFR 531", "CONFIG IMU COORD 4", "CONFIG PMUX3 IO2",
                          "CONFIG PMUX2 DIV 20", "LOG DISABLE"})
        QVERIFY2(rig.ok(c), c);
    const AsciiReply r = rig.command("LOG COMCONFIG");
    QVERIFY(r.ok());
    const std::map<std::string, std::string> want = {
        {"BAUD", "921600"}, {"LOG", "DISABLE"}, {"HI91", "ONTIME 0.005"}, {"HI83", "ONMARK 1"}, {"GGA", "ONTIME 1"},
        {"HI83_MAP", "0x0000001F"}, {"ATT_MODE", "0"}, {"URFR", "531"}, {"COORD", "4"}, {"PMUX3", "IO2"},
        {"PMUX2_DIV", "20"}, {"HI81", "OFF"}};
    for (const auto &[k, v] : want)
        QCOMPARE(QString::fromStdString(r.values.at(k)), QString::fromStdString(v));
    // v1.6.6 matrix form
    Rig legacy(opts("1.6.6"));
    QVERIFY(legacy.ok("CONFIG IMU URFR 1,0,0,0,0,1,0,-1,0"));
    QVERIFY(legacy.ok("CONFIG IMU_EN_MCAL 0"));
    const AsciiReply l = legacy.command("LOG COMCONFIG");
    QCOMPARE(QString::fromStdString(l.values.at("URFR")), QStringLiteral("1,0,0,0,0,1,0,-1,0"));
    QCOMPARE(QString::fromStdString(l.values.at("IMU_EN_MCAL")), QStringLiteral("0"));
}

void TestHipnucSimulator::saveRebootPersistence()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.02"));
    QVERIFY(rig.ok("CONFIG ATT MODE 0"));
    QVERIFY(rig.ok("CONFIG IMU URFR 240"));
    QVERIFY(rig.ok("SAVECONFIG"));
    QCOMPARE(rig.sim.savedConfig(), rig.sim.runningConfig());
    // Unsaved changes.
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.05"));
    QVERIFY(rig.ok("CONFIG IMU COORD 4"));
    QVERIFY(rig.ok("LOG DISABLE"));
    QVERIFY(!(rig.sim.savedConfig() == rig.sim.runningConfig()));
    const HipnucSimulator::Config saved = rig.sim.savedConfig();

    QVERIFY(rig.ok("REBOOT", 350000));
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::App);
    QCOMPARE(rig.sim.runningConfig(), saved);
    QCOMPARE(rig.sim.activeConfig(), saved);
    QVERIFY(rig.sim.logEnabled()); // LOG DISABLE is not saved
    QCOMPARE(rig.sim.runningConfig().message(Message::HI91).periodMs, 20);
    QCOMPARE(rig.sim.runningConfig().coord, 0);
    QCOMPARE(rig.sim.runningConfig().urfrCode, 240);
    QCOMPARE(rig.sim.runningConfig().attMode, 0);
    // Output restarts at the saved 50 Hz with system_time from the restart.
    rig.run(200000);
    const Capture c = rig.run(1000000);
    QVERIFY(std::abs(c.countTag(TagHi91) - 50) <= 1);
    const auto frames = c.packets<Hi91>();
    QVERIFY(frames.front().systemTime < 1300);
    QCOMPARE(frames.back().systemTime - frames.front().systemTime, uint32_t(20 * (frames.size() - 1)));
    QCOMPARE(frames.back().mainStatus & bit(MainStatus::MagAiding), 0); // mode 0 now active
}

void TestHipnucSimulator::rebootIgnoresInputAndIsSilent()
{
    Rig rig;
    rig.run(108000); // the frame due at 100 ms is out
    rig.sim.receive("REBOOT\r\n");
    const Capture ok = rig.run(2000);
    QCOMPARE(QString::fromStdString(ok.text()), QStringLiteral("OK\r\n"));
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::Rebooting);
    rig.sim.receive("LOG VERSION\r\n"); // lost: the MCU is resetting
    const Capture during = rig.run(280000);
    QVERIFY(during.raw.empty());
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::Rebooting);
    rig.run(30000);
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::App);
    const Capture after = rig.run(500000);
    QVERIFY(after.lines.empty()); // the LOG VERSION sent during the reset got no reply
    QVERIFY(after.countTag(TagHi91) >= 49);
    QVERIFY(rig.sim.systemTimeMs() >= 500 && rig.sim.systemTimeMs() < 600);
}

void TestHipnucSimulator::factoryReset()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.05"));
    QVERIFY(rig.ok("LOG HI83 ONTIME 0.1"));
    QVERIFY(rig.ok("CONFIG ATT MODE 0"));
    QVERIFY(rig.ok("CONFIG PMUX2 DIV 7"));
    QVERIFY(rig.ok("CONFIG ATT RST 3"));
    QVERIFY(rig.ok("SERIALCONFIG 460800"));
    QVERIFY(rig.ok("SAVECONFIG"));
    QVERIFY(rig.ok("REBOOT", 400000));
    QCOMPARE(rig.sim.baud(), 460800);
    QCOMPARE(rig.sim.runningConfig().attMode, 0);

    QVERIFY(rig.ok("FRESET", 10000));
    QCOMPARE(rig.sim.savedConfig(), rig.sim.factoryConfig());
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::Rebooting);
    rig.run(400000);
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::App);
    QCOMPARE(rig.sim.runningConfig(), rig.sim.factoryConfig());
    QCOMPARE(rig.sim.baud(), 115200);
    const auto &f = rig.sim.factoryConfig();
    QCOMPARE(f.message(Message::HI91).periodMs, 10);
    QCOMPARE(f.message(Message::HI83).mode, HipnucSimulator::MessageSetting::Mode::Off);
    QCOMPARE(f.attMode, 1);
    QCOMPARE(f.urfrCode, 24);
    QCOMPARE(f.coord, 0);
    QCOMPARE(f.pmux2Div, 1);
    QCOMPARE(f.hi83Map, 0xFFu);
    QCOMPARE(f.pmux[0], 1);
    QCOMPARE(f.pmux[1], 2);
    QCOMPARE(f.pmux[2], 5);
    rig.run(200000);
    const Capture c = rig.run(1000000);
    QVERIFY(std::abs(c.countTag(TagHi91) - 100) <= 1);
    QCOMPARE(c.countTag(TagHi83), 0);
    // The level correction (ATT RST 3) is gone: the static tilt is back.
    const auto frames = c.packets<Hi91>();
    QVERIFY(std::fabs(frames.back().roll - MotionModel::kStaticRollDeg) < 0.01);
    // HI02 factory mode is 6-axis.
    Rig hi02(opts("1.7.1", "HI02"));
    QCOMPARE(hi02.sim.factoryConfig().attMode, 0);
}

void TestHipnucSimulator::serialConfigSwitchesAfterOk()
{
    Rig rig;
    rig.run(108000); // between two frames
    rig.sim.takeOutputSegments();
    rig.sim.receive("SERIALCONFIG 460800\r\n");
    QCOMPARE(rig.sim.baud(), 460800); // at once, after the OK was queued
    QCOMPARE(rig.sim.runningConfig().baud, 460800);
    QCOMPARE(rig.sim.savedConfig().baud, 115200);
    rig.sim.advanceTo(rig.sim.nowUs() + 200000);
    const auto segs = rig.sim.takeOutputSegments();
    bool sawOk = false;
    int framesAfter = 0;
    QVERIFY(!segs.empty());
    QVERIFY(!segs.front().data); // nothing was being sent: the OK comes first
    for (const auto &s : segs) {
        if (!s.data) {
            QCOMPARE(std::string(s.bytes.begin(), s.bytes.end()), std::string("OK\r\n"));
            QCOMPARE(s.baud, 115200); // the OK goes out at the old baud
            sawOk = true;
        } else {
            QCOMPARE(s.baud, 460800);
            framesAfter += s.chunkStart;
        }
    }
    QVERIFY(sawOk);
    QVERIFY(framesAfter >= 19);
    // Not saved: a reboot returns to 115200; saved: it stays.
    QVERIFY(rig.ok("REBOOT", 400000));
    QCOMPARE(rig.sim.baud(), 115200);
    QVERIFY(rig.ok("SERIALCONFIG 921600"));
    QVERIFY(rig.ok("SAVECONFIG"));
    QVERIFY(rig.ok("REBOOT", 400000));
    QCOMPARE(rig.sim.baud(), 921600);
    QCOMPARE(rig.sim.savedConfig().baud, 921600);
}

void TestHipnucSimulator::serialConfigOtherPortAndLegacyList()
{
    Rig rig;
    QVERIFY(rig.ok("SERIALCONFIG COM2 9600"));
    QCOMPARE(rig.sim.baud(), 115200);
    QVERIFY(rig.ok("SERIALCONFIG COM1 230400"));
    QCOMPARE(rig.sim.baud(), 230400);
    Rig legacy(opts("1.6.6"));
    QVERIFY(!legacy.ok("SERIALCONFIG 230400"));
    QCOMPARE(legacy.sim.baud(), 115200);
    QVERIFY(legacy.ok("SERIALCONFIG 256000"));
    QCOMPARE(legacy.sim.baud(), 256000);
    // Bytes take 10 bit times: 1 s at 256000 carries at most 25600 bytes: 200 HI91 frames fit.
    QVERIFY(legacy.ok("LOG HI91 ONTIME 0.005"));
    legacy.run(100000);
    const Capture c = legacy.run(1000000);
    QVERIFY(c.raw.size() <= 25600);
    QVERIFY(std::abs(c.countTag(TagHi91) - 200) <= 1);
    QCOMPARE(legacy.sim.droppedFrames(), uint64_t(0));
}

void TestHipnucSimulator::logDisableStopsFrames()
{
    Rig rig;
    QVERIFY(rig.run(500000).countTag(TagHi91) >= 49);
    QVERIFY(rig.ok("LOG DISABLE", 20000));
    QVERIFY(!rig.sim.logEnabled());
    const Capture off = rig.run(1000000);
    QCOMPARE(off.frames.size(), size_t(0));
    QVERIFY(off.raw.empty());
    QVERIFY(rig.ok("LOG ENABLE", 20000));
    QVERIFY(std::abs(rig.run(1000000).countTag(TagHi91) - 100) <= 1);
}

void TestHipnucSimulator::onTimeRates_data()
{
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<int>("baud");
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("message");
    QTest::addColumn<int>("perSecond");
    QTest::newRow("HI91 100 Hz") << "1.7.1" << 115200 << "LOG HI91 ONTIME 0.01" << "HI91" << 100;
    QTest::newRow("HI91 50 Hz") << "1.7.1" << 115200 << "LOG HI91 ONTIME 0.02" << "HI91" << 50;
    QTest::newRow("HI91 1 Hz") << "1.7.1" << 115200 << "LOG HI91 ONTIME 1" << "HI91" << 1;
    QTest::newRow("HI91 500 Hz") << "1.7.1" << 921600 << "LOG HI91 ONTIME 0.002" << "HI91" << 500;
    QTest::newRow("HI91 1 kHz") << "1.7.1" << 921600 << "LOG HI91 ONTIME 0.001" << "HI91" << 1000;
    QTest::newRow("HI81 100 Hz") << "1.7.1" << 115200 << "LOG HI81 ONTIME 0.01" << "HI81" << 100;
    QTest::newRow("HI83 50 Hz") << "1.7.1" << 115200 << "LOG HI83 ONTIME 0.02" << "HI83" << 50;
    QTest::newRow("GGA 10 Hz") << "1.7.1" << 115200 << "LOG GGA ONTIME 0.1" << "GGA" << 10;
    QTest::newRow("RMC 5 Hz") << "1.7.1" << 115200 << "LOG RMC ONTIME 0.2" << "RMC" << 5;
    QTest::newRow("SXT 1 Hz") << "1.7.1" << 115200 << "LOG SXT ONTIME 1" << "SXT" << 1;
    QTest::newRow("HI91 100 Hz 1.6.6") << "1.6.6" << 115200 << "LOG HI91 ONTIME 0.01" << "HI91" << 100;
    QTest::newRow("HI92 20 Hz 1.6.6") << "1.6.6" << 115200 << "LOG HI92 ONTIME 0.05" << "HI92" << 20;
    QTest::newRow("HI92 200 Hz 1.6.6") << "1.6.6" << 115200 << "LOG HI92 ONTIME 0.005" << "HI92" << 200;
}

void TestHipnucSimulator::onTimeRates()
{
    QFETCH(QString, firmware);
    QFETCH(int, baud);
    QFETCH(QString, command);
    QFETCH(QString, message);
    QFETCH(int, perSecond);
    Rig rig(opts(firmware.toStdString(), "HI14", Motion::Static, baud));
    if (message != "HI91")
        QVERIFY(rig.ok("LOG HI91 ONTIME 0"));
    QVERIFY(rig.ok(command.toStdString()));
    rig.run(300000);
    const Capture c = rig.run(1000000);
    int n = 0;
    Message m{};
    QVERIFY(parseMessage(message.toStdString(), m));
    const uint8_t tags[] = {TagHi91, TagHi92, TagHi81, TagHi83};
    if (size_t(m) < 4)
        n = c.countTag(tags[size_t(m)]);
    else
        n = c.countSentences(message.toStdString());
    QVERIFY2(std::abs(n - perSecond) <= 1, qPrintable(QString::number(n)));
    QCOMPARE(c.frames.size() + c.sentences.size(), size_t(n)); // nothing else is sent
    QCOMPARE(rig.sim.droppedFrames(), uint64_t(0));
    QCOMPARE(c.nmeaErrors, 0);
    // Frames are on the period grid.
    if (message == "HI91") {
        const auto f = c.packets<Hi91>();
        const uint32_t period = uint32_t(1000 / perSecond);
        for (size_t i = 1; i < f.size(); ++i)
            QCOMPARE(f[i].systemTime - f[i - 1].systemTime, period);
    }
}

void TestHipnucSimulator::onMarkOnce()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0"));
    QVERIFY(rig.run(500000).frames.empty());
    rig.sim.receive("LOG HI91 ONMARK ONCE\r\n");
    const uint32_t at = rig.sim.systemTimeMs();
    const Capture c = rig.run(50000);
    QCOMPARE(c.lines, std::vector<std::string>{"OK"});
    QCOMPARE(c.countTag(TagHi91), 1);
    QCOMPARE(c.packets<Hi91>().front().systemTime, at);
    QCOMPARE(rig.sim.runningConfig().message(Message::HI91).mode, HipnucSimulator::MessageSetting::Mode::Off);
    QVERIFY(rig.run(1000000).frames.empty());
    // Other messages too.
    QCOMPARE(rig.send("LOG HI83 ONMARK ONCE").countTag(TagHi83), 1);
    QCOMPARE(rig.send("LOG HI81 ONMARK ONCE").countTag(TagHi81), 1);
    QCOMPARE(rig.send("LOG GGA ONMARK ONCE").countSentences("GGA"), 1);
    QCOMPARE(rig.send("LOG SXT ONMARK ONCE").countSentences("SXT"), 1);
    Rig legacy(opts("1.6.6"));
    QCOMPARE(legacy.send("LOG HI92 ONMARK ONCE").countTag(TagHi92), 1);
}

void TestHipnucSimulator::onMarkSyncIn()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONMARK 1"));
    QCOMPARE(rig.sim.runningConfig().message(Message::HI91).mode, HipnucSimulator::MessageSetting::Mode::OnMark);
    QVERIFY(rig.run(500000).frames.empty()); // no periodic output any more
    std::vector<uint32_t> pulses;
    Capture all;
    for (int i = 0; i < 5; ++i) {
        rig.run(100000 + 7000 * i);
        pulses.push_back(rig.sim.systemTimeMs());
        rig.sim.syncInPulse();
        const Capture c = rig.run(10000);
        all.frames.insert(all.frames.end(), c.frames.begin(), c.frames.end());
    }
    const auto f = all.packets<Hi91>();
    QCOMPARE(f.size(), size_t(5));
    for (size_t i = 0; i < 5; ++i)
        QCOMPARE(f[i].systemTime, pulses[i]);
    // Two messages on the same pulse.
    QVERIFY(rig.ok("LOG HI83 ONMARK 1"));
    rig.sim.syncInPulse();
    const Capture both = rig.run(20000);
    QCOMPARE(both.countTag(TagHi91), 1);
    QCOMPARE(both.countTag(TagHi83), 1);
    // Output disabled: pulses produce nothing.
    QVERIFY(rig.ok("LOG DISABLE"));
    rig.sim.syncInPulse();
    QVERIFY(rig.run(20000).frames.empty());
}

void TestHipnucSimulator::hi83MapChangesLength_data()
{
    QTest::addColumn<uint>("map");
    QTest::addColumn<int>("payload");
    QTest::newRow("default 0xFF") << 0x000000FFu << 92;
    QTest::newRow("imu+attitude 0x1F") << 0x0000001Fu << 72;
    QTest::newRow("acc only") << 0x00000001u << 20;
    QTest::newRow("time only") << 0x00000020u << 16;
    QTest::newRow("the SDK's bits 0xC00FFFFF") << 0xC00FFFFFu << 236;
    QTest::newRow("everything the manual sizes") << 0xFE0FFFFFu << 348;
}

void TestHipnucSimulator::hi83MapChangesLength()
{
    QFETCH(uint, map);
    QFETCH(int, payload);
    QCOMPARE(Hi83::payloadSize(map).value_or(0), size_t(payload));
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0"));
    char cmd[64];
    std::snprintf(cmd, sizeof cmd, "LOG HI83 MAP 0x%08X", map);
    QVERIFY(rig.ok(cmd));
    QCOMPARE(rig.sim.runningConfig().hi83Map, uint32_t(map));
    QVERIFY(rig.ok("LOG HI83 ONTIME 0.05"));
    rig.run(100000);
    const Capture c = rig.run(500000);
    QCOMPARE(c.frames.size(), size_t(10));
    for (const auto &f : c.frames)
        QCOMPARE(int(f.size()), payload);
    const auto packets = c.packets<Hi83>();
    QCOMPARE(packets.size(), size_t(10));
    const Hi83 &p = packets.back();
    QCOMPARE(p.bitmap, uint32_t(map));
    QCOMPARE(p.insStatus, uint8_t(0));
    const auto has = [&](int b) { return (map >> b) & 1u; };
    if (has(0))
        QVERIFY(std::fabs(vec(p.accB).norm() - 9.8) < 0.05); // m/s^2 = G * 9.8
    if (has(1))
        QVERIFY(vec(p.gyrB).norm() < 0.01); // rad/s: only bias and noise on a static module
    if (has(2))
        QVERIFY(vec(p.magB).norm() > 20.0);
    if (has(3) && has(4)) {
        const EulerAngles e = eulerEnu312(Eigen::Quaterniond(p.quat[0], p.quat[1], p.quat[2], p.quat[3]).normalized());
        QVERIFY(std::fabs(e.roll - p.rpy[0]) < 1e-3);
        QVERIFY(std::fabs(e.pitch - p.rpy[1]) < 1e-3);
        QVERIFY(std::fabs(angleDiff(e.yaw, p.rpy[2])) < 1e-3);
    }
    if (has(5)) {
        QCOMPARE(p.systemTimeUs % 1000, uint64_t(0));
        QCOMPARE(p.systemTimeUs, uint64_t(packets.front().systemTimeUs + 9 * 50000));
        QVERIFY(!p.legacyTime32);
    }
    if (has(6)) {
        QCOMPARE(int(p.utc[0]), 24);
        QCOMPARE(int(p.utc[1]), 11);
        QCOMPARE(int(p.utc[2]), 14);
        QCOMPARE(int(p.utc[3]), 8);
    }
    if (has(7))
        QVERIFY(std::fabs(p.pressure - 100000.0f) < 50.0f);
    if (has(8))
        QVERIFY(std::fabs(p.temperature - 30.0f) < 1.0f);
    if (has(15)) { // the fix of the simulated GGA
        QCOMPARE(int(p.gnssQualityNv[0]), 1);
        QCOMPARE(int(p.gnssQualityNv[1]), 12);
    }
    if (has(25)) { // gravity updates at 100 Hz since power-on, GNSS position at 1 Hz
        QCOMPARE(p.eventCounter[0], uint32_t(p.systemTimeUs / 10000));
        QVERIFY(p.eventCounter[0] > p.eventCounter[2]);
    }
    if (has(28))
        QCOMPARE(p.gnssStd[0], 1.5f);
    if (has(30)) {
        QCOMPARE(p.gnssLonLatMsl[0], 121.458333);
        QCOMPARE(p.gnssLonLatMsl[1], 31.208333);
    }
    // Refused maps (bits 20-24 are reserved, without a size) leave the configuration alone.
    QVERIFY(!rig.ok("LOG HI83 MAP 0x00100000"));
    QCOMPARE(rig.sim.runningConfig().hi83Map, uint32_t(map));
}

void TestHipnucSimulator::ppsAlignsTheClockToUtc()
{
    // v1.7.1 manual 2.2.2: a PPS edge with its time message aligns the clock to the UTC
    // second; afterwards UTC_UNSYNC (5.9.13 bit 11) is clear and the HI91 system_time is the
    // ms of the UTC day. 2.2.1: the same pin's edge triggers the ONMARK 1 messages.
    constexpr uint16_t kUnsync = 1u << 11;
    SimOptions o;
    o.ppsInput = true;
    Rig rig(o);
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.1"));
    const auto before = rig.run(500000).packets<Hi91>();
    QVERIFY(!before.empty());
    QVERIFY(!rig.sim.utcSynced());
    QVERIFY(before.back().mainStatus & kUnsync);
    QVERIFY(before.back().systemTime < 1000); // ms since power-on
    const auto after = rig.run(1000000).packets<Hi91>();
    QVERIFY(rig.sim.utcSynced());
    const Hi91 &last = after.back();
    QCOMPARE(last.mainStatus & kUnsync, 0);
    const uint32_t utcMs = uint32_t((HipnucSimulator::kUtcBaseUnixS * 1000 + rig.sim.nowUs() / 1000) % 86400000);
    QVERIFY2(last.systemTime <= utcMs && last.systemTime + 200 >= utcMs,
             qPrintable(QStringLiteral("%1 vs %2").arg(last.systemTime).arg(utcMs)));
    // ONMARK 1 now fires once per PPS edge.
    QVERIFY(rig.ok("LOG HI91 ONTIME 0"));
    QVERIFY(rig.ok("LOG HI83 ONMARK 1"));
    rig.run(1000); // what was queued
    QCOMPARE(rig.run(3000000).countTag(TagHi83), 3);

    // Without a PPS input the clock stays the time since power-on.
    Rig plain;
    QVERIFY(plain.ok("LOG HI91 ONTIME 0.1"));
    const auto free = plain.run(2500000).packets<Hi91>();
    QVERIFY(free.back().mainStatus & kUnsync);
    QVERIFY(free.back().systemTime < 3000);
    QVERIFY(!plain.sim.utcSynced());
}

void TestHipnucSimulator::hi91Contents()
{
    Rig rig;
    const auto f = rig.run(508000).packets<Hi91>(); // the frame due at 500 ms takes 7.1 ms
    QCOMPARE(f.size(), size_t(50));
    const Hi91 &h = f.back();
    QCOMPARE(h.systemTime, uint32_t(500));
    QCOMPARE(int(h.temperature), 30);
    QVERIFY(std::fabs(h.pressure - 100000.0f) < 50.0f);
    QVERIFY(std::fabs(h.roll - MotionModel::kStaticRollDeg) < 1e-3);
    QVERIFY(std::fabs(h.pitch - MotionModel::kStaticPitchDeg) < 1e-3);
    QVERIFY(std::fabs(h.yaw - MotionModel::kStaticYawDeg) < 1e-3);
    QVERIFY(h.quat[0] >= 0);
    const SensorReading truth = rig.sim.sensorModel().ideal(rig.sim.motionModel().at(0.5));
    QVERIFY((vec(h.acc) - truth.acc).norm() < 0.005);
    QVERIFY((vec(h.gyr) - truth.gyr).norm() < 0.15);
    QVERIFY((vec(h.mag) - truth.mag).norm() < 1.0); // not calibrated yet: hard iron included
    // toSample (core) agrees.
    const model::Sample s = toSample(h);
    QVERIFY(std::fabs(s.acc.z - h.acc[2]) < 1e-6);
}

void TestHipnucSimulator::hi81Contents()
{
    Rig rig(opts("1.7.1", "HI14", Motion::Static, 921600)); // HI91 + HI81 at 100 Hz exceed 115200
    QVERIFY(rig.ok("LOG HI81 ONTIME 0.01"));
    rig.run(100000);
    const Capture c = rig.run(200000);
    const auto f81 = c.packets<Hi81>();
    const auto f91 = c.packets<Hi91>();
    QVERIFY(f81.size() >= 19 && !f91.empty());
    const Hi81 &p = f81.back();
    const Hi91 &h = f91.back();
    QCOMPARE(p.mainStatus, h.mainStatus);
    QCOMPARE(p.insStatus, uint8_t(0));
    QCOMPARE(p.lat, 0);
    QCOMPARE(p.lon, 0);
    QCOMPARE(p.velEnu, (std::array<int16_t, 3>{0, 0, 0}));
    QVERIFY(std::abs(p.roll - int(std::lround(h.roll * 100))) <= 1);
    QVERIFY(std::abs(p.pitch - int(std::lround(h.pitch * 100))) <= 1);
    // Heading: clockwise from north = 360 - yaw.
    QVERIFY(std::abs(int(p.yaw) - int(std::lround((360.0 - MotionModel::kStaticYawDeg) * 100))) <= 1);
    const model::Sample s = toSample(protocol::hipnuc::Packet(p));
    QVERIFY(std::fabs(angleDiff(s.yaw, h.yaw)) < 0.02);
    QVERIFY(std::fabs(std::sqrt(s.acc.x * s.acc.x + s.acc.y * s.acc.y + s.acc.z * s.acc.z) - 1.0) < 0.01);
    QVERIFY(std::fabs(s.pressurePa - 100000.0) < 50.0);
    QCOMPARE(int(p.utcYear), 24);
    QCOMPARE(int(p.utcMonth), 11);
    QCOMPARE(int(p.utcDay), 14);
    QCOMPARE(int(p.utcHour), 8);
}

void TestHipnucSimulator::hi92Contents()
{
    Rig rig(opts("1.6.6", "HI14", Motion::Spin, 921600)); // HI91 + HI92 at 100 Hz exceed 115200
    QVERIFY(rig.ok("LOG HI92 ONTIME 0.01"));
    rig.run(100000);
    const Capture c = rig.run(300000);
    const auto f92 = c.packets<Hi92>();
    const auto f91 = c.packets<Hi91>();
    QVERIFY(f92.size() >= 29 && f91.size() >= 29);
    const Hi92 &p = f92.back();
    const Hi91 &h = f91.back(); // same instant: both are due on the 10 ms grid
    QCOMPARE(p.status, uint16_t(0));
    QCOMPARE(h.mainStatus, uint16_t(0)); // reserved before 1.7.0
    QVERIFY(std::abs(p.yaw - int(std::lround(h.yaw * 1000))) <= 1);
    QVERIFY(std::abs(p.roll - int(std::lround(h.roll * 1000))) <= 1);
    QVERIFY(std::abs(p.quat[3] - int(std::lround(h.quat[3] * 1e4))) <= 1);
    const model::Sample s = toSample(protocol::hipnuc::Packet(p));
    QVERIFY(std::fabs(s.acc.z - h.acc[2]) < 0.002);
    QVERIFY(std::fabs(s.gyr.z - h.gyr[2]) < 0.06); // 0.001 rad/s steps
    QVERIFY(std::fabs(s.gyr.z - 30.0) < 0.5);
    QVERIFY(std::fabs(s.mag.y - h.mag[1]) < 0.05);
    QVERIFY(std::abs(p.pressure) < 50);
}

void TestHipnucSimulator::nmeaSentences()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0"));
    QVERIFY(rig.ok("LOG GGA ONTIME 1"));
    QVERIFY(rig.ok("LOG RMC ONTIME 1"));
    QVERIFY(rig.ok("LOG SXT ONTIME 1"));
    rig.run(800000); // now at about 1.2 s
    const Capture c = rig.run(1000000);
    QCOMPARE(c.nmeaErrors, 0);
    QCOMPARE(c.countSentences("GGA"), 1);
    QCOMPARE(c.countSentences("RMC"), 1);
    QCOMPARE(c.countSentences("SXT"), 1);
    for (const auto &s : c.sentences) {
        if (s.type == "GGA") {
            QVERIFY(s.gga);
            QVERIFY(std::fabs(*s.gga->latitudeDeg - 31.2083333) < 1e-6);
            QVERIFY(std::fabs(*s.gga->longitudeDeg - 121.4583333) < 1e-6);
            QCOMPARE(s.gga->time->hour, 8);
            QCOMPARE(s.gga->time->minute, 0);
            QCOMPARE(s.gga->time->second, 2.0); // due at 2 s of simulation time
        } else if (s.type == "RMC") {
            QVERIFY(s.rmc && s.rmc->valid);
            QCOMPARE(s.rmc->date->year, 2024);
            QCOMPARE(s.rmc->date->month, 11);
            QCOMPARE(s.rmc->date->day, 14);
            QVERIFY(std::fabs(*s.rmc->courseDeg - (360.0 - MotionModel::kStaticYawDeg)) < 0.06);
        } else {
            QCOMPARE(s.talker, std::string("GP"));
            QCOMPARE(s.fields.size(), size_t(21));
            QCOMPARE(s.fields[0], std::string("20241114080002.00"));
            QCOMPARE(std::stod(s.fields[1]), 121.458333);
            QVERIFY(std::fabs(std::stod(s.fields[5]) - MotionModel::kStaticPitchDeg) < 0.01);
        }
    }
}

void TestHipnucSimulator::mainStatus_data()
{
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<QString>("model");
    QTest::addColumn<Motion>("motion");
    QTest::addColumn<int>("early");
    QTest::addColumn<int>("later");
    const int utc = bit(MainStatus::UtcUnsync), mag = bit(MainStatus::MagAiding), st = bit(MainStatus::Static),
              wb = bit(MainStatus::WbConv), dist = bit(MainStatus::MagDist);
    QTest::newRow("HI14 static") << "1.7.1" << "HI14" << Motion::Static << (utc | mag | st | wb | dist)
                                 << (utc | mag | st | dist);
    QTest::newRow("HI14 spin") << "1.7.1" << "HI14" << Motion::Spin << (utc | mag | wb | dist) << (utc | mag | dist);
    QTest::newRow("HI02 static") << "1.7.1" << "HI02" << Motion::Static << (utc | st | wb) << (utc | st);
    QTest::newRow("HI14 1.7.0") << "1.7.0" << "HI14" << Motion::Static << (utc | mag | st | wb | dist)
                                << (utc | mag | st | dist);
    QTest::newRow("HI14 1.6.6") << "1.6.6" << "HI14" << Motion::Static << 0 << 0;
}

void TestHipnucSimulator::mainStatus()
{
    QFETCH(QString, firmware);
    QFETCH(QString, model);
    QFETCH(Motion, motion);
    QFETCH(int, early);
    QFETCH(int, later);
    Rig rig(opts(firmware.toStdString(), model.toStdString(), motion));
    const auto a = rig.run(1000000).packets<Hi91>();
    QCOMPARE(int(a.back().mainStatus), early);
    rig.run(2500000);
    const auto b = rig.run(500000).packets<Hi91>();
    QCOMPARE(int(b.front().mainStatus), later);
    // WB_CONV returns after a restart.
    rig.sim.powerCycle();
    const auto c = rig.run(500000).packets<Hi91>();
    QCOMPARE(int(c.back().mainStatus), early);
}

void TestHipnucSimulator::modelGates()
{
    Rig hi02(opts("1.7.1", "HI02"));
    QCOMPARE(hi02.sim.runningConfig().attMode, 0);
    QVERIFY(!hi02.sim.hasMagnetometer());
    QVERIFY(!hi02.sim.hasPmux());
    QCOMPARE(QString::fromStdString(outcome(hi02.command("CONFIG ATT MODE 1"))), QStringLiteral("ERR"));
    QCOMPARE(hi02.sim.runningConfig().attMode, 0);
    const AsciiReply cc = hi02.command("LOG COMCONFIG");
    QVERIFY(cc.values.count("PMUX1") == 0);
    Rig hi50(opts("1.7.1", "HI50"));
    QVERIFY(!hi50.ok("CONFIG ATT MODE 1"));
    QVERIFY(hi50.ok("CONFIG ATT RST 5"));
    Rig hi92(opts("1.7.1", "HI92"));
    QVERIFY(hi92.sim.hasMagnetometer());
    QVERIFY(!hi92.sim.hasPmux());
    QCOMPARE(hi92.sim.family(), model::ProductFamily::HI7x_9x);
}

void TestHipnucSimulator::attitudeResets()
{
    Rig rig; // static, 9-axis, yaw 35
    auto last = [&rig] { return rig.run(100000).packets<Hi91>().back(); };
    Hi91 h = last();
    QVERIFY(std::fabs(h.yaw - 35.0f) < 1e-3);
    // RST 1: heading to zero.
    QVERIFY(rig.ok("CONFIG ATT RST 1"));
    h = last();
    QVERIFY(std::fabs(h.yaw) < 1e-3);
    QVERIFY(std::fabs(h.roll - 1.5f) < 1e-3);
    // RST 2: relative level; acc keeps its tilt (only the angles are zeroed).
    const Eigen::Vector3d accBefore = vec(h.acc);
    QVERIFY(rig.ok("CONFIG ATT RST 2"));
    h = last();
    QVERIFY(std::fabs(h.roll) < 1e-3 && std::fabs(h.pitch) < 1e-3);
    QVERIFY(std::fabs(h.yaw) < 1e-3);
    QVERIFY((vec(h.acc) - accBefore).norm() < 0.005);
    // RST 5 clears RST 2.
    QVERIFY(rig.ok("CONFIG ATT RST 5"));
    h = last();
    QVERIFY(std::fabs(h.roll - 1.5f) < 1e-3 && std::fabs(h.pitch + 2.5f) < 1e-3);
    // RST 3: auto level, acc levelled too, permanent (RST 5 does not undo it, it survives a reboot).
    QVERIFY(rig.ok("CONFIG ATT RST 3"));
    h = last();
    QVERIFY(std::fabs(h.roll) < 1e-3 && std::fabs(h.pitch) < 1e-3);
    QVERIFY(std::fabs(h.acc[0]) < 0.005f && std::fabs(h.acc[1]) < 0.005f);
    QVERIFY(rig.ok("CONFIG ATT RST 5"));
    QVERIFY(rig.ok("REBOOT", 400000));
    h = last();
    QVERIFY(std::fabs(h.roll) < 1e-3 && std::fabs(h.pitch) < 1e-3);
    QVERIFY(std::fabs(h.yaw - 35.0f) < 0.1f); // RST 1 was a runtime correction
    // RST 2 is saved with SAVECONFIG.
    Rig saved;
    QVERIFY(saved.ok("CONFIG ATT RST 2"));
    QVERIFY(saved.ok("SAVECONFIG"));
    QVERIFY(saved.ok("REBOOT", 400000));
    const Hi91 s = saved.run(100000).packets<Hi91>().back();
    QVERIFY(std::fabs(s.roll) < 1e-3 && std::fabs(s.pitch) < 1e-3);

    // RST 3 refuses a tilted module.
    Rig tilted(opts("1.7.1", "HI14", Motion::Tumble));
    int64_t t = 0;
    for (; t < 20000000; t += 10000) {
        tilted.sim.advanceTo(t);
        const EulerAngles e = eulerEnu312(tilted.sim.currentAttitude());
        if (std::fabs(e.pitch) > 20 && std::fabs(e.roll) > 20 && std::fabs(e.roll) < 160)
            break;
    }
    QVERIFY(t < 20000000);
    tilted.sim.takeOutput();
    QCOMPARE(QString::fromStdString(outcome(tilted.command("CONFIG ATT RST 3", 10000))), QStringLiteral("ERR"));
}

void TestHipnucSimulator::legacyYawCommand()
{
    Rig rig(opts("1.6.6"));
    auto yaw = [&rig] { return rig.run(100000).packets<Hi91>().back().yaw; };
    QVERIFY(std::fabs(yaw() - 35.0f) < 1e-3);
    QVERIFY(rig.ok("CONFIG YAW 1 16"));
    QVERIFY(std::fabs(yaw() - 16.0f) < 1e-3);
    QVERIFY(rig.ok("CONFIG YAW 0 1.5"));
    QVERIFY(std::fabs(yaw() - 17.5f) < 1e-3);
    QVERIFY(rig.ok("CONFIG YAW 1 -170"));
    QVERIFY(std::fabs(yaw() + 170.0f) < 1e-3);
    QVERIFY(rig.ok("SAVECONFIG"));
    QVERIFY(rig.ok("REBOOT", 400000));
    QVERIFY(std::fabs(yaw() - 35.0f) < 1e-3); // not saved
}

void TestHipnucSimulator::sixAxisHeadingStartsAtZero()
{
    Rig rig(opts("1.7.1", "HI14", Motion::Spin));
    QVERIFY(rig.ok("CONFIG ATT MODE 0"));
    const Hi91 before = rig.run(100000).packets<Hi91>().back();
    QVERIFY(before.mainStatus & bit(MainStatus::MagAiding)); // not active until a restart
    QVERIFY(rig.ok("SAVECONFIG"));
    rig.sim.receive("REBOOT\r\n");
    rig.run(300000);
    const auto f = rig.run(500000).packets<Hi91>();
    QVERIFY(!f.empty());
    QCOMPARE(f.front().mainStatus & (bit(MainStatus::MagAiding) | bit(MainStatus::MagDist)), 0);
    // Yaw counts from 0 at the restart and turns at 30 deg/s (counter-clockwise positive).
    for (const Hi91 &h : f)
        QVERIFY2(std::fabs(angleDiff(h.yaw, 30.0 * h.systemTime / 1000.0)) < 0.01, qPrintable(QString::number(h.yaw)));
}

void TestHipnucSimulator::gyroCalibration_data()
{
    QTest::addColumn<Motion>("motion");
    QTest::addColumn<int>("angle");
    QTest::addColumn<double>("seconds");
    QTest::addColumn<bool>("ok");
    QTest::newRow("720 exact") << Motion::Spin << 720 << 24.0 << true;
    QTest::newRow("720 +4.5 deg") << Motion::Spin << 720 << 24.15 << true;
    QTest::newRow("720 -4.5 deg") << Motion::Spin << 720 << 23.85 << true;
    QTest::newRow("720 +30 deg") << Motion::Spin << 720 << 25.0 << false;
    QTest::newRow("720 -30 deg") << Motion::Spin << 720 << 23.0 << false;
    QTest::newRow("1080") << Motion::Spin << 1080 << 36.0 << true;
    QTest::newRow("1800") << Motion::Spin << 1800 << 60.0 << true;
    QTest::newRow("static") << Motion::Static << 720 << 24.0 << false;
}

void TestHipnucSimulator::gyroCalibration()
{
    QFETCH(Motion, motion);
    QFETCH(int, angle);
    QFETCH(double, seconds);
    QFETCH(bool, ok);
    Rig rig(opts("1.7.1", "HI14", motion));
    rig.run(1234000);
    rig.sim.receive("CONFIG USRCAL START " + std::to_string(angle) + "\r\n");
    QVERIFY(rig.sim.gyroCalActive());
    const Capture start = rig.run(int64_t(std::llround(seconds * 1e6)));
    QVERIFY(!start.lines.empty() && start.lines.front() == "OK");
    QVERIFY(std::fabs(rig.sim.gyroCalAngleDeg() - (motion == Motion::Spin ? 30.0 * seconds : 0.0)) < 0.5);
    const AsciiReply r = rig.command("CONFIG USRCAL STOP", 10000);
    QCOMPARE(QString::fromStdString(outcome(r)), QString(ok ? "OK" : "ERR"));
    QVERIFY(!rig.sim.gyroCalActive());
    QVERIFY(!rig.ok("CONFIG USRCAL STOP")); // nothing running any more
}

void TestHipnucSimulator::magCalTumbleCompletes()
{
    Rig rig(opts("1.7.1", "HI14", Motion::Tumble));
    rig.run(500000);
    auto stat = [&rig] {
        const AsciiReply r = rig.command("LOG MCAL STAT", 10000);
        return std::make_pair(std::stoi(r.values.at("STAT")), std::stoi(r.values.at("PROGRESS")));
    };
    QCOMPARE(stat(), std::make_pair(0, 0));
    QVERIFY(rig.run(100000).packets<Hi91>().back().mainStatus & bit(MainStatus::MagDist));
    QVERIFY(rig.ok("CONFIG MCAL START", 10000));
    int previous = 0;
    for (int s = 0; s < 4; ++s) {
        rig.run(10000000);
        const auto [st, progress] = stat();
        QCOMPARE(st, 1);
        QVERIFY2(progress > previous && progress < 100, qPrintable(QString::number(progress)));
        previous = progress;
    }
    rig.run(25000000); // 65 s after START
    QCOMPARE(stat(), std::make_pair(3, 100));
    QVERIFY(rig.sim.magCalibrated());
    // MAG_DIST clears; the hard iron is gone from mag.
    const auto f = rig.run(200000).packets<Hi91>();
    QCOMPARE(f.back().mainStatus & bit(MainStatus::MagDist), 0);
    const SensorModel &sm = rig.sim.sensorModel();
    for (const Hi91 &h : f) {
        const double t = (rig.sim.startedAtUs() + int64_t(h.systemTime) * 1000) * 1e-6;
        const Eigen::Vector3d clean = sm.softIron() * (rig.sim.motionModel().at(t).q.toRotationMatrix().transpose()
                                                       * SensorModel::fieldNav());
        QVERIFY((vec(h.mag) - clean).norm() < 1.0);
    }
    // The calibration survives a reboot; STAT is idle again.
    QVERIFY(rig.ok("REBOOT", 400000));
    QCOMPARE(stat(), std::make_pair(0, 0));
    QCOMPARE(rig.run(100000).packets<Hi91>().back().mainStatus & bit(MainStatus::MagDist), 0);
}

void TestHipnucSimulator::magCalStaticFails()
{
    Rig rig; // static
    QVERIFY(rig.ok("CONFIG MCAL START"));
    rig.run(60000000);
    AsciiReply r = rig.command("LOG MCAL STAT", 10000);
    QCOMPARE(r.values.at("STAT"), std::string("1"));
    QVERIFY(std::stoi(r.values.at("PROGRESS")) < 10);
    rig.run(61000000);
    r = rig.command("LOG MCAL STAT", 10000);
    QCOMPARE(r.values.at("STAT"), std::string("4"));
    QVERIFY(!rig.sim.magCalibrated());
    QVERIFY(rig.run(100000).packets<Hi91>().back().mainStatus & bit(MainStatus::MagDist));
    // A new start resets the progress.
    QVERIFY(rig.ok("CONFIG MCAL START"));
    QCOMPARE(rig.command("LOG MCAL STAT", 10000).values.at("STAT"), std::string("1"));
}

void TestHipnucSimulator::legacyBackgroundMagCal_data()
{
    QTest::addColumn<Motion>("motion");
    QTest::addColumn<bool>("enabled");
    QTest::addColumn<bool>("calibrates");
    QTest::addColumn<double>("disturbanceUt");
    QTest::newRow("tumble") << Motion::Tumble << true << true << 0.0;
    QTest::newRow("tumble, IMU_EN_MCAL 0") << Motion::Tumble << false << false << 0.0;
    QTest::newRow("static") << Motion::Static << true << false << 0.0;
    QTest::newRow("tumble, magnetic disturbance") << Motion::Tumble << true << false << 40.0;
}

void TestHipnucSimulator::legacyBackgroundMagCal()
{
    QFETCH(Motion, motion);
    QFETCH(bool, enabled);
    QFETCH(bool, calibrates);
    QFETCH(double, disturbanceUt);
    SimFaults faults;
    faults.magDisturbanceUt = disturbanceUt;
    Rig rig(withFaults(faults, opts("1.6.6", "HI14", motion)));
    if (!enabled)
        QVERIFY(rig.ok("CONFIG IMU_EN_MCAL 0", 1000));
    AsciiReply r = rig.command("LOG MAGCONFIG");
    QVERIFY(r.ok());
    QCOMPARE(r.lines, std::vector<std::string>{"MB=0.00, 0.00, 0.00"});
    rig.run(30000000);
    QCOMPARE(rig.command("LOG MAGCONFIG").lines.front(), std::string("MB=0.00, 0.00, 0.00"));
    rig.run(40000000);
    r = rig.command("LOG MAGCONFIG");
    QVERIFY(r.ok());
    if (!calibrates) {
        QCOMPARE(r.lines.front(), std::string("MB=0.00, 0.00, 0.00"));
        return;
    }
    const Eigen::Vector3d h = rig.sim.sensorModel().hardIron();
    char want[96];
    std::snprintf(want, sizeof want, "MB=%.2f, %.2f, %.2f", h.x(), h.y(), h.z());
    QCOMPARE(r.lines.front(), std::string(want));
    // The mag output is calibrated now.
    const auto f = rig.run(100000).packets<Hi91>();
    const double t = (rig.sim.startedAtUs() + int64_t(f.back().systemTime) * 1000) * 1e-6;
    const Eigen::Vector3d clean = rig.sim.sensorModel().softIron()
        * (rig.sim.motionModel().at(t).q.toRotationMatrix().transpose() * SensorModel::fieldNav());
    QVERIFY((vec(f.back().mag) - clean).norm() < 1.0);
}

void TestHipnucSimulator::bootloaderPing()
{
    Rig rig;
    rig.run(108000);
    rig.sim.receive("REBOOT BL\r\n");
    const Capture ok = rig.run(5000);
    QCOMPARE(ok.lines, std::vector<std::string>{"OK"});
    rig.run(50000);
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::Bootloader);
    QCOMPARE(rig.sim.baud(), 115200); // the bootloader runs at the application's baud
    // No output, ASCII ignored.
    QVERIFY(rig.run(500000).raw.empty());
    rig.sim.receive("LOG VERSION\r\nREBOOT\r\n");
    QVERIFY(rig.run(500000).raw.empty());
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::Bootloader);
    // KBOOT ping.
    const uint8_t ping[] = {0x5A, 0xA6};
    rig.sim.receive(ping, 2);
    const std::vector<uint8_t> resp = rig.run(10000).raw;
    const std::vector<uint8_t> want = {0x5A, 0xA7, 0x00, 0x00, 0x02, 0x50, 0x00, 0x00, 0xF5, 0x35};
    QCOMPARE(resp, want);
    QCOMPARE(crc16(want.data(), 8), uint16_t(0x35F5));
    // Split across two reads, after garbage.
    rig.sim.receive(ping, 1);
    rig.sim.receive(ping + 1, 1);
    QCOMPARE(rig.run(10000).raw, want);
    // Power cycle: back to the application.
    rig.sim.powerCycle();
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::App);
    QVERIFY(rig.ok("LOG VERSION"));
    QVERIFY(rig.run(200000).countTag(TagHi91) >= 19);
}

void TestHipnucSimulator::uartDropsFramesWhenBaudTooLow()
{
    Rig rig;
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.001", 10000));
    rig.run(1000000);
    QVERIFY(rig.sim.droppedFrames() > 500);
    QVERIFY(rig.sim.txQueuedBytes() <= HipnucSimulator::kTxBufferSize);
    const uint64_t droppedBefore = rig.sim.droppedFrames();
    const Capture c = rig.run(1000000);
    // 115200 baud = 11520 bytes/s = about 140 HI91 frames per second.
    const int n = c.countTag(TagHi91);
    QVERIFY2(n >= 138 && n <= 142, qPrintable(QString::number(n)));
    QVERIFY(c.raw.size() <= 11521);
    QVERIFY(std::abs(int(rig.sim.droppedFrames() - droppedBefore) - (1000 - n)) <= 1);
    // Every frame that went out is intact.
    QCOMPARE(rig.demux.frameCounters().crcErrors, uint64_t(0));
    const auto f = c.packets<Hi91>();
    for (size_t i = 1; i < f.size(); ++i)
        QVERIFY(f[i].systemTime > f[i - 1].systemTime);
    // Replies still get through.
    QVERIFY(rig.ok("LOG VERSION", 500000));
}

void TestHipnucSimulator::uartNoDropsAtHighBaud()
{
    Rig rig(opts("1.7.1", "HI14", Motion::Static, 921600));
    QVERIFY(rig.ok("LOG HI91 ONTIME 0.001", 10000));
    rig.run(500000);
    const Capture c = rig.run(1000000);
    QVERIFY(std::abs(c.countTag(TagHi91) - 1000) <= 1);
    QCOMPARE(rig.sim.droppedFrames(), uint64_t(0));
}

// An old module updated over KBOOT becomes the new firmware: its LOG VERSION and its command set.
void TestHipnucSimulator::firmwareUpdateFrom166To171()
{
    Rig rig(opts("1.6.6"));
    AsciiReply v = rig.command("LOG VERSION");
    QVERIFY(v.ok());
    QCOMPARE(v.values.at("APP_VER"), std::string("166"));
    QCOMPARE(outcome(rig.command("CONFIG IMU COORD 4")), std::string("-")); // not on 1.6.6
    protocol::ihex::FirmwareImage img;
    img.startAddress = 0x8000;
    img.data = KbootBootloader::makeApplication("1.7.1", 72 * 1024, 5);
    sim::SimulatedByteLink link(rig.sim);
    firmware::UpdateFlow flow(link, firmware::UpdateFlow::Options{}, {});
    const auto r = flow.run(img);
    QVERIFY2(r.ok, qPrintable(r.message));
    QVERIFY(r.before && r.after);
    QCOMPARE(r.before->firmware->toString(), std::string("1.6.6"));
    QCOMPARE(r.after->firmware->toString(), std::string("1.7.1"));
    QCOMPARE(rig.sim.state(), HipnucSimulator::State::App);
    QCOMPARE(rig.sim.firmware().toString(), std::string("1.7.1"));
    QCOMPARE(rig.sim.edition(), model::ManualEdition::V171);
    rig.run(100000);
    rig.collect();
    v = rig.command("LOG VERSION");
    QVERIFY(v.ok());
    QCOMPARE(v.values.at("APP_VER"), std::string("171"));
    // The v1.7.1 command set, and none of the v1.6.6 words.
    QCOMPARE(outcome(rig.command("CONFIG IMU COORD 4")), std::string("OK"));
    QCOMPARE(outcome(rig.command("LOG HI81 ONTIME 0.1")), std::string("OK"));
    QCOMPARE(outcome(rig.command("LOG MCAL STAT")), std::string("OK"));
    QCOMPARE(outcome(rig.command("LOG HI92 ONTIME 0.1")), std::string("ERR"));
    QCOMPARE(outcome(rig.command("CONFIG IMU_EN_MCAL 1")), std::string("-"));
    QCOMPARE(outcome(rig.command("LOG MAGCONFIG")), std::string("-"));
    // It stays 1.7.1 after a power cycle (taken with the line idle: no frame cut in half).
    rig.quiet();
    rig.sim.powerCycle();
    v = rig.command("LOG VERSION");
    QVERIFY(v.ok());
    QCOMPARE(v.values.at("APP_VER"), std::string("171"));
}

void TestHipnucSimulator::faultNoisyGyro()
{
    SimFaults noisy;
    noisy.gyroNoiseFactor = 20;
    Rig clean, bad(withFaults(noisy));
    const auto a = clean.run(3000000).packets<Hi91>();
    const auto b = bad.run(3000000).packets<Hi91>();
    QVERIFY(a.size() >= 299 && b.size() >= 299); // 3 s at 100 Hz

    const double sa = gyroStd(a), sb = gyroStd(b);
    qInfo("gyro std per axis: %.4f deg/s clean, %.4f deg/s noisy", sa, sb);
    QVERIFY2(std::fabs(sa - SensorModel::kGyrNoiseDps) < 0.004, qPrintable(QString::number(sa)));
    QVERIFY2(std::fabs(sb - 20 * SensorModel::kGyrNoiseDps) < 0.08, qPrintable(QString::number(sb)));
    QVERIFY2(sb / sa > 17 && sb / sa < 23, qPrintable(QString::number(sb / sa)));
    // The same bias: only the noise grew.
    QVERIFY((bad.sim.sensorModel().gyroBias() - clean.sim.sensorModel().gyroBias()).norm() < 1e-12);
}

void TestHipnucSimulator::faultMounting()
{
    SimFaults side;
    side.mountingErrorDeg = {90, 0, 0};
    Rig clean(opts("1.7.1", "HI14", Motion::Static, 921600)), bad(withFaults(side, clean.sim.options()));
    for (Rig *r : {&clean, &bad})
        QVERIFY(r->ok("LOG HI81 ONTIME 0.01"));
    const Capture ca = clean.run(500000), cb = bad.run(500000);
    const Hi91 a = ca.packets<Hi91>().back(), b = cb.packets<Hi91>().back();
    QVERIFY2(std::fabs(a.roll - MotionModel::kStaticRollDeg) < 1e-3, qPrintable(QString::number(a.roll)));
    QVERIFY2(std::fabs(b.roll - (MotionModel::kStaticRollDeg + 90)) < 1e-3, qPrintable(QString::number(b.roll)));
    QVERIFY(std::fabs(b.pitch - a.pitch) < 1e-3);
    QVERIFY(std::fabs(angleDiff(b.yaw, a.yaw)) < 1e-3);
    QVERIFY(std::abs(cb.packets<Hi81>().back().roll - int(std::lround(b.roll * 100))) <= 1); // every message
    // What it measures is of the turned body: gravity along its x axis now, and the same field
    // magnitude (soft iron aside) in other axes; acc agrees with the reported attitude.
    QVERIFY2(b.acc[0] < -0.99f && std::fabs(a.acc[2] - 1.0f) < 0.01f, qPrintable(QString::number(b.acc[0])));
    const Eigen::Quaterniond q(b.quat[0], b.quat[1], b.quat[2], b.quat[3]);
    QVERIFY((vec(b.acc) - q.conjugate() * Eigen::Vector3d(0, 0, 1)).norm() < 0.005);
    const Eigen::Vector3d bodyMag = bad.sim.sensorModel().softIron().inverse()
        * (vec(b.mag) - bad.sim.sensorModel().hardIron());
    QVERIFY((bodyMag - q.conjugate() * SensorModel::fieldNav()).norm() < 1.0);
}

void TestHipnucSimulator::faultMagDisturbance_data()
{
    QTest::addColumn<double>("disturbanceUt");
    QTest::addColumn<int>("stat");
    QTest::newRow("clean fixture") << 0.0 << 3;
    QTest::newRow("motor beside the fixture") << SimFaults::kMagDisturbanceUt << 4;
}

void TestHipnucSimulator::faultMagDisturbance()
{
    QFETCH(double, disturbanceUt);
    QFETCH(int, stat);
    SimFaults faults;
    faults.magCalFixture = true;
    faults.magDisturbanceUt = disturbanceUt;
    Rig rig(withFaults(faults));
    // At rest, the measured field changes when (and only when) it is disturbed.
    const auto before = rig.run(6000000).packets<Hi91>();
    double lo = 1e9, hi = 0;
    for (const Hi91 &h : before) {
        lo = std::min(lo, vec(h.mag).norm());
        hi = std::max(hi, vec(h.mag).norm());
    }
    QVERIFY2(disturbanceUt > 0 ? hi - lo > 20 : hi - lo < 2, qPrintable(QString::number(hi - lo)));
    QVERIFY(before.back().mainStatus & bit(MainStatus::MagDist));
    // The fixture collects every direction either way; the disturbed one fails its check.
    const McalEnd end = runMagCal(rig);
    QCOMPARE(end.stat, stat);
    QCOMPARE(end.progress, 100);
    QCOMPARE(rig.sim.magCalibrated(), stat == 3);
    const uint16_t status = rig.run(100000).packets<Hi91>().back().mainStatus;
    QCOMPARE(bool(status & bit(MainStatus::MagDist)), stat != 3);
}

void TestHipnucSimulator::faultFixtureMagCal()
{
    SimFaults faults;
    faults.magCalFixture = true;
    Rig rig(withFaults(faults, opts("1.7.1", "HI14", Motion::Spin))); // the fixture holds it still
    const Eigen::Vector3d bias = rig.sim.sensorModel().gyroBias();
    auto atRest = [&](const Hi91 &h) {
        return std::fabs(h.roll - MotionModel::kStaticRollDeg) < 1e-3 && std::fabs(h.pitch - MotionModel::kStaticPitchDeg) < 1e-3
            && std::fabs(angleDiff(h.yaw, MotionModel::kStaticYawDeg)) < 1e-3 && (vec(h.gyr) - bias).norm() < 0.15
            && (h.mainStatus & bit(MainStatus::Static));
    };
    const auto still = rig.run(3500000).packets<Hi91>();
    for (const Hi91 &h : still)
        QVERIFY(atRest(h));
    // START: the fixture turns it.
    QVERIFY(rig.ok("CONFIG MCAL START", 10000));
    const auto turning = rig.run(5000000).packets<Hi91>();
    QVERIFY(!turning.empty());
    int moving = 0;
    for (const Hi91 &h : turning)
        moving += !atRest(h) && (vec(h.gyr) - bias).norm() > 10 && !(h.mainStatus & bit(MainStatus::Static));
    QVERIFY2(moving > int(turning.size()) - 2, qPrintable(QString::number(moving)));
    // Started again (the fixture starts over), it completes on the bench, and the module rests
    // at the static attitude again.
    const McalEnd end = runMagCal(rig);
    QCOMPARE(end.stat, 3);
    QCOMPARE(end.progress, 100);
    qInfo("MCAL on the fixture: %.1f s of simulated time from START to STAT=3", end.seconds);
    QVERIFY(end.seconds > 30 && end.seconds < 70);
    QVERIFY(rig.sim.magCalibrated());
    const auto after = rig.run(1000000).packets<Hi91>();
    QVERIFY(!after.empty());
    for (const Hi91 &h : after) {
        QVERIFY(atRest(h));
        QCOMPARE(h.mainStatus & bit(MainStatus::MagDist), 0);
    }
}

void TestHipnucSimulator::faultsText()
{
    SimFaults f;
    std::string error;
    QVERIFY(parseSimFaults("", f, &error));
    QVERIFY(f == SimFaults{});
    QCOMPARE(simFaultsText(f), std::string());
    // The short words and their defaults.
    QVERIFY(parseSimFaults(" noisy-gyro, Wrong-Mounting ,mag-disturbance,unplug=2.5,fixture", f, &error));
    QCOMPARE(f.gyroNoiseFactor, 20.0);
    QCOMPARE(f.mountingErrorDeg, (std::array<double, 3>{90, 0, 0}));
    QCOMPARE(f.magDisturbanceUt, 40.0);
    QCOMPARE(f.unplugAtS, 2.5);
    QVERIFY(f.magCalFixture);
    QCOMPARE(simFaultsText(f), std::string("noisy-gyro=20,mounting=90/0/0,mag-disturbance=40,unplug=2.5,fixture"));
    SimFaults back;
    QVERIFY(parseSimFaults(simFaultsText(f), back, &error));
    QVERIFY(back == f);
    // Values, round trip.
    SimFaults g;
    QVERIFY(parseSimFaults("noisy-gyro=3.5,mounting=-10/5.25/180,mag-disturbance=12.5,unplug=0", g, &error));
    QCOMPARE(g.mountingErrorDeg, (std::array<double, 3>{-10, 5.25, 180}));
    QCOMPARE(simFaultsText(g), std::string("noisy-gyro=3.5,mounting=-10/5.25/180,mag-disturbance=12.5,unplug=0"));
    SimFaults g2;
    QVERIFY(parseSimFaults(simFaultsText(g), g2, &error));
    QVERIFY(g2 == g);
    // Refused, with what is accepted; out is left as it was.
    const SimFaults keep = g;
    for (const char *bad : {"wobble", "noisy-gyro,wobble", "mounting=1/2", "mounting=1/2/3/4", "mounting=a/0/0",
                            "mounting", "unplug", "unplug=-1", "noisy-gyro=-2", "noisy-gyro=x", "mag-disturbance=-5",
                            "fixture=1", "wrong-mounting=1", "unplug=inf"}) {
        error.clear();
        QVERIFY2(!parseSimFaults(bad, g, &error), bad);
        QVERIFY2(!error.empty(), bad);
        QVERIFY2(g == keep, bad);
    }
    QVERIFY(!parseSimFaults("noisy-gyro, wobble", g, &error));
    QVERIFY2(error.find("wobble") != std::string::npos && error.find("noisy-gyro") != std::string::npos
                 && error.find("mounting=R/P/Y") != std::string::npos && error.find("unplug=T") != std::string::npos
                 && error.find("fixture") != std::string::npos,
             error.c_str());
}

IMUDESK_TEST_GUILESS_MAIN(TestHipnucSimulator)
#include "tst_hipnuc_simulator.moc"
