// Hec495Session against the simulated HEC495: identity in question/answer mode (polled
// samples), the 3 s quiet window then 50 Hz auto-output, every settings command with typed
// results, a baud change the session follows, address changes, auto-baud, RS-485 retries, and
// a planar calibration run.
//
// In process by default (sim::SimulatedTransport in the session's thread, tests/common/
// inproc_link.h); baudChangeFollowed and autoBaudAndAddress run over a pseudo-terminal and
// prove the real serial path (termios rates, a rate change on the port, auto-baud).
#include "../common/inproc_link.h"
#include "../common/test_main.h"
#include "device/hec495_session.h"
#include "itemmodels/latest_values_model.h"
#include "plot/channel_history.h"
#include "record/capture_exporter.h"
#include "record/file_analysis.h"
#include "record/replay_session.h"
#include "sim/hec495_simulator.h"
#include "sim/pty_simulator.h"
#include "record/recording.h"

#include <algorithm>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <atomic>
#include <chrono>
#include <thread>
#include <functional>
#include <memory>
#include <optional>

using namespace imudesk;
using namespace imudesk::device;
using namespace imudesk::sim;
namespace wl = imudesk::protocol::witlink;

namespace {

// A simulated compass and the session that talks to it. Members in this order: the session
// closes before the simulator goes.
struct Compass {
    std::unique_ptr<PtySimulator> pty;     // over a pseudo-terminal
    SimulatedTransport *link = nullptr;    // in process (the session owns it)
    std::unique_ptr<Hec495Session> session;
    QString port;

    // Runs fn with the simulated compass in its thread and waits.
    void withSim(const std::function<void(Hec495Simulator &)> &fn)
    {
        if (pty)
            pty->withSerialDevice([&fn](SimulatedSerialDevice &d) { fn(dynamic_cast<Hec495Simulator &>(d)); });
        else
            test::withLinkDevice<Hec495Simulator>(link, fn);
    }
};

// In process; timeScale > 1 runs the compass's clock faster than real time (only for checks on
// the device's own clock: its seconds, its turns).
Compass serve(Hec495Options o, double timeScale = 1.0)
{
    auto in = test::inProcSession<Hec495Session>(std::make_unique<Hec495Simulator>(o),
                                                 QStringLiteral("sim:HEC495"), timeScale);
    Compass c;
    c.link = in.link;
    c.session = std::move(in.session);
    c.port = in.port;
    return c;
}

// Over a pseudo-terminal and the real serial port code.
Compass servePty(Hec495Options o)
{
    Compass c;
    c.pty = std::make_unique<PtySimulator>(std::make_unique<Hec495Simulator>(o));
    QString error;
    if (!c.pty->start(&error))
        qFatal("pty: %s", qPrintable(error));
    c.port = c.pty->devicePath();
    c.session = std::make_unique<Hec495Session>();
    return c;
}

// Waits for the result of one request.
std::optional<Hec495Result> await(Hec495Session &s, quint64 id, int timeoutMs = 5000)
{
    std::optional<Hec495Result> out;
    QObject ctx;
    QObject::connect(&s, &Hec495Session::commandFinished, &ctx, [&](quint64 done, const Hec495Result &r) {
        if (done == id)
            out = r;
    });
    if (!imudesk::test::waitFor([&] { return out.has_value(); }, timeoutMs))
        return std::nullopt;
    return out;
}

#define AWAIT_OK(session, call)                                                                     \
    [&] {                                                                                           \
        const quint64 id_ = (call);                                                                 \
        auto r_ = await(session, id_);                                                              \
        if (!r_ || !r_->ok())                                                                       \
            qWarning("%s -> %s: %s", #call, r_ ? model::outcomeName(r_->status) : "no result",             \
                     r_ ? qPrintable(r_->message) : "");                                             \
        return r_ && r_->ok() ? r_ : std::nullopt;                                                  \
    }()

} // namespace

class TstHec495Session : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void questionAnswerThenStreaming50Hz()
    {
        auto c = serve({});
        Hec495Session &s = *c.session;
        QSignalSpy identity(&s, &Hec495Session::identityChanged);
        s.open(c.port, 9600);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        QCOMPARE(identity.count(), 1);
        const auto id = identity.at(0).at(0).value<model::DeviceIdentity>();
        QCOMPARE(id.productName, std::string("HEC495"));
        QCOMPARE(id.busAddress, 0);
        QVERIFY(id.usable());
        QVERIFY(!s.streaming());
        // Polled "read all" records become samples.
        QTRY_VERIFY_WITH_TIMEOUT(s.store().totalAppended() >= 5, 3000);
        const auto latest = s.store().latest();
        QVERIFY(latest && latest->has(model::FieldAcc) && latest->source == "HEC495");

        QSignalSpy streaming(&s, &Hec495Session::streamingChanged);
        QVERIFY(AWAIT_OK(s, s.setOutputRate(50)));
        QVERIFY(s.streaming());
        // Auto-output begins once the 3 s after power-on are over (2.14).
        const uint64_t polled = s.store().totalAppended();
        QTRY_VERIFY_WITH_TIMEOUT(s.store().totalAppended() > polled + 5, 5000);
        // The module's own count over 2 s is the rate; every one of those frames becomes a sample.
        auto sent = [&] {
            uint64_t n = 0;
            c.withSim([&](Hec495Simulator &d) { n = d.framesQueued(); });
            return n;
        };
        const uint64_t before = s.store().totalAppended();
        const uint64_t sent0 = sent();
        QTest::qWait(2000); // duration under test: the module's 50 Hz, counted over 2 s
        const uint64_t sentNow = sent() - sent0;
        QVERIFY2(sentNow >= 95 && sentNow <= 105, qPrintable(QString::number(sentNow)));
        QTRY_VERIFY_WITH_TIMEOUT(s.store().totalAppended() - before >= sentNow, 3000);
        // The default content: angles (the heading also as its own quantity, issue 53 point 7).
        QCOMPARE(s.store().latest()->fields, uint32_t(model::FieldEuler | model::FieldHeading));
        // Commands still work while it streams.
        const auto decl = AWAIT_OK(s, s.setDeclination(-3.2));
        QVERIFY(decl);
        const auto back = AWAIT_OK(s, s.readDeclination());
        QVERIFY(back);
        QCOMPARE(back->reply.declination, -3.2);
        QSignalSpy stats(&s, &Hec495Session::statsUpdated);
        QTRY_VERIFY_WITH_TIMEOUT(stats.count() >= 2, 3000);
        const auto st = stats.last().at(0).value<SessionStats>();
        QVERIFY(st.frames > 50);
        QCOMPARE(st.crcErrors, uint64_t(0));
        QVERIFY(st.rateByType.at("HEC495 angles") > 40.0);
    }

    void quietWindowAfterPowerOn()
    {
        // Saved for 50 Hz auto-output: silent for 3 s after power-on, yet it answers.
        Hec495Options o;
        o.rateHz = 50;
        o.content = wl::OutputContent::AllData;
        o.baud = 115200;
        auto c = serve(o);
        Hec495Session &s = *c.session;
        s.open(c.port, 115200);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 2500);
        QVERIFY(!s.streaming()); // identified by a reply inside the window
        QTRY_VERIFY_WITH_TIMEOUT(s.streaming(), 5000);
        auto sent = [&] {
            uint64_t n = 0;
            c.withSim([&](Hec495Simulator &d) { n = d.framesQueued(); });
            return n;
        };
        const uint64_t before = s.store().totalAppended();
        const uint64_t sent0 = sent();
        QTest::qWait(1000); // duration under test: the module's 50 Hz, counted over 1 s
        const uint64_t sentNow = sent() - sent0;
        QVERIFY2(sentNow >= 47 && sentNow <= 53, qPrintable(QString::number(sentNow)));
        QTRY_VERIFY_WITH_TIMEOUT(s.store().totalAppended() - before >= sentNow, 3000);
        QVERIFY(s.store().latest()->has(model::FieldDeviceTime));
    }

    void nmeaOutputBesidePolling()
    {
        // Output content NMEA 0183 at 10 Hz (0x49 = 03): the module sends $HCHDT text, not
        // frames. Each sentence becomes a heading sample and is counted by type, and polling
        // goes on beside it, so acceleration and the rest keep coming.
        Hec495Options o;
        o.rateHz = 10;
        o.content = wl::OutputContent::Nmea0183;
        o.baud = 115200;
        auto c = serve(o);
        Hec495Session &s = *c.session;
        QSignalSpy sentences(&s, &Hec495Session::nmeaReceived);
        s.open(c.port, 115200);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        // The text starts after the 3 s quiet window.
        QTRY_VERIFY_WITH_TIMEOUT(sentences.count() >= 10, 8000);
        QVERIFY(!s.streaming()); // text is not auto-output of frames: the session still polls
        QVERIFY(sentences.last().at(0).toString().startsWith(QStringLiteral("$HCHDT,")));
        const auto merged = s.store().latestPerField();
        QVERIFY(merged && merged->has(model::FieldHeading) && merged->has(model::FieldAcc));
        QVERIFY(merged->headingDeg >= 0 && merged->headingDeg < 360);
        // The sentences' true heading is in the store beside the records' magnetic one.
        uint64_t next = 0;
        const auto all = s.store().since(0, SIZE_MAX, &next);
        QVERIFY(std::any_of(all.begin(), all.end(), [](const model::Sample &x) {
            return x.has(model::FieldHeading) && x.headingTrue;
        }));
        // Polled records keep arriving while the text streams.
        const uint64_t before = s.store().totalAppended();
        QTRY_VERIFY2_WITH_TIMEOUT(s.store().totalAppended() - before >= 12,
                                  qPrintable(QString::number(s.store().totalAppended() - before)), 1000);
        QSignalSpy stats(&s, &Hec495Session::statsUpdated);
        QTRY_VERIFY_WITH_TIMEOUT(stats.count() >= 1, 3000);
        const auto st = stats.last().at(0).value<SessionStats>();
        QVERIFY(st.nmeaSentences >= 10);
        QCOMPARE(st.nmeaErrors, uint64_t(0));
        QVERIFY(st.framesByType.at("NMEA HDT") >= 10);

        // Switching the content to NMEA from the session keeps polling too.
        QVERIFY(AWAIT_OK(s, s.setOutputContent(wl::OutputContent::AllData)));
        QVERIFY(AWAIT_OK(s, s.setOutputRate(25)));
        QTRY_VERIFY_WITH_TIMEOUT(s.streaming(), 3000);
        QVERIFY(AWAIT_OK(s, s.setOutputContent(wl::OutputContent::Nmea0183)));
        QVERIFY(!s.streaming());
        const int heard = int(sentences.count());
        QTRY_VERIFY_WITH_TIMEOUT(sentences.count() >= heard + 10, 3000);
    }

    void replyEqualToRequest_data()
    {
        QTest::addColumn<bool>("echo");
        QTest::newRow("RS-232") << false;
        QTest::newRow("2-wire RS-485 that echoes") << true;
    }
    void replyEqualToRequest()
    {
        // "Set output content 00" and its success are the same six bytes (77 05 00 49 00 4E):
        // without an echo that frame is the reply; with one, the second of them.
        QFETCH(bool, echo);
        Hec495Options o;
        o.echo = echo;
        auto c = serve(o);
        Hec495Session &s = *c.session;
        s.setPollingRate(0);
        s.open(c.port, 9600);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        for (auto content : {wl::OutputContent::AllData, wl::OutputContent::Default, wl::OutputContent::Nmea0183,
                             wl::OutputContent::Default}) {
            QVERIFY(AWAIT_OK(s, s.setOutputContent(content)));
            wl::OutputContent now{};
            c.withSim([&](Hec495Simulator &d) { now = d.runningSettings().content; });
            QCOMPARE(int(now), int(content));
        }
        QVERIFY(AWAIT_OK(s, s.readAll()));
    }

    void recordedReplayedExported()
    {
        // 50 Hz records, then NMEA output, recorded; the capture exports (tidy CSV, JSON Lines
        // with the sentences), analyses and replays through the HEC495 path of CaptureDecoder.
        Hec495Options o;
        o.rateHz = 50;
        o.content = wl::OutputContent::AllData;
        o.baud = 115200;
        // The compass's clock at 4 times real time: its 3 s quiet window passes sooner; what is
        // checked is the recording's content, not its pace.
        auto c = serve(o, 4.0);
        Hec495Session &s = *c.session;
        QVERIFY(s.capabilities().testFlag(DeviceLink::Capability::Recording));
        s.open(c.port, 115200);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(s.streaming(), 6000);
        QTemporaryDir dir;
        const QString capture = dir.filePath(QStringLiteral("hec495.imucap"));
        QSignalSpy stopped(&s, &Session::recordingStopped);
        QSignalSpy started(&s, &Session::recordingStarted);
        QSignalSpy sentences(&s, &Hec495Session::nmeaReceived);
        record::startRecording(s, capture);
        QTRY_COMPARE(started.count(), 1);
        // 50 records (a second of them), then NMEA sentences, in the recording.
        const uint64_t recorded0 = s.store().totalAppended();
        QTRY_VERIFY_WITH_TIMEOUT(s.store().totalAppended() >= recorded0 + 50, 5000);
        QVERIFY(AWAIT_OK(s, s.setOutputContent(wl::OutputContent::Nmea0183)));
        QTRY_VERIFY_WITH_TIMEOUT(sentences.count() >= 20, 5000);
        s.stopRecording();
        QTRY_COMPARE(stopped.count(), 1);

        record::CaptureExporter::Options eo;
        eo.format = record::CaptureExporter::Format::TidyCsv;
        eo.output = dir.filePath(QStringLiteral("hec495.csv"));
        const auto csv = record::CaptureExporter::run(capture, eo);
        QVERIFY2(csv.ok, qPrintable(csv.error));
        QVERIFY2(csv.frames >= 40, qPrintable(QString::number(csv.frames)));
        eo.format = record::CaptureExporter::Format::JsonLines;
        eo.output = dir.filePath(QStringLiteral("hec495.jsonl"));
        const auto jsonl = record::CaptureExporter::run(capture, eo);
        QVERIFY2(jsonl.ok, qPrintable(jsonl.error));
        QFile f(eo.output);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY(text.contains("\"type\":\"HEC495\""));
        QVERIFY(text.contains("$HCHDT,"));

        const auto a = record::FileAnalysis::run(capture);
        QVERIFY2(a.ok, qPrintable(a.error));
        QCOMPARE(a.result.frames, csv.frames);

        record::ReplaySession replay;
        QSignalSpy finished(&replay, &record::ReplaySession::finished);
        replay.open(capture);
        QTRY_COMPARE(replay.state(), SessionState::Connected);
        replay.setSpeed(0); // as fast as possible
        replay.play();
        QTRY_VERIFY_WITH_TIMEOUT(finished.count() == 1, 10000);
        QCOMPARE(replay.store().totalAppended(), csv.frames + uint64_t(text.count("$HCHDT,"))); // records + headings
    }

    // Over a pseudo-terminal: the port's rate changes with the module's.
    void baudChangeFollowed()
    {
        auto c = servePty({});
        Hec495Session &s = *c.session;
        s.open(c.port, 9600);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        QSignalSpy baud(&s, &Hec495Session::baudChanged);
        QVERIFY(AWAIT_OK(s, s.setBaud(115200)));
        QTRY_COMPARE(s.baud(), 115200);
        int simBaud = 0;
        c.withSim([&](Hec495Simulator &d) { simBaud = d.baud(); });
        QCOMPARE(simBaud, 115200);
        const auto angles = AWAIT_OK(s, s.readAngles());
        QVERIFY(angles);
        QCOMPARE(angles->reply.kind, wl::Reply::Kind::Angles);
        // Invalid arguments never reach the wire.
        const auto bad = await(s, s.setBaud(38400));
        QVERIFY(bad);
        QCOMPARE(bad->status, Hec495Result::Status::NotSent);
        QVERIFY(!bad->message.isEmpty());
    }

    void autoBaudAndAddress()
    {
        Hec495Options o;
        o.baud = 19200;
        o.address = 5;
        auto c = servePty(o); // over a pseudo-terminal: auto-baud walks the port's real rates
        Hec495Session &s = *c.session;
        s.open(c.port, 0, 5);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 8000);
        QCOMPARE(s.baud(), 19200);
        QVERIFY(AWAIT_OK(s, s.setAddress(7)));
        QTRY_COMPARE(s.address(), 7);
        const auto q = AWAIT_OK(s, s.queryAddress());
        QVERIFY(q);
        QCOMPARE(q->reply.deviceAddress, uint8_t(7));
        QVERIFY(AWAIT_OK(s, s.readAll()));
        QVERIFY(AWAIT_OK(s, s.saveSettings()));
        QVERIFY(AWAIT_OK(s, s.factoryReset()));
        QTRY_COMPARE(s.baud(), 9600);
        QCOMPARE(s.address(), 0);
        QVERIFY(AWAIT_OK(s, s.readAngles()));
    }

    void wrongAddressTimesOut()
    {
        auto c = serve({});
        Hec495Session &s = *c.session;
        QSignalSpy err(&s, &Hec495Session::errorOccurred);
        s.open(c.port, 9600, 3);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Failed, 8000);
        QCOMPARE(err.count(), 1);
        QVERIFY(err.at(0).at(0).toString().contains(QLatin1String("address")));
    }

    void rs485Retries()
    {
        Hec495Options o;
        o.rs485 = true;
        o.baud = 9600;
        o.rateHz = 50;               // angles: 14 bytes x 50 Hz = 73 % of the line
        auto c = serve(o);
        Hec495Session &s = *c.session;
        s.open(c.port, 9600);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(s.streaming(), 5000);
        int retried = 0;
        for (int i = 0; i < 6; ++i) {
            const auto r = AWAIT_OK(s, s.readDeclination());
            QVERIFY(r);
            retried += r->attempts > 1;
        }
        uint64_t lost = 0;
        c.withSim([&](Hec495Simulator &d) { lost = d.commandsLost(); });
        QCOMPARE(lost > 0, retried > 0);
    }

    // "Collect a point" whose reply comes late (a busy machine) is not sent again: the module
    // counts every one it hears, and a second would be a second point.
    void manualPointSentOnceWhenItsReplyIsLate()
    {
        Hec495Options o;
        o.baud = 115200;
        auto c = servePty(o);
        Hec495Session &s = *c.session;
        s.open(c.port, 115200);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        QVERIFY(AWAIT_OK(s, s.startCalibration(wl::CalibrationMethod::Manual)));
        // The compass's thread stalls for 700 ms (more than two reply timeouts) from before
        // the request is written until after.
        std::atomic<bool> stalled{false};
        std::thread stall([&] {
            c.withSim([&](Hec495Simulator &) {
                stalled = true;
                std::this_thread::sleep_for(std::chrono::milliseconds(700));
            });
        });
        while (!stalled)
            std::this_thread::yield();
        const quint64 id = s.collectCalibrationPoint();
        stall.join();
        const auto r = await(s, id);
        QVERIFY(r);
        QVERIFY2(r->ok(), qPrintable(r->message));
        QCOMPARE(r->attempts, 1);
        QCOMPARE(r->reply.points, 1);
        int held = 0;
        c.withSim([&](Hec495Simulator &d) { held = d.calibration().points(); });
        QCOMPARE(held, 1);
        const auto next = AWAIT_OK(s, s.collectCalibrationPoint());
        QVERIFY(next);
        QCOMPARE(next->reply.points, 2);
        QVERIFY(AWAIT_OK(s, s.stopCalibration()));
    }

    void planarCalibrationRun()
    {
        Hec495Options o;
        o.motion = Motion::Spin;
        o.baud = 115200;
        auto c = serve(o, 4.0); // the points come with the turns, on the compass's clock
        Hec495Session &s = *c.session;
        s.open(c.port, 115200);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        int points = 0;
        connect(&s, &Hec495Session::calibrationPoint, this, [&](int n) { points = n; });
        QVERIFY(AWAIT_OK(s, s.startCalibration(wl::CalibrationMethod::Planar)));
        QTRY_COMPARE_WITH_TIMEOUT(points, 12, 16000);
        const auto saved = AWAIT_OK(s, s.saveCalibration());
        QVERIFY(saved);
        QCOMPARE(saved->reply.kind, wl::Reply::Kind::CalibrationSaved);
        QCOMPARE(saved->reply.points, 12);
        QVERIFY(saved->reply.fitError < 10.0f);
        bool calibrated = false;
        c.withSim([&](Hec495Simulator &d) { calibrated = d.calibrated(); });
        QVERIFY(calibrated);
        // A second save without a run: the module reports failure.
        const auto again = await(s, s.saveCalibration());
        QVERIFY(again);
        QCOMPARE(again->status, Hec495Result::Status::Refused);
    }

    // The demo compass (imudesk --link hec495): polled full records, then 50 Hz angles without
    // a device time once its 3 s after power-on are over. Past 10 s the charts' device axis
    // still moves with the angles, the heading keeps one convention (±180, as the full
    // records), and acceleration, rate and device time are stale with their age while the
    // angles stay live.
    void demoCompassChartsPastTenSeconds()
    {
        Hec495Options o; // as LinkRequest::simulatedHec495
        o.rateHz = 50;
        o.motion = Motion::Spin; // the heading passes 180
        auto c = serve(o);
        Hec495Session &s = *c.session;
        s.open(c.port, o.baud);
        QTRY_COMPARE_WITH_TIMEOUT(s.state(), SessionState::Connected, 5000);
        // The views' clock: the charts' history and the values with their ages, as the workspace.
        plot::ChannelHistory history;
        models::LatestValuesModel values;
        uint64_t next = 0;
        QTimer viewClock;
        viewClock.setInterval(30);
        QObject::connect(&viewClock, &QTimer::timeout, [&] {
            history.append(s.store().since(next, SIZE_MAX, &next));
            values.refresh(s.store().latestPerField(), s.store().fieldAges());
        });
        viewClock.start();
        QTRY_VERIFY_WITH_TIMEOUT(s.streaming(), 8000);
        // Ten seconds of device axis: before, it stopped with the last full record (about 3 s).
        QTRY_VERIFY_WITH_TIMEOUT(!history.empty() && history.newestTime(plot::TimeAxis::Device)
                                                          - history.oldestTime(plot::TimeAxis::Device) >= 10.0,
                                 16000);
        viewClock.stop();
        // The axis moved with the angles: the last 5 s of device time hold about 250 angle rows.
        const double t1 = history.newestTime(plot::TimeAxis::Device);
        const plot::IndexRange last5 = history.range(plot::TimeAxis::Device, t1 - 5.0, t1);
        QVERIFY2(last5.size() >= 200, qPrintable(QString::number(last5.size())));
        bool passed180 = false;
        for (size_t r = 0; r < history.size(); ++r) {
            if (!history.has(plot::Channel::Yaw, r))
                continue;
            const double yaw = history.value(plot::Channel::Yaw, r);
            QVERIFY2(yaw >= -180.0 && yaw <= 180.0, qPrintable(QString::number(yaw)));
            passed180 = passed180 || yaw < -90.0;
        }
        QVERIFY(passed180);
        // Acceleration, rate and the device time stopped with the full records: stale, with their
        // age; the angles are live.
        using Model = models::LatestValuesModel;
        for (Model::Row row : {Model::AccX, Model::GyrZ, Model::DeviceTime}) {
            QVERIFY2(values.isStale(row), qPrintable(values.valueText(row)));
            QVERIFY(values.index(row, Model::ValueColumn).data(Model::StaleRole).toBool());
            QVERIFY2(values.valueText(row).contains(QLatin1String(" s old)")), qPrintable(values.valueText(row)));
        }
        for (Model::Row row : {Model::Roll, Model::Pitch, Model::Yaw})
            QVERIFY2(!values.isStale(row), qPrintable(values.valueText(row)));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstHec495Session)
#include "tst_hec495_session.moc"
