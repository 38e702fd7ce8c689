// The device-side magnetometer calibration (manual v1.7.1 4.6.7.9 and 9.30.49-50: CONFIG
// MCAL START, LOG MCAL STAT with STAT 0/1/2/3/4 and PROGRESS; v1.6.6 8.1.1: LOG MAGCONFIG
// "MB=..." after the background calibration), against replies written out and against
// the simulated module in process (simulated time runs as fast as the test wants).
#include "calib/mag_cal_procedure.h"
#include "protocol/stream/stream_demux.h"
#include "sim/hipnuc_simulator.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk;
using calib::MagCalProcedure;
using protocol::hipnuc::AsciiReply;

namespace {

AsciiReply reply(AsciiReply::Status status, std::map<std::string, std::string> values = {})
{
    AsciiReply r;
    r.status = status;
    r.values = std::move(values);
    for (const auto &[k, v] : r.values)
        r.lines.push_back(k + "=" + v);
    return r;
}

// Sends one command to the simulated module and runs simulated time until the reply is
// complete or 1 s passed (then a Timeout, as the session reports it).
AsciiReply ask(sim::HipnucSimulator &dev, protocol::StreamDemux &demux, int64_t &nowUs, const QString &cmd)
{
    protocol::hipnuc::ReplyCollector collector(cmd.toStdString());
    dev.receive((cmd + QStringLiteral("\r\n")).toStdString());
    const int64_t deadline = nowUs + 1000000;
    while (nowUs < deadline) {
        nowUs += 5000;
        dev.advanceTo(nowUs);
        const auto bytes = dev.takeOutput();
        std::vector<protocol::StreamEvent> events;
        demux.feed(bytes.data(), bytes.size(), events);
        demux.flushPending(events); // the session does this when the line goes quiet
        for (const auto &e : events)
            if (e.kind == protocol::StreamEvent::Kind::Line && collector.addLine(e.text))
                return collector.take();
    }
    AsciiReply t;
    t.status = AsciiReply::Status::Timeout;
    t.command = cmd.toStdString();
    return t;
}

struct Outcome {
    MagCalProcedure::State state;
    std::vector<int> stats;
    std::vector<int> progress;
    QString message;
    Eigen::Vector3d bias;
};

Outcome runOnSimulator(const char *model, const char *firmware, sim::Motion motion, MagCalProcedure::Flow flow)
{
    sim::SimOptions o;
    o.model = model;
    o.firmware = firmware;
    o.motion = motion;
    o.seed = 5;
    sim::HipnucSimulator dev(o);
    protocol::StreamDemux demux;
    demux.endQuarantine(); // a clean in-process line from the start
    int64_t now = 0;
    // Quiet the data output so the replies stand out (as a wizard would not, but faster here).
    ask(dev, demux, now, QStringLiteral("LOG DISABLE"));
    MagCalProcedure proc(MagCalProcedure::Options{500, 400000, 3});
    MagCalProcedure::Step step = proc.start(flow);
    const int64_t startUs = now;
    Outcome out;
    while (step.hasCommand()) {
        now += int64_t(step.delayMs) * 1000;
        dev.advanceTo(now);
        const AsciiReply r = ask(dev, demux, now, QString::fromStdString(step.command.text));
        step = proc.handleReply(r, (now - startUs) / 1000);
        if (proc.stat() >= 0 && (out.stats.empty() || out.stats.back() != proc.stat()))
            out.stats.push_back(proc.stat());
        out.progress.push_back(proc.progress());
    }
    out.state = proc.state();
    out.message = proc.message();
    out.bias = proc.bias();
    return out;
}

} // namespace

class TstMagCalProcedure : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void flowByFirmware()
    {
        QCOMPARE(MagCalProcedure::flowFor({1, 7, 1}), MagCalProcedure::Flow::Mcal);
        QCOMPARE(MagCalProcedure::flowFor({1, 7, 0}), MagCalProcedure::Flow::Mcal);
        QCOMPARE(MagCalProcedure::flowFor({1, 6, 6}), MagCalProcedure::Flow::Background);
    }

    void replies_data()
    {
        QTest::addColumn<QString>("stat");
        QTest::addColumn<QString>("state");
        QTest::addColumn<bool>("polls");
        QTest::newRow("STAT=1 calibrating") << "1" << "calibrating" << true;
        QTest::newRow("STAT=2 verifying") << "2" << "verifying" << true;
        QTest::newRow("STAT=3 done") << "3" << "succeeded" << false;
        QTest::newRow("STAT=4 failed") << "4" << "failed" << false;
        QTest::newRow("STAT=0 idle: stopped") << "0" << "failed" << false;
        QTest::newRow("STAT=7 unknown") << "7" << "failed" << false;
        QTest::newRow("no STAT line") << "" << "failed" << false;
    }
    void replies()
    {
        QFETCH(QString, stat);
        QFETCH(QString, state);
        QFETCH(bool, polls);
        MagCalProcedure p;
        QCOMPARE(QString::fromStdString(p.start(MagCalProcedure::Flow::Mcal).command.text), QStringLiteral("CONFIG MCAL START"));
        MagCalProcedure::Step s = p.handleReply(reply(AsciiReply::Status::Ok), 10);
        QCOMPARE(QString::fromStdString(s.command.text), QStringLiteral("LOG MCAL STAT"));
        QCOMPARE(s.delayMs, 500);
        std::map<std::string, std::string> v{{"PROGRESS", "42"}};
        if (!stat.isEmpty())
            v["STAT"] = stat.toStdString();
        s = p.handleReply(reply(AsciiReply::Status::Ok, v), 600);
        QCOMPARE(QString::fromLatin1(MagCalProcedure::stateName(p.state())), state);
        QCOMPARE(s.hasCommand(), polls);
        QVERIFY(!p.message().isEmpty());
        if (!stat.isEmpty() && stat != QLatin1String("0") && stat != QLatin1String("7") && stat != QLatin1String("4"))
            QCOMPARE(p.progress(), 42);
    }

    void startRefusedOrSilent()
    {
        MagCalProcedure p;
        p.start(MagCalProcedure::Flow::Mcal);
        p.handleReply(reply(AsciiReply::Status::Refused), 5);
        QCOMPARE(p.state(), MagCalProcedure::State::Failed);
        p.start(MagCalProcedure::Flow::Mcal);
        p.handleReply(reply(AsciiReply::Status::Timeout), 1000);
        QCOMPARE(p.state(), MagCalProcedure::State::Failed);
        QVERIFY(p.message().contains(QStringLiteral("1.7.0")));
    }

    void missedPollsAndTimeout()
    {
        MagCalProcedure p(MagCalProcedure::Options{500, 10000, 2});
        p.start(MagCalProcedure::Flow::Mcal);
        p.handleReply(reply(AsciiReply::Status::Ok), 0);
        QVERIFY(p.handleReply(reply(AsciiReply::Status::Timeout), 1000).hasCommand());
        QVERIFY(p.handleReply(reply(AsciiReply::Status::Timeout), 2000).hasCommand());
        QVERIFY(!p.handleReply(reply(AsciiReply::Status::Timeout), 3000).hasCommand());
        QCOMPARE(p.state(), MagCalProcedure::State::Failed);
        // Overall time limit.
        p.start(MagCalProcedure::Flow::Mcal);
        p.handleReply(reply(AsciiReply::Status::Ok), 0);
        p.handleReply(reply(AsciiReply::Status::Ok, {{"STAT", "1"}, {"PROGRESS", "5"}}), 20000);
        QCOMPARE(p.state(), MagCalProcedure::State::Failed);
        QVERIFY(!MagCalProcedure::troubleshooting().isEmpty());
    }

    void backgroundReadout_data()
    {
        QTest::addColumn<QString>("mb");
        QTest::addColumn<QString>("state");
        // The v1.6.6 manual's example (8.1.1): MB=14.14, -2.08, -8.75 means calibrated.
        QTest::newRow("manual example") << "14.14, -2.08, -8.75" << "succeeded";
        QTest::newRow("not yet (0,0,0)") << "0.00, 0.00, 0.00" << "calibrating";
        QTest::newRow("unreadable") << "14.14, x, 1" << "failed";
        QTest::newRow("two values") << "1, 2" << "failed";
    }
    void backgroundReadout()
    {
        QFETCH(QString, mb);
        QFETCH(QString, state);
        MagCalProcedure p;
        QCOMPARE(QString::fromStdString(p.start(MagCalProcedure::Flow::Background).command.text), QStringLiteral("LOG MAGCONFIG"));
        p.handleReply(reply(AsciiReply::Status::Ok, {{"MB", mb.toStdString()}}), 100);
        QCOMPARE(QString::fromLatin1(MagCalProcedure::stateName(p.state())), state);
        if (state == QLatin1String("succeeded"))
            QVERIFY((p.bias() - Eigen::Vector3d(14.14, -2.08, -8.75)).norm() < 1e-9);
    }

    void simulator171Tumble()
    {
        const Outcome o = runOnSimulator("HI14", "1.7.1", sim::Motion::Tumble, MagCalProcedure::Flow::Mcal);
        QVERIFY2(o.state == MagCalProcedure::State::Succeeded, qPrintable(o.message));
        // The manual's sequence: calibrating, verifying, done.
        QCOMPARE(o.stats, (std::vector<int>{1, 2, 3}));
        QVERIFY(std::is_sorted(o.progress.begin(), o.progress.end()));
        QCOMPARE(o.progress.back(), 100);
    }

    void simulator171StaticFails()
    {
        const Outcome o = runOnSimulator("HI14", "1.7.1", sim::Motion::Static, MagCalProcedure::Flow::Mcal);
        QCOMPARE(o.state, MagCalProcedure::State::Failed);
        QCOMPARE(o.stats.back(), 4);
    }

    void simulatorWithoutMagnetometerRefuses()
    {
        const Outcome o = runOnSimulator("HI02", "1.7.1", sim::Motion::Tumble, MagCalProcedure::Flow::Mcal);
        QCOMPARE(o.state, MagCalProcedure::State::Failed);
        QVERIFY(o.stats.empty());
    }

    void simulator166Background()
    {
        const Outcome o = runOnSimulator("HI14", "1.6.6", sim::Motion::Tumble, MagCalProcedure::Flow::Background);
        QCOMPARE(o.state, MagCalProcedure::State::Succeeded);
        QVERIFY(!o.bias.isZero());
        // 1.6.6 does not know CONFIG MCAL: silence, reported as such.
        const Outcome silent = runOnSimulator("HI14", "1.6.6", sim::Motion::Tumble, MagCalProcedure::Flow::Mcal);
        QCOMPARE(silent.state, MagCalProcedure::State::Failed);
        QVERIFY(silent.message.contains(QStringLiteral("1.7.0")));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstMagCalProcedure)
#include "tst_mag_cal_procedure.moc"
