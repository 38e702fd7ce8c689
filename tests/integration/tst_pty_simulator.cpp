// PtySimulator end to end: a QSerialPort client on the pseudo-terminal, at the right
// and at the wrong baud, a baud switch to the non-standard 256000 (termios2 path),
// reconnecting, withDevice() on the simulator thread, and a pulled cable (SimFaults::unplugAtS).
#include "protocol/hipnuc/ascii_reply.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "sim/pty_simulator.h"
#include "../common/test_main.h"

#include <QElapsedTimer>
#include <QSerialPort>
#include <QTest>

#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

using namespace imudesk;
using namespace imudesk::sim;
using namespace imudesk::protocol::hipnuc;

namespace {

struct Received {
    QByteArray raw;
    std::vector<std::string> lines;
    std::vector<Hi91> hi91;
    int frames = 0;
};

// Splits the byte stream into frames and text lines. Unlike a plain StreamDemux, text
// collected before a frame is dropped when the frame arrives: a reply is never split by
// a frame, so that text can only be the tail of a frame the capture started inside.
class Splitter : public FrameDecoder::Sink {
public:
    Received *out = nullptr;
    void onFrame(const uint8_t *payload, size_t len) override
    {
        m_line.clear();
        ++out->frames;
        Hi91 h;
        if (decodeHi91(payload, len, h))
            out->hi91.push_back(h);
    }
    void onSkipped(const uint8_t *bytes, size_t n) override
    {
        for (size_t i = 0; i < n; ++i) {
            const uint8_t c = bytes[i];
            if (c == '\n') {
                if (!m_line.empty())
                    out->lines.push_back(m_line);
                m_line.clear();
            } else if (c >= 0x20 && c < 0x7F) {
                m_line.push_back(char(c));
            } else if (c != '\r') {
                m_line.clear();
            }
        }
    }

private:
    std::string m_line;
};

// One client's view of the port: the decoder state is kept between calls.
class Session {
public:
    explicit Session(QSerialPort &port) : m_port(port) {}

    // Reads for up to ms, or until done(r) is true; returns what arrived meanwhile.
    Received read(int ms, const std::function<bool(const Received &)> &done = {})
    {
        Received r;
        m_splitter.out = &r;
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < ms) {
            m_port.waitForReadyRead(20);
            const QByteArray chunk = m_port.readAll();
            if (chunk.isEmpty())
                continue;
            r.raw += chunk;
            m_decoder.feed(reinterpret_cast<const uint8_t *>(chunk.constData()), size_t(chunk.size()), m_splitter);
            if (done && done(r))
                break;
        }
        m_splitter.out = nullptr;
        return r;
    }

    // Sends a command once the stream is in sync (a frame was seen, when frames flow) and
    // returns the parsed reply (Pending = no reply within ms).
    AsciiReply command(const std::string &cmd, int ms = 1500)
    {
        read(300, [](const Received &r) { return r.frames > 0; });
        m_port.write((cmd + "\r\n").c_str());
        m_port.waitForBytesWritten(500);
        AsciiReply out;
        read(ms, [&](const Received &r) {
            ReplyCollector rc(cmd);
            for (const auto &l : r.lines)
                if (rc.addLine(l)) {
                    out = rc.take();
                    return true;
                }
            return false;
        });
        return out;
    }

private:
    QSerialPort &m_port;
    FrameDecoder m_decoder;
    Splitter m_splitter;
};

Received collect(QSerialPort &port, int ms)
{
    return Session(port).read(ms);
}

AsciiReply command(QSerialPort &port, const std::string &cmd, int ms = 1500)
{
    return Session(port).command(cmd, ms);
}

void drain(QSerialPort &port, int ms)
{
    collect(port, ms);
}

} // namespace

class TestPtySimulator : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void readLineSpeedOnOwnPty();
    void versionAt115200();
    void receivesHi91Frames();
    void wrongBaudIsGarbage();
    void switchTo256000();
    void reopenAfterClose();
    void withDeviceRunsOnSimulatorThread();
    void unpluggedCableHangsUp();

private:
    bool openPort(QSerialPort &port, int baud);
    PtySimulator *m_sim = nullptr;
};

bool TestPtySimulator::openPort(QSerialPort &port, int baud)
{
    port.setPortName(m_sim->devicePath());
    port.setBaudRate(baud);
    port.setDataBits(QSerialPort::Data8);
    port.setParity(QSerialPort::NoParity);
    port.setStopBits(QSerialPort::OneStop);
    port.setFlowControl(QSerialPort::NoFlowControl);
    if (!port.open(QIODevice::ReadWrite)) {
        qWarning("open %s: %s", qPrintable(port.portName()), qPrintable(port.errorString()));
        return false;
    }
    return true;
}

void TestPtySimulator::initTestCase()
{
    SimOptions o;
    o.model = "HI14";
    o.firmware = "1.7.1";
    o.seed = 5;
    m_sim = new PtySimulator(o);
    QString error;
    QVERIFY2(m_sim->start(&error), qPrintable(error));
    QVERIFY(m_sim->isRunning());
    QVERIFY2(m_sim->devicePath().startsWith("/dev/pts/"), qPrintable(m_sim->devicePath()));
}

void TestPtySimulator::cleanupTestCase()
{
    m_sim->stop();
    QVERIFY(!m_sim->isRunning());
    m_sim->stop(); // twice is fine
    delete m_sim;
}

void TestPtySimulator::readLineSpeedOnOwnPty()
{
    int master = -1, slave = -1;
    QCOMPARE(::openpty(&master, &slave, nullptr, nullptr, nullptr), 0);
    termios t{};
    ::tcgetattr(slave, &t);
    ::cfmakeraw(&t);
    ::cfsetispeed(&t, B9600);
    ::cfsetospeed(&t, B9600);
    ::tcsetattr(slave, TCSANOW, &t);
    QCOMPARE(PtySimulator::readLineSpeed(slave), 9600);
    QCOMPARE(PtySimulator::readLineSpeed(master), 9600); // the master reports the slave's settings
    ::cfsetispeed(&t, B921600);
    ::cfsetospeed(&t, B921600);
    ::tcsetattr(slave, TCSANOW, &t);
    QCOMPARE(PtySimulator::readLineSpeed(master), 921600);
    QCOMPARE(PtySimulator::readLineSpeed(-1), -1);
    ::close(slave);
    ::close(master);
}

void TestPtySimulator::versionAt115200()
{
    QSerialPort port;
    QVERIFY(openPort(port, 115200));
    QCOMPARE(PtySimulator::readLineSpeed(int(port.handle())), 115200);
    const AsciiReply r = command(port, "LOG VERSION");
    QVERIFY2(r.ok(), model::outcomeName(r.status));
    QCOMPARE(r.values.at("PNAME"), std::string("HI14R3"));
    QCOMPARE(r.values.at("APP_VER"), std::string("171"));
    QCOMPARE(r.values.at("BL_VER"), std::string("109"));
    QCOMPARE(r.values.at("UUID").size(), size_t(16));
    // Unknown commands stay unanswered.
    QCOMPARE(command(port, "HELLO", 500).status, AsciiReply::Status::Pending);
    QCOMPARE(command(port, "CONFIG ATT MODE 9").status, AsciiReply::Status::Refused);
}

void TestPtySimulator::receivesHi91Frames()
{
    QSerialPort port;
    QVERIFY(openPort(port, 115200));
    drain(port, 100);
    const Received r = collect(port, 1000);
    QVERIFY2(r.hi91.size() >= 80 && r.hi91.size() <= 110, qPrintable(QString::number(r.hi91.size())));
    for (size_t i = 1; i < r.hi91.size(); ++i)
        QCOMPARE(r.hi91[i].systemTime - r.hi91[i - 1].systemTime, uint32_t(10));
    for (const Hi91 &h : r.hi91) {
        const double g = std::sqrt(h.acc[0] * h.acc[0] + h.acc[1] * h.acc[1] + h.acc[2] * h.acc[2]);
        QVERIFY(std::fabs(g - 1.0) < 0.01);
    }
    const auto stats = m_sim->stats();
    QVERIFY(stats.bytesOut > 8000);
}

void TestPtySimulator::wrongBaudIsGarbage()
{
    QSerialPort port;
    QVERIFY(openPort(port, 9600));
    QCOMPARE(PtySimulator::readLineSpeed(int(port.handle())), 9600);
    drain(port, 150);
    const auto before = m_sim->stats();
    port.write("LOG VERSION\r\n");
    port.waitForBytesWritten(500);
    const Received r = collect(port, 1000);
    QCOMPARE(r.frames, 0);        // no valid frame
    QVERIFY(r.lines.empty());     // no reply, no text
    QVERIFY(!r.raw.isEmpty());    // but the line is not quiet: garbage
    QVERIFY(r.raw.size() < 2000); // about 9600/115200 of what the module sent
    for (char c : r.raw)
        QVERIFY(uint8_t(c) >= 0x80);
    const auto after = m_sim->stats();
    QVERIFY(after.bytesDiscarded >= before.bytesDiscarded + 13);
    QVERIFY(after.bytesGarbled > before.bytesGarbled + 5000);
    int baud = 0;
    m_sim->withDevice([&baud](HipnucSimulator &d) { baud = d.baud(); });
    QCOMPARE(baud, 115200);
    // Back to the right speed on the same open port: frames again.
    QVERIFY(port.setBaudRate(115200));
    drain(port, 100);
    QVERIFY(collect(port, 500).hi91.size() >= 30);
}

void TestPtySimulator::switchTo256000()
{
    QSerialPort port;
    QVERIFY(openPort(port, 115200));
    drain(port, 50);
    const AsciiReply ok = command(port, "SERIALCONFIG 256000");
    QVERIFY(ok.ok()); // sent at the old baud
    int baud = 0;
    m_sim->withDevice([&baud](HipnucSimulator &d) { baud = d.baud(); });
    QCOMPARE(baud, 256000);
    // Still at 115200 on our side: nothing valid arrives.
    drain(port, 50);
    QCOMPARE(collect(port, 300).frames, 0);
    // Custom (non-standard) rate: Qt uses termios2 BOTHER; the simulator reads it with TCGETS2.
    QVERIFY2(port.setBaudRate(256000), qPrintable(port.errorString()));
    QCOMPARE(PtySimulator::readLineSpeed(int(port.handle())), 256000);
    drain(port, 100);
    const Received r = collect(port, 500);
    QVERIFY2(r.hi91.size() >= 40, qPrintable(QString::number(r.hi91.size())));
    const AsciiReply v = command(port, "LOG VERSION");
    QVERIFY(v.ok());
    QCOMPARE(v.values.at("PNAME"), std::string("HI14R3"));
    // Back to 115200 for the next tests.
    QVERIFY(command(port, "SERIALCONFIG 115200").ok());
    QVERIFY(port.setBaudRate(115200));
    drain(port, 50);
    QVERIFY(command(port, "LOG VERSION").ok());
}

void TestPtySimulator::reopenAfterClose()
{
    {
        QSerialPort port;
        QVERIFY(openPort(port, 115200));
        QVERIFY(command(port, "LOG VERSION").ok());
        port.close();
    }
    // Nobody listens: output is lost, not stored. Closed until more is lost than the check
    // below lets through, so that a stored backlog could not pass it.
    const qsizetype mostIn300Ms = 115200 / 10 * 300 / 1000 + 200;
    const uint64_t lostBefore = m_sim->stats().bytesLost;
    QTRY_VERIFY_WITH_TIMEOUT(m_sim->stats().bytesLost > lostBefore + uint64_t(mostIn300Ms), 10000);
    QVERIFY(m_sim->stats().bytesLost > 0);
    QSerialPort again;
    QVERIFY(openPort(again, 115200));
    const Received r = collect(again, 300);
    QVERIFY(!r.hi91.empty());
    // No backlog of frames from while the port was closed: at most what 300 ms carry.
    QVERIFY2(r.raw.size() < mostIn300Ms, qPrintable(QString::number(r.raw.size())));
    QVERIFY(command(again, "LOG COMCONFIG").ok());
}

void TestPtySimulator::withDeviceRunsOnSimulatorThread()
{
    QThread *simThread = nullptr;
    m_sim->withDevice([&simThread](HipnucSimulator &d) {
        simThread = QThread::currentThread();
        d.powerCycle();
    });
    QVERIFY(simThread != nullptr);
    QVERIFY(simThread != QThread::currentThread());
    uint32_t ms = 0;
    HipnucSimulator::State state{};
    m_sim->withDevice([&](HipnucSimulator &d) {
        ms = d.systemTimeMs();
        state = d.state();
    });
    QCOMPARE(state, HipnucSimulator::State::App);
    QVERIFY(ms < 1000);
    // The device keeps serving after the power cycle.
    QSerialPort port;
    QVERIFY(openPort(port, 115200));
    QVERIFY(command(port, "LOG VERSION").ok());
}

void TestPtySimulator::unpluggedCableHangsUp()
{
    SimOptions o;
    o.seed = 7;
    o.faults.unplugAtS = 1.0;
    PtySimulator sim(o);
    QElapsedTimer sinceStart;
    sinceStart.start();
    QVERIFY(sim.start());
    QSerialPort port;
    port.setPortName(sim.devicePath());
    port.setBaudRate(115200);
    QVERIFY2(port.open(QIODevice::ReadWrite), qPrintable(port.errorString()));
    qint64 errorAtMs = -1;
    QSerialPort::SerialPortError error = QSerialPort::NoError;
    // (A read that waited in vain is TimeoutError: a machine too busy to run the simulator for a
    // while, not the hang-up.)
    QObject::connect(&port, &QSerialPort::errorOccurred, &port, [&](QSerialPort::SerialPortError e) {
        if (e != QSerialPort::NoError && e != QSerialPort::TimeoutError && errorAtMs < 0) {
            errorAtMs = sinceStart.elapsed();
            error = e;
        }
    });
    // Frames flow until the cable goes; then the client sees the hang-up.
    Session session(port);
    size_t frames = 0;
    while (errorAtMs < 0 && sinceStart.elapsed() < 4000 && port.isOpen())
        frames += session.read(50).hi91.size();
    QVERIFY2(errorAtMs >= 950 && errorAtMs < 2000, qPrintable(QString::number(errorAtMs)));
    // What a pulled USB adapter gives QSerialPort (io/serial_transport.cpp treats both as the device lost).
    QVERIFY2(error == QSerialPort::ReadError || error == QSerialPort::ResourceError, qPrintable(QString::number(error)));
    // Frames flowed: a quarter of the second's hundred at least. The module's clock starts with
    // sim.start(), so what it sent before a busy machine let this client open the port went to
    // nobody (46 frames beside two busy loops, against about 95 on an idle machine).
    QVERIFY2(frames >= 25, qPrintable(QString::number(frames)));
    // The simulator's thread sets the flag just after it hangs up: the client may be faster.
    QTRY_VERIFY_WITH_TIMEOUT(sim.stats().unplugged, 2000);
    QVERIFY(!m_sim->stats().unplugged);
    // The device never comes back: once the client lets go, the pty is gone.
    port.close();
    const auto opensAgain = [&sim] {
        QSerialPort again; // closed again as it goes
        again.setPortName(sim.devicePath());
        return again.open(QIODevice::ReadWrite);
    };
    QTRY_VERIFY_WITH_TIMEOUT(!opensAgain(), 5000);
    sim.stop();
}

IMUDESK_TEST_GUILESS_MAIN(TestPtySimulator)
#include "tst_pty_simulator.moc"
